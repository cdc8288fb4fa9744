// exercise_score.cpp — the attempt and the target drawn at 256 x 256 and compared.
#include "app/exercise_score.h"

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
    drawView(renderer, preset, mesh, Viewport{0, 0, kExerciseRenderSide, kExerciseRenderSide}, ViewDraw{});
    return target.readRgb();
}

} // namespace

bool ExerciseScorer::update(Renderer& renderer, const Exercise& exercise, unsigned opened, const Preset& attempt,
                            const std::shared_ptr<const Mesh>& attemptMesh, const std::shared_ptr<const Mesh>& targetMesh,
                            bool gestureInProgress, double clock, unsigned framebuffer) {
    if (opened != opened_) {
        reset();
        opened_ = opened;
    }
    Preset scored = attemptAsScored(exercise, attempt);
    if (scored_ && *scored_ == scored) {
        return false;
    }
    if (gestureInProgress && clock - scoredAt_ < kDragInterval) {
        return false;
    }
    if (!target_) {
        target_ = renderScored(renderer, targetAsScored(exercise), targetMesh);
    }
    std::optional<Image> tried = renderScored(renderer, scored, attemptMesh);
    bindFramebuffer(framebuffer);
    if (!target_ || !tried) {
        return false;
    }
    score_ = scoreExercise(exercise, attempt, *tried, *target_);
    scored_ = scored;
    scoredAt_ = clock;
    return true;
}

} // namespace lab
