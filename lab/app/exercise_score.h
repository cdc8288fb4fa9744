// exercise_score.h — what the lab shows of exercises: the live "how close" of the attempt, and the
// panel's view of the exercise and of a draft. The scene's link as a QR code is share_code.h.
//
// The score: the attempt and the target rendered as `lab exercise check` renders them (256 x 256,
// the target's camera, the lit view) and compared (core/exercise/score.h scoreExercise). The
// target's render, and the start's difference from it (d(start)), are made once for the
// exercise; the attempt is rendered again when it changed, at most
// every kDragInterval seconds while a gesture goes on (a slider drag) and at once when it ends, so
// the score is exact within one frame of the release. Needs the GL context.
#pragma once

#include "app/workspace.h"
#include "core/exercise/exercise.h"
#include "core/exercise/score.h"
#include "core/scene/mesh.h"
#include "render/renderer.h"
#include "ui/panel/panel.h"

#include <memory>
#include <optional>

namespace lab {

class ExerciseScorer {
public:
    static constexpr double kDragInterval = 0.25;

    // Scores the workspace's attempt when it changed; true when the score changed (the frame
    // that showed the old one is owed a new one). The first solved score leaves a note ("Solved!").
    // Binds `framebuffer` again after drawing.
    bool update(Renderer& renderer, Workspace& workspace, bool gestureInProgress, double clock, unsigned framebuffer);
    const std::optional<ExerciseScore>& score() const { return score_; }

private:
    unsigned opened_ = 0;
    std::optional<Image> target_;
    std::optional<double> startDifference_; // d(start) (core/exercise/score.h)
    std::optional<Preset> scored_;
    std::optional<ExerciseScore> score_;
    double scoredAt_ = -1e9;
};

// The score's line of plain text (ExerciseScore::line: "Score 42%: not solved yet", "Solved: score
// 100%"), what the panel's bar says and a screen reader announces; "" before the first score.
std::string exerciseScoreLine(const std::optional<ExerciseScore>& score);
// The panel's view of an exercise being solved, with its last score.
ui::ExercisePanelModel exercisePanelModel(const ExerciseSession& session, const std::optional<ExerciseScore>& score);
// The panel's view of the workspace's draft (draft() must hold one), with why it is not an exercise yet.
ui::DraftPanelModel draftPanelModel(Workspace& workspace);

} // namespace lab
