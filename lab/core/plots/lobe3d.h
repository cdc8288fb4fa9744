// lobe3d.h — the reflected intensity over the whole hemisphere of outgoing directions: the data
// behind the plots window's 3D lobe and its intensity map (ui/plots/plots_3d.cpp).
//
// The same light and lighting function as the plane-of-incidence plots (core/plots/plot_data.h): N = (0, 1, 0),
// a directional light from L = (-sin θi, cos θi, 0) (unit white, or LobeInputs' colours), each sample the Rec. 709 luminance
// of glsl::lightContribution's diffuse and specular parts for V(θo, φ) =
// (sin θo cos φ, cos θo, sin θo sin φ). φ = 0 is the plot's right half (θo > 0, the side of R),
// φ = 180° its left half: those two meridians are reflectedIntensity()'s samples, bit for bit
// (sin φ and cos φ are exact at multiples of 90°, θo in whole degrees as the plot has them).
//
// The grid: θo = 0 … 90° in 1° steps (91 rings, the plot's resolution), φ = 0 … 360° in 4° steps
// (91 meridians, the last one repeating the first so that the mesh closes without wrapping); and a
// coarse of it (θo by 5°, φ by 12°: 19 × 31, 7% of the samples) that the 3D lobe draws while its
// inputs change frame after frame (a drag), whose in-plane meridians are the plot's samples too.
// What it does not do: draw, project or cache (ui/plots/plots_3d.cpp does; the UI keeps grids by
// LobeInputs).
#pragma once

#include "core/plots/plot_data.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace lab {

// A grid's spacing in whole degrees: θo's step divides 90 and φ's divides 180 (so that φ = 0 and
// 180°, the plane of incidence, are meridians).
struct GridSteps {
    int thetaDeg = 1, phiDeg = 4;
    constexpr int rings() const { return 90 / thetaDeg + 1; }      // θo = 0, step, …, 90°
    constexpr int meridians() const { return 360 / phiDeg + 1; }   // φ = 0, step, …, 360° (the first again)
};
constexpr bool operator==(const GridSteps& x, const GridSteps& y) { return x.thetaDeg == y.thetaDeg && x.phiDeg == y.phiDeg; }
inline constexpr GridSteps kLobeGrid{1, 4};
inline constexpr GridSteps kLobeCoarseGrid{5, 12};
inline constexpr int kLobeRings = kLobeGrid.rings();         // 91
inline constexpr int kLobeMeridians = kLobeGrid.meridians(); // 91
inline constexpr float kLobeThetaStepDeg = static_cast<float>(kLobeGrid.thetaDeg);
inline constexpr float kLobePhiStepDeg = static_cast<float>(kLobeGrid.phiDeg);
static_assert(90 % kLobeGrid.thetaDeg == 0 && 180 % kLobeGrid.phiDeg == 0 && 90 % kLobeCoarseGrid.thetaDeg == 0 &&
              180 % kLobeCoarseGrid.phiDeg == 0 && kLobeCoarseGrid.thetaDeg % kLobeGrid.thetaDeg == 0 &&
              kLobeCoarseGrid.phiDeg % kLobeGrid.phiDeg == 0, "the coarse grid's directions are the full grid's");
static_assert(kLobeCoarseGrid.rings() * kLobeCoarseGrid.meridians() < kLobeRings * kLobeMeridians / 10);

// V for θo, φ in degrees; exact (0 and ±1) at φ a multiple of 90°.
glm::vec3 outgoingDirection(float thetaDeg, float phiDeg);

struct HemisphereGrid {
    GridSteps steps = kLobeGrid;
    // Ring i (θo = i·steps.thetaDeg), meridian j (φ = j·steps.phiDeg): index i·meridians() + j.
    std::vector<glm::vec3> directions;
    std::vector<float> diffuse, specular, total;
    float largestTotal = 0.0f; // over the grid

    int rings() const { return steps.rings(); }
    int meridians() const { return steps.meridians(); }
    int index(int ring, int meridian) const { return ring * meridians() + meridian; }
    const std::vector<float>& component(PlotComponent c) const {
        return c == PlotComponent::Diffuse ? diffuse : c == PlotComponent::Specular ? specular : total;
    }
    float largest(PlotComponent c) const;
};

// The grid for `inputs` (rings × meridians evaluations of lightContribution).
HemisphereGrid sampleHemisphere(const LobeInputs& inputs, GridSteps steps = kLobeGrid);

// One component at direction V (unit, any direction: 0 where the model gives 0).
float intensityAt(const LobeInputs& inputs, const glm::vec3& V, PlotComponent component);

// The lobe's surface: plotRadius(I, outer, scale)·V for each grid direction, as lobePoints() makes
// the plot's curve (the in-plane meridians are lobePoints()'s points with z = 0).
std::vector<glm::vec3> lobeSurface(const HemisphereGrid& grid, PlotComponent component, float outer, RadialScale scale);
// One point of it: grid sample k's.
glm::vec3 lobeSurfacePoint(const HemisphereGrid& grid, std::size_t k, PlotComponent component, float outer, RadialScale scale);

// The intensity map's disc: V seen from above N, at radius θo/90° in the direction of its azimuth
// (x along the plane of incidence towards R, y = z of V): an azimuthal equidistant projection, so
// every ring of the grid is a circle and the plane of incidence the x axis.
glm::vec2 mapPoint(const glm::vec3& V);

// Where one component is largest: the grid's largest sample, then refined by a compass search in
// (θo, φ) from the grid's φ step down to 1e-4°. A component that does not depend on V (the diffuse
// term) or is 0 everywhere has its maximum everywhere: the search then stays at the first largest
// sample.
struct LobeMaximum {
    glm::vec3 V{0.0f, 1.0f, 0.0f};
    float thetaDeg = 0.0f, phiDeg = 0.0f;
    float value = 0.0f;
    int gridIndex = 0; // the grid sample the search started from
};
LobeMaximum lobeMaximum(const LobeInputs& inputs, const HemisphereGrid& grid, PlotComponent component);

} // namespace lab
