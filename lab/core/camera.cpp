// camera.cpp — orbit, zoom and pan.
#include "core/camera.h"

#include "core/limits.h"

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
    float viewHeight = 2.0f * distance * std::tan(glm::radians(camera.fovyDeg) / 2.0f);
    glm::vec3 move = (-dx * right - dy * up) * viewHeight;
    camera.eye += move;
    camera.target += move;
    keepCameraValid(camera);
}

} // namespace lab
