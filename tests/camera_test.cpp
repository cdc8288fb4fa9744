// camera_test.cpp — orbit keeps the distance and never flips, zoom and pan move as documented.
#include "core/camera.h"
#include "core/preset.h"
#include "core/limits.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace lab {
namespace {

TEST(Camera, OrbitTurnsAroundTheTargetAtTheSameDistance) {
    Camera c;
    orbitCamera(c, 90.0f, 0.0f); // a quarter turn about +y: from +z to +x
    EXPECT_NEAR(glm::distance(c.eye, glm::vec3(4, 0, 0)), 0.0f, 1e-5f);
    orbitCamera(c, 0.0f, 30.0f); // raise by 30 degrees
    EXPECT_NEAR(glm::length(c.eye - c.target), 4.0f, 1e-5f);
    EXPECT_NEAR(c.eye.y, 4.0f * std::sin(glm::radians(30.0f)), 1e-4f);
}

TEST(Camera, OrbitStopsShortOfThePoles) {
    Camera c;
    orbitCamera(c, 0.0f, 500.0f);
    glm::vec3 dir = glm::normalize(c.eye - c.target);
    EXPECT_NEAR(glm::degrees(std::acos(dir.y)), 1.0f, 1e-3f);
    orbitCamera(c, 0.0f, -1000.0f);
    dir = glm::normalize(c.eye - c.target);
    EXPECT_NEAR(glm::degrees(std::acos(dir.y)), 179.0f, 1e-3f);
}

TEST(Camera, ZoomScalesTheDistanceWithinLimits) {
    Camera c;
    zoomCamera(c, 0.5f);
    EXPECT_NEAR(glm::length(c.eye - c.target), 2.0f, 1e-6f);
    zoomCamera(c, 1e-6f);
    EXPECT_NEAR(glm::length(c.eye - c.target), 2.0f * c.near, 1e-6f);
    zoomCamera(c, 1e9f);
    EXPECT_NEAR(glm::length(c.eye - c.target), c.far / 2.0f, 1e-3f);
}

TEST(Camera, PanDragsTheSceneWithTheMouse) {
    Camera c; // looking down -z from (0, 0, 4): right is +x, up is +y
    panCamera(c, 0.5f, 0.0f); // drag the scene right by half a view height
    float viewHeight = 2.0f * 4.0f * std::tan(glm::radians(22.5f));
    EXPECT_NEAR(c.eye.x, -0.5f * viewHeight, 1e-5f);
    EXPECT_NEAR(c.target.x, -0.5f * viewHeight, 1e-5f);
    panCamera(c, 0.0f, 0.25f); // and up
    EXPECT_NEAR(c.target.y, -0.25f * viewHeight, 1e-5f);
}

// Issue 14: a gesture never makes the camera one a preset may not hold (the validator's ranges).
TEST(Camera, GesturesKeepTheCameraValidAndItsDirection) {
    Preset p;
    p.camera.near = limits::kNear.min;
    p.camera.eye = {1.0f, 1.0f, 1.0f};
    zoomCamera(p.camera, 1e-9f); // all the way in: near * 2 is below the validator's minimum distance
    glm::vec3 offset = p.camera.eye - p.camera.target;
    EXPECT_GE(glm::length(offset), limits::kMinDirectionLength);
    EXPECT_NEAR(glm::dot(glm::normalize(offset), glm::normalize(glm::vec3(1.0f))), 1.0f, 1e-4f) << "the same direction";
    p.camera.eye = {0.0f, 0.0f, 9999.9999f};
    p.camera.target = {0.0f, 0.0f, 9999.9995f};
    for (int i = 0; i < 50; ++i) {
        panCamera(p.camera, 0.0f, 1e3f);
        zoomCamera(p.camera, 1e3f);
    }
    Diagnostics d;
    std::optional<Preset> back = parsePreset(presetToJson(p), "camera.json", std::nullopt, d);
    EXPECT_TRUE(back) << toString(d);
}

} // namespace
} // namespace lab
