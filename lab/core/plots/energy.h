// energy.h — how much light the lighting model reflects in all: the albedo of each term.
//
// The directional-hemispherical reflectance (albedo) of the diffuse and specular terms for light
// arriving at incident angle θi, integrated numerically over the hemisphere of outgoing
// directions from the same per-light function the shaders and the plots run
// (glsl::lightContribution, with core/plots/plot_data.h's unit white directional light).
//
// Normalization. For a unit light the lab's colour I(L, V) (I_d = Kd·(N·L), I_s = Ks·S) is π
// times the reflected radiance per unit incoming irradiance measured across the beam, so that
//     ρ(θi) = 1/(π·cos θi) · ∫_Ω I(L, V) cos θo dω_o
// is the reflected flux over the incident flux, and a Lambertian Kd = 1 reflects exactly 1 at
// every θi (∫ cos θo dω = π). At θi = 90° no light arrives and ρ is undefined.
//
// Quadrature (fixed, the same for every material, so equal inputs give equal numbers):
//   * diffuse: Gauss-Legendre in cos θo on [0, 1] × the midpoint rule in φ, about N;
//   * specular: the lobes peak at the mirror direction R, so about R: Gauss-Legendre panels in the
//     angle α from R, graded geometrically from π/4096 to π (sharp and wide lobes alike fall on
//     several panels) and split where the horizon starts to cut the circle at α; in φ (on [0, π]:
//     the lobes are symmetric about the plane of incidence) the midpoint rule, or Gauss-Legendre
//     from the horizon's cut to π where it cuts. Directions below the horizon reflect nothing.
// README "Energy" gives the measured error. It does NOT model light emitted or ambient light
// (they do not depend on L), nor attenuation (a directional light).
#pragma once

#include "core/plots/plot_data.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace lab {

// Each term per RGB channel (the material's Kd and Ks are per channel), and its luminance.
struct Albedo {
    glm::vec3 diffuse{0.0f}, specular{0.0f};
    glm::vec3 total() const { return diffuse + specular; }
};
// One component as luminance, what the Energy view and the albedo figure draw (the total's is the
// luminance of the summed channels, as albedoCsv writes it).
float albedoOf(const Albedo& a, PlotComponent c);

// The quadrature's size: Gauss-Legendre nodes per panel (and in cos θo for the diffuse term) and
// midpoint steps in φ over [0, π]. The default is what the GUI, `lab plot --albedo` and the README's
// error figures use; the tests use finer ones as references.
struct AlbedoRule {
    int nodes = 8;
    int phiSteps = 64;
};

// ρ(inputs.incidentDeg) of the diffuse and specular terms (the sign of the angle does not matter);
// nullopt at |θi| ≥ 90°, where no light arrives.
std::optional<Albedo> albedo(const LobeInputs& inputs, const AlbedoRule& rule = {});

struct AlbedoSample {
    float incidentDeg;
    Albedo albedo;
};

// ρ for θi = 0°, 1°, …, 89° (inputs.incidentDeg is not used).
std::vector<AlbedoSample> albedoCurve(LobeInputs inputs, const AlbedoRule& rule = {});

// "theta_in_deg,diffuse,specular,total,total_r,total_g,total_b": the luminance of each term, as in
// plotCsv, then the total per channel (a channel may reflect more than the luminance shows).
std::string albedoCsv(const std::vector<AlbedoSample>& samples);

// Gauss-Legendre nodes and weights on [-1, 1] (n ≥ 1), by Newton's iteration on P_n.
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

} // namespace lab
