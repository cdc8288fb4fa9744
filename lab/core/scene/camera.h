// camera.h — moving the preset's camera: orbit, zoom, pan, framing. Pure math on Camera, no input.
#pragma once

#include "core/scene/preset.h"

#include <glm/vec3.hpp>

#include <span>

namespace lab {

// A bounding sphere: what a model's lights are placed and carried by (core/gltf/model_loader.h),
// and the centre orbiting lights turn about.
struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};

// The direction model viewers show a model from (<model-viewer>, Sketchfab): a three-quarter view
// from above the front, 35° from +z (glTF's front) towards +x and 25° above the horizontal. A unit
// vector from the target to the eye.
glm::vec3 threeQuarterDirection();

// A camera that shows all of `points` (a model's drawn positions: core/gltf/model_loader.h
// drawnPositions) tightly, as model viewers do: it looks along `direction` (from the target to
// the eye; `base`'s own direction when not given, +z when that has no length), keeps `base`'s up
// (unless the direction is parallel to it) and field of view, and stands where the points,
// projected, span 85% of the view's narrower side in their larger dimension, centred: the target
// is moved across the image plane to centre them, at the depth of the centre of their box.
// fovy_deg spans the narrower side (core/lighting/lighting.h), so this holds in a view of any
// shape and the points are whole in all. Near and far stand in the default camera's ratios to the
// distance (0.1 and 100 at 4), near closer still when a point is: the points lie between them,
// and zooming in or out by the gestures' limits keeps them there. Everything stays inside
// core/scene/limits.h: points whose box has a half diagonal below 0.001 are framed as a cube of
// that half diagonal (as are none, or ones that are not finite, at `base`'s target), points that
// project to (almost) nothing (a rod seen end on) as their box with each side at least a
// thousandth of its diagonal, and where the eye would leave the coordinate range the field of
// view widens (up to 179°) until it stays inside. Linear in the number of points but for a sort
// of those near the outline (about 0.1 s for a million triangles).
Camera framedCamera(const Camera& base, std::span<const glm::vec3> points);
Camera framedCamera(const Camera& base, std::span<const glm::vec3> points, glm::vec3 direction);

// Keeps the camera what a preset may hold (core/scene/limits.h): eye and target inside the coordinate
// range and at least twice the validator's minimum apart, in the direction they had. Every
// gesture and the panel call it, so a valid scene stays valid whatever was dragged.
void keepCameraValid(Camera& camera);

// Turns the eye around the target: `yawDeg` about the up vector (counter-clockwise seen from
// above), `pitchDeg` upwards (positive raises the eye), stopping 1° short of the poles so the
// view never flips. The distance is kept.
void orbitCamera(Camera& camera, float yawDeg, float pitchDeg);

// Moves the eye towards the target by `factor` of the distance (factor < 1 zooms in), keeping
// the distance within [near * 2, far / 2].
void zoomCamera(Camera& camera, float factor);

// Drags the scene by (dx, dy) times the view's narrower side (which fovy_deg spans) at the
// target's distance (x right, y up): eye and target move together the opposite way.
void panCamera(Camera& camera, float dx, float dy);

} // namespace lab
