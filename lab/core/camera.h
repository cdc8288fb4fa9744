// camera.h — moving the preset's camera: orbit, zoom, pan. Pure math on Camera, no input.
#pragma once

#include "core/preset.h"

namespace lab {

// Keeps the camera what a preset may hold (core/limits.h): eye and target inside the coordinate
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

// Drags the scene by (dx, dy) view heights at the target's distance (x right, y up): eye and
// target move together the opposite way.
void panCamera(Camera& camera, float dx, float dy);

} // namespace lab
