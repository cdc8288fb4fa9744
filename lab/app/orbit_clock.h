// orbit_clock.h — the moving lights' clocks (core/scene/light_orbit.h) and the frames they ask for.
//
// The document keeps the preset's light positions (what Save writes, what screenshots and
// `lab render` show); the live view, its markers and the probe show shown(): the scene with each
// orbiting light where its clock has taken it. A light's clock runs while its orbit is on and
// nothing is being dragged or edited, and starts again from 0 when its orbit is switched off or
// a scene opens. The user can pause them all (paused()), and a scene can open paused (reduced
// motion). A and B (compare mode) share one clock per light index, and each circles the
// centre of its own model's drawn bounds.
//
// While a light moves, frames come at a steady kFrameSeconds whatever a frame costs: the wait is
// corrected by how far the last period (frame start to frame start) missed it; where the swap
// waits for the display, the wait shrinks to what is left of its interval. Pure: frames pass
// their time in, like app/frame_pacer.h.
#pragma once

#include "core/scene/light_orbit.h"
#include "core/scene/mesh.h"
#include "core/scene/preset.h"

#include <array>
#include <memory>

namespace lab {

// Whether a scene's lights move by themselves (their orbit), and whether that motion is paused.
enum class MovingLights { None, Moving, Paused };

class OrbitClock {
public:
    // `startPaused` (AppOptions::reducedMotion): every scene opens with its lights' motion paused.
    explicit OrbitClock(bool startPaused = false) : startPaused_(startPaused), userPaused_(startPaused) {}

    // The user's pause (Command::ToggleLightMotion): the clocks stand still until resumed, the
    // lights shown where they were. A scene opened starts paused again when startPaused, moving
    // otherwise.
    bool paused() const { return userPaused_; }
    void togglePaused() { userPaused_ = !userPaused_; }
    MovingLights moving(const Preset& preset) const {
        return !anyOrbit(preset) ? MovingLights::None : userPaused_ ? MovingLights::Paused : MovingLights::Moving;
    }

    static constexpr float kFrameSeconds = 1.0f / 60.0f;
    // A clock never jumps more than this at once (the first frame after an idle wait would
    // otherwise turn the light by the whole wait).
    static constexpr float kMaxStep = 0.1f;

    // One side's scene this frame: its preset and its model's mesh (null while none loads).
    struct Scene {
        const Preset* preset = nullptr;
        std::shared_ptr<const Mesh> mesh;
    };
    // Runs the clocks of the lights that orbit in `a`, or in `b` (compare mode; null otherwise),
    // by `deltaTime` unless `paused` (a drag) or paused(). `scenesOpened` counts the scenes opened (a new
    // one resets the clocks). True when some light is moving and not paused: another frame is due.
    bool advance(const Scene& a, const Scene& b, unsigned scenesOpened, float deltaTime, bool paused);

    // The motion of side 0 (A) or 1 (B), and its scene as the live view shows it.
    const LightMotion& motion(std::size_t side) const { return motions_[side]; }
    Preset shown(const Preset& preset, std::size_t side) const {
        return anyOrbit(preset) ? orbitedScene(preset, motions_[side]) : preset;
    }

    // When the next frame is due: `redrawIn` as the app has it (< 0: only on input), or sooner
    // while `moving` (advance's answer for this frame, which took `deltaTime` since the last).
    float redrawIn(float redrawIn, bool moving, float deltaTime);

private:
    // The centre of the model's drawn bounds, computed again only when the mesh or the model's
    // transform changes.
    struct Centre {
        const Mesh* mesh = nullptr;
        Model model;
        glm::vec3 centre{0.0f};
    };
    static glm::vec3 centreOf(Centre& cache, const std::shared_ptr<const Mesh>& mesh, const Model& model);

    std::array<LightMotion, 2> motions_;
    std::array<Centre, 2> centres_;
    unsigned scene_ = 0;
    float sleep_ = kFrameSeconds; // the wait between orbit frames, corrected to a steady rate
    bool lastFrameMoved_ = false; // the last frame was asked for by the orbit
    bool startPaused_ = false;
    bool userPaused_ = false;
};

} // namespace lab
