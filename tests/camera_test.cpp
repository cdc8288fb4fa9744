// camera_test.cpp — orbit keeps the distance and never flips, zoom and pan move as documented,
// framing puts the model's box tightly in view (85% of the narrower side) at any size and aspect.
#include "core/scene/camera.h"
#include "core/scene/limits.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

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

// Where a box's 8 corners land in a view of `aspect` (width / height) seen from `c`, projected
// with glm as the renderer does (fovy_deg spans the narrower side): their extent in units of the
// narrower side (1 is the whole side), the centre of that extent relative to the view's (0 is
// centred, in the same units), whether all are inside the view (|NDC| < 1), and whether every
// corner lies between near and far.
struct Projected {
    glm::vec2 extent{0.0f}, center{0.0f};
    bool inside = true;
    bool betweenNearAndFar = true;
    float larger() const { return std::max(extent.x, extent.y); }
};

Projected project(const Camera& c, glm::vec3 lo, glm::vec3 hi, float aspect) {
    glm::mat4 view = glm::lookAt(c.eye, c.target, c.up);
    float tanHalfY = std::tan(glm::radians(c.fovyDeg) / 2.0f) / std::min(aspect, 1.0f);
    glm::mat4 projection = glm::perspective(2.0f * std::atan(tanHalfY), aspect, c.near, c.far);
    glm::vec2 mn(INFINITY), mx(-INFINITY);
    Projected r;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        glm::vec4 eye = view * glm::vec4(corner, 1.0f);
        r.betweenNearAndFar = r.betweenNearAndFar && -eye.z > c.near && -eye.z < c.far;
        glm::vec4 clip = projection * eye;
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        r.inside = r.inside && std::abs(ndc.x) < 1.0f && std::abs(ndc.y) < 1.0f;
        mn = glm::min(mn, ndc);
        mx = glm::max(mx, ndc);
    }
    // NDC spans 2 across each side; the wider side is `aspect` (or 1 / aspect) narrower sides long.
    glm::vec2 sides = aspect >= 1.0f ? glm::vec2(aspect, 1.0f) : glm::vec2(1.0f, 1.0f / aspect);
    r.extent = (mx - mn) * 0.5f * sides;
    r.center = (mx + mn) * 0.25f * sides;
    return r;
}

// The 8 corners of the box from `lo` to `hi`: the points framed.
std::vector<glm::vec3> corners(glm::vec3 lo, glm::vec3 hi) {
    std::vector<glm::vec3> c;
    for (int i = 0; i < 8; ++i) {
        c.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    }
    return c;
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

glm::vec3 direction(const Camera& c) { return glm::normalize(c.eye - c.target); }

// The view direction model viewers open with: above the horizontal by 20° to 30° and turned from
// the front (+z) towards +x by 30° to 40°.
TEST(Camera, TheThreeQuarterDirectionIsAboveTheFrontTurnedTowardsX) {
    glm::vec3 d = threeQuarterDirection();
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
    float elevation = glm::degrees(std::asin(d.y));
    float azimuth = glm::degrees(std::atan2(d.x, d.z));
    EXPECT_GE(elevation, 20.0f);
    EXPECT_LE(elevation, 30.0f);
    EXPECT_GE(azimuth, 30.0f);
    EXPECT_LE(azimuth, 40.0f);
}

// Issue 25: the projected box spans 85% of the narrower side in its larger dimension, centred,
// whatever the box's size and shape, the direction and the view's aspect.
TEST(Camera, FramingSpansTheNarrowerSideWithTheProjectedBoxCentred) {
    struct Shape {
        const char* name;
        glm::vec3 half;
    };
    for (Shape shape : {Shape{"cube", {1.0f, 1.0f, 1.0f}}, Shape{"long", {5.0f, 0.5f, 0.5f}},
                        Shape{"tall", {0.2f, 3.0f, 0.4f}}, Shape{"flat", {2.0f, 0.0f, 1.0f}}}) {
        for (float size : {0.005f, 1.0f, 1000.0f}) {
            for (glm::vec3 dir : {threeQuarterDirection(), glm::vec3(0, 0, 1), glm::vec3(-2, 1, -1)}) {
                glm::vec3 center = glm::vec3(3.0f, -2.0f, 1.0f) * size;
                glm::vec3 lo = center - shape.half * size, hi = center + shape.half * size;
                Camera c = framedCamera(Camera{}, corners(lo, hi), dir);
                expectValid(c);
                EXPECT_NEAR(glm::dot(direction(c), glm::normalize(dir)), 1.0f, 1e-5f);
                EXPECT_EQ(c.up, Camera{}.up);
                EXPECT_NEAR(glm::dot(c.target - center, direction(c)), 0.0f, 1e-4f * size)
                    << "the target at the depth of the box's centre";
                if (size <= 1.0f) { // (the largest boxes need a wider view inside the coordinate range)
                    EXPECT_EQ(c.fovyDeg, Camera{}.fovyDeg);
                }
                for (float aspect : {1.0f, 16.0f / 9.0f, 9.0f / 16.0f, 2.0f, 0.5f}) {
                    SCOPED_TRACE(std::string(shape.name) + " box of " + std::to_string(size) + " seen from (" +
                                 std::to_string(dir.x) + ", " + std::to_string(dir.y) + ", " + std::to_string(dir.z) +
                                 ") at aspect " + std::to_string(aspect));
                    Projected p = project(c, lo, hi, aspect);
                    EXPECT_NEAR(p.larger(), 0.85f, 0.002f);
                    EXPECT_NEAR(p.center.x, 0.0f, 0.002f);
                    EXPECT_NEAR(p.center.y, 0.0f, 0.002f);
                    EXPECT_TRUE(p.inside);
                    EXPECT_TRUE(p.betweenNearAndFar);
                }
                // Near and far leave the gestures room: zoom keeps the distance in [near * 2, far / 2].
                float distance = glm::distance(c.eye, c.target);
                EXPECT_LE(c.near * 2.0f, distance);
                EXPECT_GT(c.far / 2.0f, distance + glm::length(shape.half) * size);
            }
        }
    }
}

TEST(Camera, FramingAlongTheBasesDirectionKeepsItAndItsUpAndFieldOfView) {
    Camera base;
    base.eye = {3.0f, 1.0f, 2.0f};
    base.target = {1.0f, 1.0f, 1.0f};
    base.up = {0.0f, 0.0f, 1.0f};
    base.fovyDeg = 30.0f;
    const glm::vec3 lo(9.5f, -0.5f, -0.2f), hi(10.5f, 0.5f, 0.2f);
    Camera c = framedCamera(base, corners(lo, hi));
    EXPECT_NEAR(glm::dot(direction(c), direction(base)), 1.0f, 1e-6f);
    EXPECT_EQ(c.up, base.up);
    EXPECT_EQ(c.fovyDeg, 30.0f);
    EXPECT_NEAR(project(c, lo, hi, 1.0f).larger(), 0.85f, 0.002f);
    // Framing twice changes nothing more.
    Camera again = framedCamera(c, corners(lo, hi));
    EXPECT_LT(glm::distance(again.eye, c.eye), 1e-4f);
    EXPECT_LT(glm::distance(again.target, c.target), 1e-4f);
    // Looking along up (a base the validator refuses): another up, a camera it accepts.
    base.eye = base.target + glm::vec3(0.0f, 0.0f, 5.0f);
    Camera along = framedCamera(base, corners(lo, hi));
    EXPECT_GT(glm::length(glm::cross(glm::normalize(along.up), direction(along))), 0.99f);
    Diagnostics d;
    Preset p;
    p.camera = along;
    EXPECT_TRUE(parsePreset(presetToJson(p), "along.json", std::nullopt, d)) << toString(d);
    EXPECT_NEAR(project(along, lo, hi, 1.0f).larger(), 0.85f, 0.002f);
}

// The points framed are the model's own, not a box around them: a model seen from a corner of
// its box (a sphere's points) spans 85% itself, where its box's corners reach farther.
TEST(Camera, FramingFitsThePointsThemselves) {
    std::vector<glm::vec3> sphere;
    for (int i = 0; i < 64; ++i) {
        for (int j = 0; j <= 32; ++j) {
            float phi = glm::two_pi<float>() * static_cast<float>(i) / 64.0f;
            float theta = glm::pi<float>() * static_cast<float>(j) / 32.0f;
            sphere.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
        }
    }
    Camera c = framedCamera(Camera{}, sphere, threeQuarterDirection());
    // The sphere's silhouette, seen from d at distance D, has the half angle asin(1 / D) about
    // the centre: 0.85 of the view's half side, centred.
    EXPECT_NEAR(std::tan(std::asin(1.0f / glm::distance(c.eye, glm::vec3(0.0f)))),
                0.85f * std::tan(glm::radians(c.fovyDeg) / 2.0f), 0.005f);
    EXPECT_LT(glm::length(c.target), 1e-3f) << "a symmetric model: centred on its centre";
    EXPECT_GT(project(c, glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f).larger(), 1.0f) << "its box is cut";

    // A cloud of points (a fixed pseudo-random sequence), every one of them projected: the
    // larger dimension spans 85%, centred, at every aspect.
    std::vector<glm::vec3> cloud;
    std::uint32_t state = 12345u;
    auto next = [&state] { return static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
    for (int i = 0; i < 20000; ++i) {
        float u = next(), v = next(), w = next();
        cloud.push_back(glm::vec3(4.0f * u - 1.0f, 2.0f * v * v, w * u - 0.5f) + glm::vec3(7.0f, 0.0f, -3.0f));
    }
    Camera k = framedCamera(Camera{}, cloud, glm::vec3(-1.0f, 0.5f, 2.0f));
    for (float aspect : {1.0f, 16.0f / 9.0f, 9.0f / 16.0f}) {
        glm::mat4 view = glm::lookAt(k.eye, k.target, k.up);
        float tanHalfY = std::tan(glm::radians(k.fovyDeg) / 2.0f) / std::min(aspect, 1.0f);
        glm::mat4 clip = glm::perspective(2.0f * std::atan(tanHalfY), aspect, k.near, k.far) * view;
        glm::vec2 mn(INFINITY), mx(-INFINITY);
        for (const glm::vec3& point : cloud) {
            glm::vec4 p = clip * glm::vec4(point, 1.0f);
            mn = glm::min(mn, glm::vec2(p) / p.w);
            mx = glm::max(mx, glm::vec2(p) / p.w);
        }
        glm::vec2 sides = aspect >= 1.0f ? glm::vec2(aspect, 1.0f) : glm::vec2(1.0f, 1.0f / aspect);
        glm::vec2 extent = (mx - mn) * 0.5f * sides, center = (mx + mn) * 0.25f * sides;
        EXPECT_NEAR(std::max(extent.x, extent.y), 0.85f, 0.002f) << "aspect " << aspect;
        EXPECT_NEAR(center.x, 0.0f, 0.002f) << "aspect " << aspect;
        EXPECT_NEAR(center.y, 0.0f, 0.002f) << "aspect " << aspect;
    }
}

// A long box seen end on reaches far nearer the eye than the distance to its centre: near moves
// in so that it lies between near and far all the same.
TEST(Camera, FramingALongBoxEndOnKeepsItBetweenNearAndFar) {
    const glm::vec3 lo(-50.0f, -0.5f, -0.5f), hi(50.0f, 0.5f, 0.5f);
    Camera c = framedCamera(Camera{}, corners(lo, hi), glm::vec3(1.0f, 0.0f, 0.0f));
    expectValid(c);
    Projected p = project(c, lo, hi, 1.0f);
    EXPECT_TRUE(p.betweenNearAndFar);
    EXPECT_NEAR(p.larger(), 0.85f, 0.002f);
}

TEST(Camera, FramingStaysInsideTheRanges) {
    // Too large for the eye to stand back inside the coordinate range: it stays inside and the
    // field of view widens to fit.
    const glm::vec3 lo(-4000.0f), hi(4000.0f);
    Camera c = framedCamera(Camera{}, corners(lo, hi), threeQuarterDirection());
    expectValid(c);
    EXPECT_GT(c.fovyDeg, 45.0f);
    EXPECT_GT(std::max({std::abs(c.eye.x), std::abs(c.eye.y), std::abs(c.eye.z)}), 0.99f * limits::kCoordinate.max) << "at the edge, no nearer than needed";
    Projected p = project(c, lo, hi, 1.0f);
    EXPECT_NEAR(p.larger(), 0.85f, 0.002f);
    EXPECT_TRUE(p.betweenNearAndFar);
    // Too small: framed as a box of half diagonal 0.001, a valid camera; none, or not a number:
    // the same at the base's target.
    const glm::vec3 smallest(1e-3f / std::sqrt(3.0f));
    for (float half : {1e-9f, 0.0f}) {
        Camera tiny = framedCamera(Camera{}, corners(glm::vec3(1.0f - half), glm::vec3(1.0f + half)));
        expectValid(tiny);
        Projected t = project(tiny, glm::vec3(1.0f) - smallest, glm::vec3(1.0f) + smallest, 1.0f);
        EXPECT_TRUE(t.betweenNearAndFar);
        EXPECT_NEAR(t.larger(), 0.85f, 0.002f);
    }
    for (const std::vector<glm::vec3>& points : {std::vector<glm::vec3>{}, corners(glm::vec3(std::nanf("")), glm::vec3(1.0f))}) {
        Camera none = framedCamera(Camera{}, points);
        expectValid(none);
        EXPECT_NEAR(project(none, -smallest, smallest, 1.0f).larger(), 0.85f, 0.002f);
    }
    // Far outside the range, or not finite: the target at its edge or the base's, the camera still valid.
    expectValid(framedCamera(Camera{}, corners(glm::vec3(5e4f, -10.0f, -5e4f), glm::vec3(5e4f + 20.0f, 10.0f, -5e4f + 20.0f))));
    Camera lost = framedCamera(Camera{}, corners(glm::vec3(-3e38f, -INFINITY, 0.0f), glm::vec3(3e38f, INFINITY, 1.0f)));
    expectValid(lost);
    EXPECT_LT(glm::distance(lost.target, Camera{}.target), 1e-6f) << "the base's target";
}

} // namespace
} // namespace lab
