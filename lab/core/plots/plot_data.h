// plot_data.h — the reflected-intensity data behind the polar plots and `lab plot`.
//
// A unit white directional light in the plane of incidence: N = (0, 1, 0),
// L = (-sin θi, cos θi, 0), V = (sin θo, cos θo, 0), θo from -90° to 90° in 1° steps. Each
// sample is the Rec. 709 luminance of Kd·max(0, N·L), of Ks·S and of their sum (times the light's
// colours where LobeInputs gives it some: a probed point's light, core/plots/probe_lobe.h), from the same
// lighting function the shaders run for one light (glsl::lightContribution): a term the preset
// switches off (Preset::terms.diffuse, .specular) reads 0, as on the model. Emissive and ambient
// light do not depend on L or V and are not part of the plot.
#pragma once

#include "core/lighting/lighting.h"
#include "core/scene/preset.h"

#include <glm/vec2.hpp>

#include <array>
#include <string>
#include <vector>

namespace lab {

struct PlotSample {
    float thetaOutDeg;
    float diffuse;
    float specular;
    float total;
};

// Everything the samples depend on: the material, BRDF and term switches as the shaders get them
// (packed from the preset), the incident angle and the light that arrives. Equal inputs give equal
// samples, so the plots may keep samples from frame to frame keyed on them (ui/plots/plot_cache.h).
struct LobeInputs : SurfaceUniforms {
    float incidentDeg = 0.0f;
    // The light's diffuse and specular colours as they arrive: unit white for the plots and `lab
    // plot`; at a probed point its colours × Att × spot factor (core/plots/probe_lobe.h), so that
    // the lobe reads what the model reflects there.
    glm::vec3 lightDiffuse{1.0f}, lightSpecular{1.0f};
};
LobeInputs lobeInputs(const Preset& preset, float incidentDeg);
// Every field equal (floats compared exactly, so a NaN never equals and is never reused).
bool operator==(const LobeInputs& x, const LobeInputs& y);

// The plots' light: unit white, directional, arriving from `L` (unit, towards the light), no
// attenuation. The lobe plots and the albedo (core/plots/energy.h) shade with exactly this light.
glsl::Light unitLightFrom(const glm::vec3& L);
// The lobes' light: unitLightFrom(L) with the inputs' colours (white unless they say otherwise).
// The albedo (core/plots/energy.h) stays with the unit light: it is a ratio of reflected to incident.
glsl::Light lobeLightFrom(const LobeInputs& inputs, const glm::vec3& L);

// The plots' geometry for an incident angle θi (degrees, negative on the other side): N = (0, 1, 0),
// L = (−sin θi, cos θi, 0) towards the light, R = 2(N·L)N − L. The plane plots, the 3D lobe
// (core/plots/lobe3d.h) and the albedo all put their light there.
struct LobeVectors {
    glm::vec3 N, L, R;
};
LobeVectors lobeVectors(float incidentDeg);

// (sin θo, cos θo) for θo = -90° … 90° in 1° steps, index θo + 90: the directions of the samples.
const std::array<glm::vec2, 181>& outgoingDirections();

// 181 samples, θo = -90 … 90; or every `stepDeg` degrees of them (a divisor of 90: the same
// numbers at those angles), for a coarse plot.
std::vector<PlotSample> reflectedIntensity(const LobeInputs& inputs, int stepDeg = 1);
inline std::vector<PlotSample> reflectedIntensity(const Preset& preset, float incidentDeg) {
    return reflectedIntensity(lobeInputs(preset, incidentDeg));
}

// "theta_out_deg,diffuse,specular,total" and one line per sample.
std::string plotCsv(const std::vector<PlotSample>& samples);

//----------------------------------------------------------------------------------------
// Plot geometry: what the GUI draws, as numbers (tested against the lighting functions)
//----------------------------------------------------------------------------------------

enum class PlotComponent { Diffuse, Specular, Total };
enum class RadialScale { Linear, Log };

// How many decades below the outer circle the logarithmic scale shows.
inline constexpr float kLogDecades = 3.0f;

float componentOf(const PlotSample& s, PlotComponent c);
// The component of a diffuse and a specular part (the total is their sum, as the plots have it).
inline float componentOf(float diffuse, float specular, PlotComponent c) {
    return c == PlotComponent::Diffuse ? diffuse : c == PlotComponent::Specular ? specular : diffuse + specular;
}

// The radius, in [0, 1], at which `intensity` is drawn when `maxIntensity` is the outer circle:
// linear I/Imax, or logarithmic 1 + log10(I/Imax)/kLogDecades (0 below that range).
float plotRadius(float intensity, float maxIntensity, RadialScale scale);

// A lobe in the plot's unit half-disc, one point per sample: radius × (sin θo, cos θo), x along
// the surface towards the viewer's side, y along N.
std::vector<glm::vec2> lobePoints(const std::vector<PlotSample>& samples, PlotComponent component,
                                  float maxIntensity, RadialScale scale);

// The largest total over several sample sets (the outer circle when lobes are overlaid); 1e-6 at least.
float maxTotal(const std::vector<std::vector<PlotSample>>& sets);

// The outer circle for the largest intensity a plot draws: that intensity, or 1 where nothing is
// lit (the scale then shows 0 to 1). The lab's plots and the figures (core/plots/figures.h) both use it.
inline constexpr float kNothingLit = 2e-6f;
inline float outerRing(float largest) { return largest > kNothingLit ? largest : 1.0f; }

// The rings a radial scale draws inside an outer circle of `outer`, innermost first: each one's
// intensity and its radius in [0, 1] (none nearer the centre than 0.02).
struct RadialRing {
    float value, radius;
};
std::vector<RadialRing> radialRings(float outer, RadialScale scale);

// (d, Att(d)) for d from 0 to maxDistance, with the lighting model's attenuation().
std::vector<glm::vec2> attenuationCurve(const glm::vec3& coefficients, float maxDistance, int samples);

// Where the attenuation plot of `light` reads: the distance from the light to the model's origin,
// and the plot's largest d (twice that distance rounded up, at least 5; 5 for a directional light,
// which is not attenuated).
struct AttenuationSpan {
    float distance, maxDistance;
};
AttenuationSpan attenuationSpan(const LightDesc& light, const Model& model);

} // namespace lab
