// exercise_score.h — the live "how close" of an exercise: the attempt and the target rendered as
// `lab exercise check` renders them (256 x 256, the target's camera, the lit view) and compared
// (core/exercise/exercise.h scoreExercise).
//
// The target's render is kept for the exercise; the attempt is rendered again when it changed,
// at most every kDragInterval seconds while a gesture goes on (a slider drag) and at once when it
// ends, so the score is exact within one frame of the release. Needs the GL context.
#pragma once

#include "core/exercise/exercise.h"
#include "core/scene/mesh.h"
#include "render/renderer.h"

#include <memory>
#include <optional>

namespace lab {

class ExerciseScorer {
public:
    static constexpr double kDragInterval = 0.25;

    // Scores `attempt` when it changed; true when the score changed. `opened` names the exercise
    // (a new one renders its target again). Restores `framebuffer` as the bound one.
    bool update(Renderer& renderer, const Exercise& exercise, unsigned opened, const Preset& attempt,
                const std::shared_ptr<const Mesh>& attemptMesh, const std::shared_ptr<const Mesh>& targetMesh,
                bool gestureInProgress, double clock, unsigned framebuffer);
    const std::optional<ExerciseScore>& score() const { return score_; }
    void reset() { *this = ExerciseScorer{}; }

private:
    unsigned opened_ = 0;
    std::optional<Image> target_;
    std::optional<Preset> scored_;
    std::optional<ExerciseScore> score_;
    double scoredAt_ = -1e9;
};

} // namespace lab
