// describe.h — the scene and its plots in words: the text alternatives of the pictures.
//
// What a student who cannot see the canvas reads instead (the page's parallel DOM, web/access.js):
// the model's view described from the camera (the model, its shading and BRDF, each light and
// where it is, where the highlight falls), the plane plot as a short summary and a table of its
// numbers, the lobe's peak and the albedo, the (θh, θd) slice. Words only from the preset and the lighting model's
// numbers (plot_data.h, energy.h); no UI.
#pragma once

#include "core/plots/plot_data.h"
#include "core/scene/preset.h"

#include <string>
#include <vector>

namespace lab {

// Where `d` points as seen from `camera`: "upper left, in front", "right, behind", "straight ahead".
// A part of the unit vector above `side` counts (sin 22.5°: the eight directions of a compass rose).
std::string directionWords(const Camera& camera, const glm::vec3& d, float side = 0.38f);

// The view of the model in a few sentences: "A sphere, Phong shading, Blinn-Phong BRDF, shininess
// 32. Light 1, point, on: upper right, in front, 3.5 units from the model's centre. The highlight
// of light 1 falls on the upper right of the model."
std::string describeScene(const Preset& preset);

// The plane plot at the preset's incident angle: one sentence (its peak and where), and its rows
// every `stepDeg` degrees of the outgoing angle.
struct PlotWords {
    std::string summary;
    std::vector<PlotSample> rows;
};
PlotWords describePlanePlot(const Preset& preset, int stepDeg = 5);

// The lobe's and the energy's summary: the peak of the specular lobe and its direction, the albedo
// of each term at the plot's incident angle.
std::string describeLobe(const Preset& preset);

// The Slice tab's image in one or two sentences (core/plots/slice.h, the specular term, as the tab
// opens): its largest value and where, how far in θh it stays above half of that, and whether it is
// the same at every θd (a model of N·H alone: vertical stripes). From the full image (8281 values).
std::string describeSlice(const Preset& preset);

} // namespace lab
