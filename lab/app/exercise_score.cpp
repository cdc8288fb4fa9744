// exercise_score.cpp — the live score, the panel's views of exercises, the QR code of the link.
#include "app/exercise_score.h"

#include "core/io/safe_text.h"
#include "core/share/share_link.h"

namespace lab {

namespace {

std::optional<Image> renderScored(Renderer& renderer, const Preset& preset, const std::shared_ptr<const Mesh>& mesh) {
    if (!mesh) {
        return std::nullopt;
    }
    Framebuffer target(kExerciseRenderSide, kExerciseRenderSide);
    if (!target.complete()) {
        return std::nullopt;
    }
    target.bind();
    drawView(renderer, preset, mesh, Viewport{0, 0, kExerciseRenderSide, kExerciseRenderSide}, ViewportDraw{});
    return target.readRgb();
}

} // namespace

bool ExerciseScorer::update(Renderer& renderer, Workspace& workspace, bool gestureInProgress, double clock,
                            unsigned framebuffer) {
    const std::optional<ExerciseSession>& session = workspace.exercise();
    if (!session) {
        *this = ExerciseScorer{};
        return false;
    }
    if (session->opened != opened_) {
        *this = ExerciseScorer{};
        opened_ = session->opened;
    }
    const Exercise& exercise = session->exercise;
    Preset scored = attemptAsScored(exercise, workspace.a());
    if ((scored_ && *scored_ == scored) || (gestureInProgress && clock - scoredAt_ < kDragInterval)) {
        return false;
    }
    if (!target_) {
        target_ = renderScored(renderer, targetAsScored(exercise), workspace.mesh(Side::B));
        std::optional<Image> start = renderScored(renderer, startAsScored(exercise), workspace.exerciseStartMesh());
        if (target_ && start) {
            startDifference_ = startDifference(exercise, *start, *target_);
        }
    }
    std::optional<Image> tried = renderScored(renderer, scored, workspace.mesh(Side::A));
    bindFramebuffer(framebuffer);
    if (!target_ || !tried) {
        return false;
    }
    bool wasSolved = score_ && score_->solved;
    score_ = scoreExercise(exercise, workspace.a(), *tried, *target_, startDifference_);
    if (score_->solved && !wasSolved) {
        workspace.note("Solved! Your attempt matches the target.");
    }
    scored_ = scored;
    scoredAt_ = clock;
    return true;
}

std::string exerciseScoreLine(const std::optional<ExerciseScore>& score) { return score ? score->line() : std::string{}; }

ui::ExercisePanelModel exercisePanelModel(const ExerciseSession& session, const std::optional<ExerciseScore>& score) {
    const Exercise& e = session.exercise;
    ui::ExercisePanelModel view{printable(e.title, true), printable(e.instructions, true), {},
                          static_cast<int>(e.hints.size()) - session.hintsShown, e.open,
                          exerciseScoreLine(score), score ? score->details() : std::string{},
                          score ? score->progress : 0.0, score && score->solved};
    for (int i = 0; i < session.hintsShown; ++i) {
        view.hints.push_back(printable(e.hints[static_cast<std::size_t>(i)], true));
    }
    return view;
}

ui::DraftPanelModel draftPanelModel(Workspace& workspace) {
    ExerciseDraft& draft = *workspace.draft();
    Diagnostics d;
    workspace.draftExercise(d);
    std::string problem;
    if (draft.open.empty()) {
        problem = "Tick the fields students may change: the boxes before the fields below.";
    } else if (!d.empty()) {
        problem = printable(d.front().where.empty() ? d.front().message : d.front().where + ": " + d.front().message, true);
    }
    return {&draft.open, &draft.title, &draft.instructions, &draft.hints, problem};
}

} // namespace lab
