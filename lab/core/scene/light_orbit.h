// light_orbit.h — where a moving light stands after some seconds of its orbit.
//
// A light whose `orbit` is on circles the axis through a centre (the GUI passes the centre of the
// model's drawn bounds) at orbit.degreesPerSecond, starting from the preset's own position: the
// position is rotated about the axis through the centre, and a directional or spot light's
// direction is rotated with it (a spot aimed at the model keeps aiming at it). The preset is never
// changed: the live view shows orbitedScene(); screenshots, `lab render` and `lab check` show
// the preset as it is.
//
// This file owns the motion as a pure function of time. It does not keep the clock (the app
// does, and pauses it while the user drags) and does not touch GL or ImGui.
#pragma once

#include "core/scene/preset.h"

#include <glm/vec3.hpp>

#include <vector>

namespace lab {

// The angle in degrees, in [0, 360), turned after `seconds` (computed in double, so that hours
// of a lecture do not lose the angle's precision).
double orbitAngleDeg(const LightOrbit& orbit, double seconds);

// `v` rotated by orbitAngleDeg(orbit, seconds) about orbit.axis (right-handed: positive speeds
// turn counter-clockwise seen from the axis's tip). The angle 0 returns `v` exactly.
glm::vec3 orbitRotate(const LightOrbit& orbit, double seconds, const glm::vec3& v);
// The inverse rotation: a displacement of the moving light back in the preset's frame (a marker
// dragged while the orbit is paused moves the preset's position so that the shown one follows).
glm::vec3 orbitUnrotate(const LightOrbit& orbit, double seconds, const glm::vec3& v);

// The light `seconds` into its orbit about `centre` (unchanged when its orbit is off). The
// position stays inside the preset's coordinate range.
LightDesc orbitedLight(const LightDesc& light, const glm::vec3& centre, double seconds);

// Whether any light of `preset` moves.
bool anyOrbit(const Preset& preset);

// `preset` with every moving light where it stands after `seconds`.
Preset orbitedScene(const Preset& preset, const glm::vec3& centre, double seconds);

// The live view's clocks: each light's seconds into its orbit (by index; a light past the end is
// at 0), so a light switched on starts from its own position whatever the others are doing.
struct LightMotion {
    glm::vec3 centre{0.0f}; // what the lights circle: the centre of the model's drawn bounds
    std::vector<double> seconds;
    double secondsOf(std::size_t light) const { return light < seconds.size() ? seconds[light] : 0.0; }
};
Preset orbitedScene(const Preset& preset, const LightMotion& motion);

} // namespace lab
