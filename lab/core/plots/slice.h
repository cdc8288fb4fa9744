// slice.h — the BRDF as an image over the half angle θh and the difference angle θd (Rusinkiewicz
// 1998), as Disney's BRDF Explorer shows it: the data behind the plots window's Slice tab, `lab plot
// --figure slice` and its CSV.
//
// The construction (README "The slice"): N = (0, 0, 1); the half vector H = (sin θh, 0, cos θh),
// at φh = 0; L and V the difference vector D(θd, φd) = (sin θd cos φd, sin θd sin φd, cos θd) and
// D(θd, φd + 180°) taken from H's frame (z along H, y the binormal (0, 1, 0)) to the world, that is
// rotated by θh about y. On the slice φd = 90°:
//     L = (sin θh cos θd,  sin θd, cos θh cos θd),   V = (sin θh cos θd, −sin θd, cos θh cos θd),
// so N·L = N·V = cos θh cos θd, H = normalize(L + V) exactly, and the angle between L and V is 2θd.
// Each value is what the lobe plot shows for a unit white directional light from L seen from V (the
// Rec. 709 luminance of glsl::lightContribution's diffuse and specular parts, the preset's term switches
// applied): Blinn-Phong's specular is Ks·cos^n θh, Phong's Ks·max(0, cos²θd cos 2θh + sin²θd)^n.
// Where N·L or N·V is 0 (θh or θd = 90°) the value is 0.
//
// The plane plot's directions lie on other slices: L at θi and V at θo in the plane of incidence have
// θh = |θo − θi|/2, θd = |θi + θo|/2 and φd = 0° or 180°, so they are on this slice only where θo = θi
// (θh = 0, where φd is undefined). What it does not do: draw or cache (ui/plots/plots_slice.cpp does).
#pragma once

#include "core/lighting/lighting.h"
#include "core/plots/plot_data.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace lab {

inline constexpr float kSlicePhiDeg = 90.0f; // φd of the slice
inline constexpr int kSliceSide = 91;        // θh, θd = 0 … 90° in 1° steps

struct SliceVectors {
    glm::vec3 N, H, L, V;
};
// The directions at (θh, θd, φd) in degrees, by the construction above.
SliceVectors sliceVectors(float thetaHDeg, float thetaDDeg, float phiDDeg = kSlicePhiDeg);

// The diffuse and specular luminance at one point of the slice (0 where N·L or N·V ≤ 0).
struct SliceValue {
    float diffuse = 0.0f, specular = 0.0f;
    float total() const { return diffuse + specular; }
    float component(PlotComponent c) const { return componentOf(diffuse, specular, c); }
};
SliceValue sliceValue(const SurfaceUniforms& surface, float thetaHDeg, float thetaDDeg);

// The image: θh across (column), θd down (row), every `stepDeg` degrees (a divisor of 90): side × side
// values, index row·side + column, θh varying fastest — the CSV's order. Row 0 is θd = 0.
struct SliceImage {
    int stepDeg = 1;
    std::vector<float> diffuse, specular, total;

    int side() const { return 90 / stepDeg + 1; }
    int index(int column, int row) const { return row * side() + column; }
    const std::vector<float>& component(PlotComponent c) const {
        return c == PlotComponent::Diffuse ? diffuse : c == PlotComponent::Specular ? specular : total;
    }
    float largest(PlotComponent c) const;
};
SliceImage sampleSlice(const SurfaceUniforms& surface, int stepDeg = 1);

// A − B, sample by sample, each component (the slice of the difference; both sampled alike).
SliceImage sliceDifference(const SliceImage& a, const SliceImage& b);

// The plane plot's (θi, θo) on the (θh, θd) plane: (|θo − θi|/2, |θi + θo|/2), and whether that point
// is on this slice (θo = θi) or only has the same angles on another (φd = 0° or 180°).
struct SliceMarker {
    float thetaHDeg = 0.0f, thetaDDeg = 0.0f;
    bool onSlice = false;
};
SliceMarker planeToSlice(float incidentDeg, float outgoingDeg);

// The slice of the difference's palette, diverging about 0: t in [−1, 1] (the value over the largest
// |A − B|), ColorBrewer's PuOr (Harrower and Brewer 2003; safe for the common colour blindnesses):
// purple where B reflects more (t < 0), near-white at 0, orange where A does (t > 0); linear between
// its five stops, clamped outside [−1, 1].
glm::vec3 divergingColor(float t);
// Where a signed difference v goes on that palette, t in [−1, 1], for the largest |A − B| `largestAbs`:
// v / largestAbs (linear), or sign(v)·plotRadius(|v|, largestAbs, Log), the plots' 3-decade log scale on
// |v| (log: a difference a thousand times smaller than the largest still shows). 0 where both are 0.
float differencePosition(float v, float largestAbs, RadialScale scale);

// "theta_h_deg,theta_d_deg,diffuse,specular,total" and one row per sample, θh varying fastest.
std::string sliceCsv(const SliceImage& image);

} // namespace lab
