// camera.cpp — orbit, zoom, pan and framing.
#include "core/scene/camera.h"

#include "core/scene/limits.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

void keepCameraValid(Camera& camera) {
    constexpr float kMinDistance = 2.0f * limits::kMinDirectionLength; // twice the validator's, for rounding
    const glm::vec3 margin(kMinDistance);
    camera.target = glm::clamp(camera.target, glm::vec3(limits::kCoordinate.min) + margin,
                               glm::vec3(limits::kCoordinate.max) - margin);
    glm::vec3 offset = camera.eye - camera.target;
    float distance = glm::length(offset);
    if (!(distance >= kMinDistance)) { // too close (or not a number): the same direction, farther
        offset = distance > 0.0f ? offset / distance : glm::vec3(0.0f, 0.0f, 1.0f);
        camera.eye = camera.target + offset * kMinDistance;
    }
    camera.eye = glm::clamp(camera.eye, glm::vec3(limits::kCoordinate.min), glm::vec3(limits::kCoordinate.max));
}

void orbitCamera(Camera& camera, float yawDeg, float pitchDeg) {
    glm::vec3 up = glm::normalize(camera.up);
    glm::vec3 offset = camera.eye - camera.target;
    float distance = glm::length(offset);
    glm::vec3 dir = offset / distance;
    // Yaw about the up axis.
    dir = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(yawDeg), up) * glm::vec4(dir, 0.0f));
    // Pitch about the right axis, clamped so that the direction stays 1 degree from the up axis.
    float current = glm::degrees(std::acos(std::clamp(glm::dot(dir, up), -1.0f, 1.0f))); // 0 = above the target
    float target = std::clamp(current - pitchDeg, 1.0f, 179.0f);
    glm::vec3 right = glm::cross(dir, up); // turning about it by a positive angle raises dir towards up
    if (glm::length(right) > 1e-6f) {
        right = glm::normalize(right);
        dir = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(current - target), right) * glm::vec4(dir, 0.0f));
    }
    camera.eye = camera.target + glm::normalize(dir) * distance;
    keepCameraValid(camera);
}

void zoomCamera(Camera& camera, float factor) {
    glm::vec3 offset = camera.eye - camera.target;
    float distance = glm::length(offset);
    float next = std::clamp(distance * factor, camera.near * 2.0f, camera.far / 2.0f);
    camera.eye = camera.target + offset * (next / distance);
    keepCameraValid(camera);
}

void panCamera(Camera& camera, float dx, float dy) {
    glm::vec3 forward = camera.target - camera.eye;
    float distance = glm::length(forward);
    forward /= distance;
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 up = glm::cross(right, forward);
    float viewSide = 2.0f * distance * std::tan(glm::radians(camera.fovyDeg) / 2.0f); // the narrower side's extent
    glm::vec3 move = (-dx * right - dy * up) * viewSide;
    camera.eye += move;
    camera.target += move;
    keepCameraValid(camera);
}

//----------------------------------------------------------------------------------------
// Framing
//----------------------------------------------------------------------------------------

namespace {

constexpr float kFramedShare = 0.8f;      // of the view's smaller side that the sphere spans
constexpr float kMinFramedRadius = 1.0e-3f; // smaller spheres are framed as this (near stays in range)
constexpr float kMaxFramedRadius = 1.0e7f;  // (a finite bound for the arithmetic; such a model cannot be framed anyway)

// The distance at which a sphere of `radius` spans kFramedShare of a view whose smaller half
// angle has tangent `tanHalf`: its silhouette's half angle a has tan a = kFramedShare · tanHalf
// and sin a = radius / distance.
float framingDistance(float radius, float tanHalf) {
    return radius / std::sin(std::atan(kFramedShare * tanHalf));
}

} // namespace

Sphere sphereAround(glm::vec3 boundsMin, glm::vec3 boundsMax) {
    return {(boundsMin + boundsMax) * 0.5f, glm::length(boundsMax - boundsMin) * 0.5f};
}

Camera framedCamera(const Camera& base, glm::vec3 boundsMin, glm::vec3 boundsMax, float aspect) {
    return framedCamera(base, sphereAround(boundsMin, boundsMax), aspect);
}

Camera framedCamera(const Camera& base, const Sphere& sphere, float aspect) {
    Camera c = base;
    glm::vec3 dir = base.eye - base.target;
    float length = glm::length(dir);
    dir = length > 0.0f && std::isfinite(length) ? dir / length : glm::vec3(0.0f, 0.0f, 1.0f);
    // (An infinite radius, from bounds that overflow, is the largest; NaN the smallest.)
    float radius = std::isnan(sphere.radius) ? kMinFramedRadius : std::clamp(sphere.radius, kMinFramedRadius, kMaxFramedRadius);
    (void)aspect; // (the narrower side decides, whatever the shape)

    // fovy_deg spans the view's narrower side whatever its shape (core/lighting/lighting.h).
    float tanHalf = std::tan(glm::radians(limits::clamp(limits::kFovyDeg, base.fovyDeg)) * 0.5f);
    float distance = framingDistance(radius, tanHalf);

    // The target inside the coordinate range, as keepCameraValid keeps it; the eye as far back as
    // the range allows along the direction.
    bool finite = std::isfinite(sphere.center.x) && std::isfinite(sphere.center.y) && std::isfinite(sphere.center.z);
    c.target = finite ? sphere.center : base.target;
    keepCameraValid(c); // (only the target matters here; the eye is set below)
    float room = limits::kUnbounded;
    for (int i = 0; i < 3; ++i) {
        if (dir[i] > 0.0f) {
            room = std::min(room, (limits::kCoordinate.max - c.target[i]) / dir[i]);
        } else if (dir[i] < 0.0f) {
            room = std::min(room, (limits::kCoordinate.min - c.target[i]) / dir[i]);
        }
    }
    if (distance > room) { // too far for the range: nearer, with a wider view
        distance = room;
        float sinA = std::min(radius / distance, 0.999f);
        float tanA = sinA / std::sqrt(1.0f - sinA * sinA);
        float fovy = glm::degrees(2.0f * std::atan(tanA / kFramedShare));
        c.fovyDeg = limits::clamp(limits::kFovyDeg, std::max(base.fovyDeg, fovy));
    }
    c.eye = c.target + dir * distance;
    // The default camera's ratios: near 0.1 and far 100 at a distance of 4.
    c.near = limits::clamp(limits::kNear, distance / 40.0f);
    c.far = std::max(limits::clamp(limits::kFar, distance * 25.0f), limits::nextUp(c.near));
    keepCameraValid(c);
    return c;
}

} // namespace lab
