// orbit_clock.cpp — the moving lights' clocks and their pacing.
#include "app/orbit_clock.h"

#include "core/gltf/model_loader.h"

#include <algorithm>
#include <utility>

namespace lab {

glm::vec3 OrbitClock::centreOf(Centre& cache, const std::shared_ptr<const Mesh>& mesh, const Model& model) {
    if (mesh && (cache.mesh != mesh.get() || !(cache.model == model))) {
        cache.mesh = mesh.get();
        cache.model = model;
        std::optional<Sphere> bounds = drawnBounds(*mesh, model);
        cache.centre = bounds ? bounds->center : model.translate;
    }
    return mesh ? cache.centre : model.translate;
}

bool OrbitClock::advance(const Scene& a, const Scene& b, unsigned scenesOpened, float deltaTime, bool paused) {
    auto moves = [](const Preset* p, std::size_t i) {
        return p && i < p->lights.size() && p->lights[i].orbit.on && p->lights[i].orbit.degreesPerSecond != 0.0f;
    };
    bool newScene = std::exchange(scene_, scenesOpened) != scenesOpened;
    userPaused_ = newScene ? startPaused_ : userPaused_;
    paused = paused || userPaused_;
    std::vector<double>& seconds = motions_[0].seconds;
    seconds.resize(std::max(a.preset->lights.size(), b.preset ? b.preset->lights.size() : 0), 0.0);
    bool moving = false;
    for (std::size_t i = 0; i < seconds.size(); ++i) {
        if (newScene || !(moves(a.preset, i) || moves(b.preset, i))) {
            seconds[i] = 0.0;
        } else {
            moving = true;
            seconds[i] += paused ? 0.0 : std::min(deltaTime, kMaxStep);
        }
    }
    motions_[0].centre = centreOf(centres_[0], a.mesh, a.preset->model);
    motions_[1].seconds = seconds;
    if (b.preset) {
        motions_[1].centre = centreOf(centres_[1], b.mesh, b.preset->model);
    }
    return moving && !paused;
}

float OrbitClock::redrawIn(float redrawIn, bool moving, float deltaTime) {
    if (moving) {
        if (lastFrameMoved_) {
            sleep_ = std::clamp(sleep_ + 0.5f * (kFrameSeconds - deltaTime), 0.001f, kFrameSeconds);
        }
        redrawIn = redrawIn < 0.0f ? sleep_ : std::min(redrawIn, sleep_);
    }
    lastFrameMoved_ = moving;
    return redrawIn;
}

} // namespace lab
