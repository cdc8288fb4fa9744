// lobe3d_test.cpp — the 3D lobe's hemisphere against the plane-of-incidence plot, and where its
// maximum lies.
//
// The maxima, from the lab's equations (shaders/lighting.glsl): the specular part of the
// reflected intensity is Ks·S with a unit white light and no further factor (no N·L, no
// normalization on the specular term), and the diffuse part Kd·max(0, N·L) does not depend on V.
// So the total's maximum over V is S's maximum:
//   * Phong, S = max(0, R·V)^n: 1 at V = R = 2(N·L)N − L, less everywhere else;
//   * Blinn-Phong, S = max(0, N·H)^n with H = normalize(L + V): 1 where H = N, that is where
//     L + V is along N: V = 2(N·L)N − L, the same mirror direction (there H = N exactly).
// The test finds the V that makes H = N by its own reasoning (L + V ∥ N, |V| = 1) rather than
// calling reflectionVector, and checks H at the found maximum.
#include "core/plots/lobe3d.h"

#include "core/lighting/lighting.h"
#include "core/plots/plot_data.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <string>

namespace lab {
namespace {

Preset material(BrdfModel brdf, float shininess) {
    Preset p;
    p.brdf = brdf;
    p.material.shininess = shininess;
    return p;
}

float angleDeg(const glm::vec3& a, const glm::vec3& b) {
    return glm::degrees(std::acos(glm::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

// Presets that cover every BRDF, distribution and Fresnel, and the term switches.
std::vector<std::pair<std::string, Preset>> variety() {
    std::vector<std::pair<std::string, Preset>> out;
    out.emplace_back("phong", material(BrdfModel::Phong, 32.0f));
    out.emplace_back("blinn-phong", material(BrdfModel::BlinnPhong, 7.0f));
    Preset ct = material(BrdfModel::CookTorrance, 1.0f);
    for (Distribution d : {Distribution::Beckmann, Distribution::Gaussian, Distribution::Ggx}) {
        ct.cookTorrance.distribution = d;
        ct.cookTorrance.fresnel = d == Distribution::Gaussian ? FresnelMode::Full : FresnelMode::Schlick;
        out.emplace_back("cook-torrance " + std::to_string(static_cast<int>(d)), ct);
    }
    Preset off = material(BrdfModel::Phong, 5.0f);
    off.terms.diffuse = false;
    out.emplace_back("diffuse off", off);
    off.terms.diffuse = true;
    off.terms.specular = false;
    out.emplace_back("specular off", off);
    return out;
}

// φ = 0 is the plot's θo > 0 half, φ = 180° its θo < 0 half: the same numbers, bit for bit, for
// the full grid (every plot sample) and for the coarse one (every fifth).
TEST(Lobe3d, ThePlaneOfIncidenceIsThePlotsSamples) {
    ASSERT_EQ(kLobeThetaStepDeg, 1.0f); // one ring per plot sample
    for (GridSteps steps : {kLobeGrid, kLobeCoarseGrid}) {
        const int half = 180 / steps.phiDeg;
        for (const auto& [name, preset] : variety()) {
            for (float incident : {-70.0f, -15.0f, 0.0f, 30.0f, 45.0f, 89.0f}) {
                const LobeInputs in = lobeInputs(preset, incident);
                const std::vector<PlotSample> plot = reflectedIntensity(in);
                const HemisphereGrid grid = sampleHemisphere(in, steps);
                ASSERT_EQ(grid.total.size(), static_cast<std::size_t>(steps.rings() * steps.meridians()));
                for (int ring = 0; ring < grid.rings(); ++ring) {
                    for (int side : {1, -1}) {
                        const int meridian = side > 0 ? 0 : half;
                        const PlotSample& s = plot[static_cast<std::size_t>(90 + side * ring * steps.thetaDeg)];
                        const std::size_t k = static_cast<std::size_t>(grid.index(ring, meridian));
                        const std::string where = name + " at " + std::to_string(incident) + ", theta_o " +
                                                  std::to_string(side * ring * steps.thetaDeg) + ", step " +
                                                  std::to_string(steps.thetaDeg);
                        ASSERT_EQ(grid.diffuse[k], s.diffuse) << where;
                        ASSERT_EQ(grid.specular[k], s.specular) << where;
                        ASSERT_EQ(grid.total[k], s.total) << where;
                        ASSERT_EQ(grid.directions[k].z, 0.0f) << where;
                    }
                }
                // The closing meridian repeats the first.
                for (int ring = 0; ring < grid.rings(); ++ring) {
                    ASSERT_EQ(grid.total[static_cast<std::size_t>(grid.index(ring, grid.meridians() - 1))],
                              grid.total[static_cast<std::size_t>(grid.index(ring, 0))]);
                }
            }
        }
    }
}

// The coarse one is the full grid with rings and meridians left out: each of its samples is the full
// grid's at the same θo and φ, bit for bit.
TEST(Lobe3d, TheCoarseGridIsTheFullGridThinned) {
    for (const auto& [name, preset] : variety()) {
        const LobeInputs in = lobeInputs(preset, 35.0f);
        const HemisphereGrid full = sampleHemisphere(in), coarse = sampleHemisphere(in, kLobeCoarseGrid);
        EXPECT_EQ(coarse.rings(), 19);
        EXPECT_EQ(coarse.meridians(), 31);
        const int ringStep = kLobeCoarseGrid.thetaDeg / kLobeGrid.thetaDeg, meridianStep = kLobeCoarseGrid.phiDeg / kLobeGrid.phiDeg;
        for (int ring = 0; ring < coarse.rings(); ++ring) {
            for (int meridian = 0; meridian < coarse.meridians(); ++meridian) {
                const std::size_t d = static_cast<std::size_t>(coarse.index(ring, meridian));
                const std::size_t f = static_cast<std::size_t>(full.index(ring * ringStep, meridian * meridianStep));
                ASSERT_EQ(coarse.directions[d], full.directions[f]) << name << " ring " << ring << " meridian " << meridian;
                ASSERT_EQ(coarse.total[d], full.total[f]) << name << " ring " << ring << " meridian " << meridian;
            }
        }
    }
}

// The surface's points in the plane of incidence are the plot's curve points (lobePoints), at the
// same radius and in the same direction, for each component and both scales.
TEST(Lobe3d, TheSurfaceInThePlaneIsThePlotsCurve) {
    const int half = static_cast<int>(180.0f / kLobePhiStepDeg);
    for (const auto& [name, preset] : variety()) {
        const LobeInputs in = lobeInputs(preset, 35.0f);
        const std::vector<PlotSample> plot = reflectedIntensity(in);
        const HemisphereGrid grid = sampleHemisphere(in);
        const float outer = maxTotal({plot});
        for (PlotComponent c : {PlotComponent::Diffuse, PlotComponent::Specular, PlotComponent::Total}) {
            for (RadialScale scale : {RadialScale::Linear, RadialScale::Log}) {
                const std::vector<glm::vec2> curve = lobePoints(plot, c, outer, scale);
                const std::vector<glm::vec3> surface = lobeSurface(grid, c, outer, scale);
                for (int ring = 0; ring < kLobeRings; ++ring) {
                    for (int side : {1, -1}) {
                        const glm::vec3 p = surface[static_cast<std::size_t>(grid.index(ring, side > 0 ? 0 : half))];
                        const glm::vec2 q = curve[static_cast<std::size_t>(90 + side * ring)];
                        ASSERT_EQ(p.x, q.x) << name << " ring " << ring << " side " << side;
                        ASSERT_EQ(p.y, q.y) << name << " ring " << ring << " side " << side;
                        ASSERT_EQ(p.z, 0.0f);
                    }
                }
            }
        }
    }
}

// Away from the plane, a sample is the lighting function at its direction: checked against
// lightContribution called here, with V from θo and φ as the header defines it and the light
// from θi written out, not through the grid's own evaluation.
TEST(Lobe3d, EverySampleIsTheModelAtItsDirection) {
    const float incident = 50.0f;
    const LobeInputs in = lobeInputs(material(BrdfModel::BlinnPhong, 20.0f), incident);
    const HemisphereGrid grid = sampleHemisphere(in);
    ASSERT_EQ(grid.total.size(), static_cast<std::size_t>(kLobeRings * kLobeMeridians));
    const float ti = glm::radians(incident);
    glsl::Light light{};
    light.type = glsl::LIGHT_DIRECTIONAL;
    light.direction = -glm::vec3(-std::sin(ti), std::cos(ti), 0.0f); // the light travels against L
    light.diffuse = light.specular = glm::vec3(1.0f);
    light.attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
    for (int ring = 0; ring < kLobeRings; ring += 7) {
        for (int meridian = 0; meridian < kLobeMeridians; meridian += 5) {
            const std::size_t k = static_cast<std::size_t>(grid.index(ring, meridian));
            const float to = glm::radians(static_cast<float>(ring)), phi = glm::radians(static_cast<float>(meridian) * 4.0f);
            const glm::vec3 V(std::sin(to) * std::cos(phi), std::cos(to), std::sin(to) * std::sin(phi));
            EXPECT_LT(angleDeg(grid.directions[k], V), 1e-3f) << ring << " " << meridian;
            const glsl::LightTerms t = glsl::lightContribution(in.material, in.brdf, in.terms, light, glm::vec3(0.0f),
                                                               glm::vec3(0, 1, 0), grid.directions[k]);
            EXPECT_EQ(grid.diffuse[k], luminance(t.diffuse));
            EXPECT_EQ(grid.specular[k], luminance(t.specular));
            EXPECT_EQ(grid.total[k], luminance(t.diffuse) + luminance(t.specular));
        }
    }
}

// The classic difference the 3D view shows: Phong's lobe is round about R (it depends on R·V
// alone); Blinn-Phong's is not: on the same cone, 8.6° around R, it reads the same in the plane of
// incidence at every θi (N·H there turns by half the angle) but less and less across the plane as
// the light goes towards grazing (0.93, 0.80, 0.18 of its peak at n = 20 for θi = 30°, 60°, 80°):
// the lobe is drawn out along the plane of incidence.
TEST(Lobe3d, PhongIsRoundAboutRAndBlinnPhongIsNot) {
    float lastGap = 0.0f;
    for (float incident : {30.0f, 60.0f, 80.0f}) {
        const LobeVectors v = lobeVectors(incident);
        const glm::vec3 inPlane = glm::normalize(glm::cross(v.R, glm::vec3(0, 0, 1))), across(0, 0, 1);
        const glm::vec3 a = glm::normalize(v.R + 0.15f * inPlane), b = glm::normalize(v.R + 0.15f * across);
        ASSERT_NEAR(angleDeg(a, v.R), angleDeg(b, v.R), 1e-3f);
        const LobeInputs phong = lobeInputs(material(BrdfModel::Phong, 20.0f), incident);
        EXPECT_NEAR(intensityAt(phong, a, PlotComponent::Specular), intensityAt(phong, b, PlotComponent::Specular), 1e-5f)
            << incident;
        const LobeInputs blinn = lobeInputs(material(BrdfModel::BlinnPhong, 20.0f), incident);
        const float gap = intensityAt(blinn, a, PlotComponent::Specular) - intensityAt(blinn, b, PlotComponent::Specular);
        EXPECT_GT(gap, lastGap + 0.01f) << incident << ": across the plane less than along it, more so towards grazing";
        lastGap = gap;
    }
}

// The V where H = normalize(L + V) equals N: L + V = t·N with |V| = 1, so V = t·N − L with
// t² − 2t(N·L) + 1 = 1, t = 2(N·L).
glm::vec3 whereHIsN(const glm::vec3& N, const glm::vec3& L) {
    const float t = 2.0f * glm::dot(N, L);
    return t * N - L;
}

// Float rounding makes a peak flat: (R·V)^n = 1 − nδ²/2 is 1 in float for δ below about
// sqrt(1.2e-7/n) rad, so the search can only find the peak to about 0.02° for n = 1.
constexpr float kPeakToleranceDeg = 0.05f;

// From the full grid and from the coarse one (the search starts a coarse cell away and still ends at R).
TEST(Lobe3d, PhongPeaksAtR) {
    for (GridSteps steps : {kLobeGrid, kLobeCoarseGrid}) {
        for (float n : {1.0f, 8.0f, 32.0f, 200.0f, 2000.0f}) {
            for (float incident : {0.0f, 13.0f, 37.0f, -52.0f, 75.5f, 86.0f}) {
                const LobeInputs in = lobeInputs(material(BrdfModel::Phong, n), incident);
                const HemisphereGrid grid = sampleHemisphere(in, steps);
                const LobeVectors v = lobeVectors(in.incidentDeg);
                const std::string where = "n " + std::to_string(n) + ", incident " + std::to_string(incident) +
                                          ", grid step " + std::to_string(steps.phiDeg);
                for (PlotComponent c : {PlotComponent::Specular, PlotComponent::Total}) {
                    const LobeMaximum m = lobeMaximum(in, grid, c);
                    EXPECT_LT(angleDeg(m.V, v.R), kPeakToleranceDeg) << where;
                    // The drawn surface's largest vertex is within one grid cell of R.
                    const glm::vec3 gridBest = grid.directions[static_cast<std::size_t>(m.gridIndex)];
                    EXPECT_LE(angleDeg(gridBest, v.R), static_cast<float>(steps.phiDeg)) << where;
                    EXPECT_GE(m.value, grid.component(c)[static_cast<std::size_t>(m.gridIndex)]) << where;
                }
            }
        }
    }
}

TEST(Lobe3d, BlinnPhongPeaksWhereHIsN) {
    for (GridSteps steps : {kLobeGrid, kLobeCoarseGrid}) {
        for (float n : {1.0f, 8.0f, 64.0f, 500.0f}) {
            for (float incident : {0.0f, 21.0f, 44.5f, -63.0f, 80.0f}) {
                const LobeInputs in = lobeInputs(material(BrdfModel::BlinnPhong, n), incident);
                const HemisphereGrid grid = sampleHemisphere(in, steps);
                const LobeVectors v = lobeVectors(in.incidentDeg);
                const std::string where = "n " + std::to_string(n) + ", incident " + std::to_string(incident) +
                                          ", grid step " + std::to_string(steps.phiDeg);
                const LobeMaximum m = lobeMaximum(in, grid, PlotComponent::Total);
                // From the coarse one the search takes another path over the flat top of n = 1's peak
                // and stops where float rounding stops it: 0.056° from it at 21°.
                const float tolerance = steps == kLobeGrid ? kPeakToleranceDeg : 2.0f * kPeakToleranceDeg;
                EXPECT_LT(angleDeg(m.V, whereHIsN(v.N, v.L)), tolerance) << where;
                // And H there is N.
                EXPECT_LT(angleDeg(glsl::halfVector(v.L, m.V), v.N), tolerance) << where;
            }
        }
    }
}

// Cook-Torrance leans off the mirror direction: 1/(4 N·V) and the Fresnel term grow towards
// grazing, so for a rough surface lit obliquely the peak lies in the plane of incidence beyond R
// (the off-specular peak of Torrance and Sparrow).
TEST(Lobe3d, CookTorrancePeaksBeyondRForARoughSurface) {
    Preset p = material(BrdfModel::CookTorrance, 1.0f);
    p.cookTorrance.roughness = 0.4f;
    for (float incident : {40.0f, 60.0f}) {
        const LobeInputs in = lobeInputs(p, incident);
        const LobeMaximum m = lobeMaximum(in, sampleHemisphere(in), PlotComponent::Specular);
        EXPECT_NEAR(std::fmod(m.phiDeg + 180.0f, 360.0f) - 180.0f, 0.0f, kPeakToleranceDeg) << incident;
        EXPECT_GT(m.thetaDeg, incident + 1.0f) << incident;
    }
}

// The diffuse term does not depend on V: its lobe is a hemisphere, and its maximum stays put.
TEST(Lobe3d, TheDiffuseLobeIsAHemisphere) {
    const LobeInputs in = lobeInputs(material(BrdfModel::Phong, 10.0f), 30.0f);
    const HemisphereGrid grid = sampleHemisphere(in);
    const float first = grid.diffuse.front();
    EXPECT_GT(first, 0.0f);
    for (float d : grid.diffuse) {
        ASSERT_EQ(d, first);
    }
    const LobeMaximum m = lobeMaximum(in, grid, PlotComponent::Diffuse);
    EXPECT_EQ(m.gridIndex, 0);
    EXPECT_EQ(m.value, first);
}

TEST(Lobe3d, TheMapPutsRingsOnCirclesAndThePlaneOnTheXAxis) {
    EXPECT_EQ(mapPoint({0, 1, 0}), glm::vec2(0.0f));
    for (float theta : {10.0f, 45.0f, 90.0f}) {
        for (float phi : {0.0f, 37.0f, 180.0f, 300.0f}) {
            const glm::vec2 q = mapPoint(outgoingDirection(theta, phi));
            EXPECT_NEAR(glm::length(q), theta / 90.0f, 1e-5f);
            if (theta > 0.0f) {
                const float turn = std::atan2(q.y, q.x) - glm::radians(phi); // a multiple of 2π
                EXPECT_NEAR(std::remainder(turn, glm::two_pi<float>()), 0.0f, 1e-4f) << theta << " " << phi;
            }
        }
    }
    EXPECT_GT(mapPoint(outgoingDirection(30, 0)).x, 0.0f); // R's side on the right
}

} // namespace
} // namespace lab
