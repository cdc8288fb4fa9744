// plot.h — the reflected-intensity data behind the polar plots and `lab plot`.
//
// A unit white directional light in the plane of incidence: N = (0, 1, 0),
// L = (-sin θi, cos θi, 0), V = (sin θo, cos θo, 0), θo from -90° to 90° in 1° steps. Each
// sample is the Rec. 709 luminance of Kd·max(0, N·L), of Ks·S and of their sum, with S from the
// same lighting functions the shaders run (lab::glsl).
#pragma once

#include "core/preset.h"

#include <string>
#include <vector>

namespace lab {

struct PlotSample {
    float thetaOutDeg;
    float diffuse;
    float specular;
    float total;
};

// 181 samples, θo = -90 … 90.
std::vector<PlotSample> reflectedIntensity(const Preset& preset, float incidentDeg);

// "theta_out_deg,diffuse,specular,total" and one line per sample.
std::string plotCsv(const std::vector<PlotSample>& samples);

} // namespace lab
