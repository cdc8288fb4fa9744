// camera_test.cpp — orbit keeps the distance and never flips, zoom and pan move as documented,
// framing puts the whole bounding sphere in view at any size.
#include "core/scene/camera.h"
#include "core/scene/limits.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

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
    panCamera(c, 0.5f, 0.0f); // drag the scene right by half the view's narrower side
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

//----------------------------------------------------------------------------------------
// Framing
//----------------------------------------------------------------------------------------

// How far the sphere reaches into the view: the largest |x| and |y| in normalized device
// coordinates over points on its silhouette as seen from `c` (the sphere is in view when both are
// below 1), and whether every point lies between near and far.
struct Reach {
    float x = 0.0f, y = 0.0f;
    bool betweenNearAndFar = true;
};

Reach reach(const Camera& c, const Sphere& s, float aspect) {
    glm::mat4 view = glm::lookAt(c.eye, c.target, c.up);
    // fovy_deg spans the narrower side: the width when the view is taller than wide.
    float tanHalfY = std::tan(glm::radians(c.fovyDeg) / 2.0f) / std::min(aspect, 1.0f);
    glm::mat4 projection = glm::perspective(2.0f * std::atan(tanHalfY), aspect, c.near, c.far);
    Reach r;
    for (int i = 0; i < 64; ++i) {        // directions over the whole sphere
        for (int j = 0; j <= 32; ++j) {
            float phi = glm::two_pi<float>() * static_cast<float>(i) / 64.0f;
            float theta = glm::pi<float>() * static_cast<float>(j) / 32.0f;
            glm::vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            glm::vec4 eye = view * glm::vec4(s.center + s.radius * dir, 1.0f);
            r.betweenNearAndFar = r.betweenNearAndFar && -eye.z > c.near && -eye.z < c.far;
            glm::vec4 clip = projection * eye;
            r.x = std::max(r.x, std::abs(clip.x / clip.w));
            r.y = std::max(r.y, std::abs(clip.y / clip.w));
        }
    }
    return r;
}

// A camera a preset may hold (the validator's ranges, core/scene/limits.h).
void expectValid(const Camera& c) {
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(limits::contains(limits::kCoordinate, c.eye[i])) << c.eye[i];
        EXPECT_TRUE(limits::contains(limits::kCoordinate, c.target[i])) << c.target[i];
    }
    EXPECT_TRUE(limits::contains(limits::kFovyDeg, c.fovyDeg)) << c.fovyDeg;
    EXPECT_TRUE(limits::contains(limits::kNear, c.near)) << c.near;
    EXPECT_TRUE(limits::contains(limits::kFar, c.far)) << c.far;
    EXPECT_GT(c.far, c.near);
    EXPECT_GE(glm::distance(c.eye, c.target), limits::kMinDirectionLength);
}

TEST(Camera, FramingPutsTheSphereInViewWithAMarginAtAnySize) {
    for (float radius : {0.005f, 1.0f, 1000.0f}) {
        for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f}) {
            Sphere s{glm::vec3(3.0f, -2.0f, 1.0f) * radius, radius};
            Camera c = framedCamera(Camera{}, s, aspect);
            SCOPED_TRACE("radius " + std::to_string(radius) + ", aspect " + std::to_string(aspect));
            expectValid(c);
            EXPECT_LT(glm::distance(c.target, s.center), 1e-5f * radius);
            EXPECT_NEAR(glm::dot(glm::normalize(c.eye - c.target), glm::vec3(0, 0, 1)), 1.0f, 1e-6f)
                << "the default camera's direction";
            EXPECT_EQ(c.up, Camera{}.up);
            EXPECT_EQ(c.fovyDeg, Camera{}.fovyDeg);
            Reach r = reach(c, s, aspect);
            EXPECT_TRUE(r.betweenNearAndFar);
            // The smaller side spans 80% (within the sampling's reach of the silhouette), the other no more.
            float smaller = aspect >= 1.0f ? r.y : r.x, other = aspect >= 1.0f ? r.x : r.y;
            EXPECT_NEAR(smaller, 0.8f, 0.01f);
            EXPECT_LE(other, 0.81f);
            // Near and far leave the gestures room: zoom keeps the distance in [near * 2, far / 2].
            float distance = glm::distance(c.eye, c.target);
            EXPECT_LT(c.near * 2.0f, distance - radius);
            EXPECT_GT(c.far / 2.0f, distance + radius);
        }
    }
}

TEST(Camera, FramingKeepsTheDirectionUpAndFieldOfView) {
    Camera base;
    base.eye = {3.0f, 1.0f, 2.0f};
    base.target = {1.0f, 1.0f, 1.0f};
    base.fovyDeg = 30.0f;
    Sphere s{{10.0f, 0.0f, 0.0f}, 0.5f};
    Camera c = framedCamera(base, s, 1.0f);
    EXPECT_NEAR(glm::dot(glm::normalize(c.eye - c.target), glm::normalize(base.eye - base.target)), 1.0f, 1e-6f);
    EXPECT_EQ(c.fovyDeg, 30.0f);
    EXPECT_NEAR(reach(c, s, 1.0f).y, 0.8f, 0.01f);
    // Framing twice changes nothing more.
    Camera again = framedCamera(c, s, 1.0f);
    EXPECT_LT(glm::distance(again.eye, c.eye), 1e-5f);
}

TEST(Camera, FramingABoxFitsTheSphereThroughItsCorners) {
    Sphere s = sphereAround({-1.0f, -2.0f, -2.0f}, {1.0f, 2.0f, 2.0f});
    EXPECT_EQ(s.center, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(s.radius, 3.0f);
    Camera c = framedCamera(Camera{}, glm::vec3(-1.0f, -2.0f, -2.0f), glm::vec3(1.0f, 2.0f, 2.0f), 2.0f);
    EXPECT_EQ(c, framedCamera(Camera{}, s, 2.0f));
}

TEST(Camera, FramingStaysInsideTheRanges) {
    // Too large for the eye to stand back inside the coordinate range: it stays at the edge and
    // the field of view widens to fit.
    Sphere large{glm::vec3(0.0f), 4000.0f};
    Camera c = framedCamera(Camera{}, large, 1.0f);
    expectValid(c);
    EXPECT_GT(c.fovyDeg, 45.0f);
    EXPECT_FLOAT_EQ(c.eye.z, limits::kCoordinate.max);
    Reach r = reach(c, large, 1.0f);
    EXPECT_NEAR(r.y, 0.8f, 0.01f);
    EXPECT_TRUE(r.betweenNearAndFar);
    // Too small, empty, or not a number: framed as a sphere of 0.001, a valid camera.
    for (float radius : {1e-9f, 0.0f, std::nanf("")}) {
        Camera tiny = framedCamera(Camera{}, Sphere{glm::vec3(1.0f), radius}, 1.0f);
        expectValid(tiny);
        EXPECT_TRUE(reach(tiny, Sphere{glm::vec3(1.0f), 1e-3f}, 1.0f).betweenNearAndFar);
    }
    // Far outside the range, or not finite: the target at its edge or the base's, the camera still valid.
    expectValid(framedCamera(Camera{}, Sphere{glm::vec3(5e4f, 0.0f, -5e4f), 10.0f}, 1.0f));
    Camera lost = framedCamera(Camera{}, Sphere{glm::vec3(std::nanf(""), INFINITY, 0.0f), INFINITY}, 1.0f);
    expectValid(lost);
    EXPECT_EQ(lost.target, Camera{}.target);
}

} // namespace
} // namespace lab
