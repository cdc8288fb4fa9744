// lobe3d.h — the reflected intensity over the whole hemisphere of outgoing directions: the data
// behind the plots window's 3D lobe and its intensity map (ui/plots_3d.cpp).
//
// The same light and lighting function as the plane-of-incidence plots (core/plots/plot_data.h): N = (0, 1, 0),
// a directional light from L = (-sin θi, cos θi, 0) (unit white, or LobeInputs' colours), each sample the Rec. 709 luminance
// of glsl::lightContribution's diffuse and specular parts for V(θo, φ) =
// (sin θo cos φ, cos θo, sin θo sin φ). φ = 0 is the plot's right half (θo > 0, the side of R),
// φ = 180° its left half: those two meridians are reflectedIntensity()'s samples, bit for bit
// (sin φ and cos φ are exact at multiples of 90°, θo in whole degrees as the plot has them).
//
// The grid: θo = 0 … 90° in 1° steps (91 rings, the plot's resolution), φ = 0 … 360° in 4° steps
// (91 meridians, the last one repeating the first so that the mesh closes without wrapping). What
// it does not do: draw, project or cache (ui/plots_3d.cpp does; the UI keeps grids by LobeInputs).
#pragma once

#include "core/plots/plot_data.h"

#include <glm/vec3.hpp>

#include <vector>

namespace lab {

inline constexpr int kLobeRings = 91;        // θo = 0, 1, …, 90°
inline constexpr int kLobeMeridians = 91;    // φ = 0, 4, …, 360° (the last is the first again)
inline constexpr float kLobeThetaStepDeg = 1.0f;
inline constexpr float kLobePhiStepDeg = 4.0f;

// V for θo, φ in degrees; exact (0 and ±1) at φ a multiple of 90°.
glm::vec3 outgoingDirection(float thetaDeg, float phiDeg);

struct HemisphereGrid {
    // Ring i (θo = i·1°), meridian j (φ = j·4°): index i·kLobeMeridians + j.
    std::vector<glm::vec3> directions;
    std::vector<float> diffuse, specular, total;
    float largestTotal = 0.0f; // over the grid

    static int index(int ring, int meridian) { return ring * kLobeMeridians + meridian; }
    const std::vector<float>& component(PlotComponent c) const {
        return c == PlotComponent::Diffuse ? diffuse : c == PlotComponent::Specular ? specular : total;
    }
    float largest(PlotComponent c) const;
};

// The grid for `inputs` (kLobeRings × kLobeMeridians evaluations of lightContribution).
HemisphereGrid sampleHemisphere(const LobeInputs& inputs);

// One component at direction V (unit, any direction: 0 where the model gives 0).
float intensityAt(const LobeInputs& inputs, const glm::vec3& V, PlotComponent component);

// The lobe's surface: plotRadius(I, outer, scale)·V for each grid direction, as lobePoints() makes
// the plot's curve (the in-plane meridians are lobePoints()'s points with z = 0).
std::vector<glm::vec3> lobeSurface(const HemisphereGrid& grid, PlotComponent component, float outer, RadialScale scale);

// The intensity map's disc: V seen from above N, at radius θo/90° in the direction of its azimuth
// (x along the plane of incidence towards R, y = z of V): an azimuthal equidistant projection, so
// every ring of the grid is a circle and the plane of incidence the x axis.
glm::vec2 mapPoint(const glm::vec3& V);

// Where one component is largest: the grid's largest sample, then refined by a compass search in
// (θo, φ) down to 1e-4°. A component that does not depend on V (the diffuse term) or is 0
// everywhere has its maximum everywhere: the search then stays at the first largest sample.
struct LobeMaximum {
    glm::vec3 V{0.0f, 1.0f, 0.0f};
    float thetaDeg = 0.0f, phiDeg = 0.0f;
    float value = 0.0f;
    int gridIndex = 0; // the grid sample the search started from
};
LobeMaximum lobeMaximum(const LobeInputs& inputs, const HemisphereGrid& grid, PlotComponent component);

} // namespace lab
