// camera.h — moving the preset's camera: orbit, zoom, pan, framing. Pure math on Camera, no input.
#pragma once

#include "core/scene/preset.h"

#include <glm/vec3.hpp>

namespace lab {

// A bounding sphere: what framing fits in the view.
struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};

// The sphere through a box's corners: its centre and half its diagonal.
Sphere sphereAround(glm::vec3 boundsMin, glm::vec3 boundsMax);

// A camera that shows all of `sphere`: it looks at the centre along `base`'s direction (from
// the target to the eye; +z when that has no length), keeps `base`'s up and field of view, and
// stands back so that the sphere spans about 80% of the view's smaller side at `aspect`
// (width / height), touching no border. Near and far stand in the default camera's ratio to the
// distance (0.1 and 100 at 4): the sphere lies well between them, and zooming in or out by the
// gestures' limits keeps it there. Everything stays inside core/scene/limits.h: a radius below 0.001
// is framed as 0.001 (as is one that is not a number; a centre that is not finite is `base`'s
// target), and where the eye would leave the coordinate range it stays at the edge and the field
// of view widens (up to 179°) to fit the sphere.
Camera framedCamera(const Camera& base, const Sphere& sphere, float aspect = 1.0f);
Camera framedCamera(const Camera& base, glm::vec3 boundsMin, glm::vec3 boundsMax, float aspect = 1.0f);

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
