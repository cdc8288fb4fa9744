// light_orbit.cpp — Rodrigues' rotation of a light about the orbit's axis.
#include "core/scene/light_orbit.h"

#include "core/scene/limits.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

namespace {

// Rotation by `deg` about the unit axis `k`, in double: v cos θ + (k × v) sin θ + k (k·v)(1 - cos θ).
glm::vec3 rotate(const glm::vec3& axis, double deg, const glm::vec3& v) {
    if (deg == 0.0) {
        return v; // t = 0 (or a stopped orbit) is the preset's own position, bit for bit
    }
    glm::dvec3 k = glm::normalize(glm::dvec3(axis));
    glm::dvec3 x(v);
    double theta = deg * (3.14159265358979323846 / 180.0);
    double c = std::cos(theta), s = std::sin(theta);
    return glm::vec3(x * c + glm::cross(k, x) * s + k * glm::dot(k, x) * (1.0 - c));
}

} // namespace

double orbitAngleDeg(const LightOrbit& orbit, double seconds) {
    double deg = std::fmod(static_cast<double>(orbit.degreesPerSecond) * seconds, 360.0);
    return deg < 0.0 ? deg + 360.0 : deg;
}

glm::vec3 orbitRotate(const LightOrbit& orbit, double seconds, const glm::vec3& v) {
    return rotate(orbit.axis, orbitAngleDeg(orbit, seconds), v);
}

glm::vec3 orbitUnrotate(const LightOrbit& orbit, double seconds, const glm::vec3& v) {
    double deg = orbitAngleDeg(orbit, seconds);
    return rotate(orbit.axis, deg == 0.0 ? 0.0 : 360.0 - deg, v);
}

LightDesc orbitedLight(const LightDesc& light, const glm::vec3& centre, double seconds) {
    if (!light.orbit.on || glm::length(light.orbit.axis) < limits::kMinDirectionLength) {
        return light; // off, or an axis the validator would refuse: the light stays
    }
    LightDesc moved = light;
    if (orbitAngleDeg(light.orbit, seconds) == 0.0) {
        return moved;
    }
    // About the axis through the centre: the offset from the centre turns, its length stays.
    glm::vec3 offset = orbitRotate(light.orbit, seconds, light.position - centre);
    moved.position = glm::clamp(centre + offset, glm::vec3(limits::kCoordinate.min), glm::vec3(limits::kCoordinate.max));
    moved.direction = orbitRotate(light.orbit, seconds, light.direction);
    return moved;
}

bool anyOrbit(const Preset& preset) {
    return std::any_of(preset.lights.begin(), preset.lights.end(), [](const LightDesc& l) { return l.orbit.on; });
}

Preset orbitedScene(const Preset& preset, const glm::vec3& centre, double seconds) {
    Preset shown = preset;
    for (LightDesc& l : shown.lights) {
        l = orbitedLight(l, centre, seconds);
    }
    return shown;
}

Preset orbitedScene(const Preset& preset, const LightMotion& motion) {
    Preset shown = preset;
    for (std::size_t i = 0; i < shown.lights.size(); ++i) {
        shown.lights[i] = orbitedLight(shown.lights[i], motion.centre, motion.secondsOf(i));
    }
    return shown;
}

} // namespace lab
