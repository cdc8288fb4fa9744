// slice_test.cpp — the (θh, θd) slice against the closed forms the lectures give for it.
//
// On the slice φd = 90° (core/plots/slice.h): N·L = N·V = cos θh cos θd, N·H = cos θh, V·H = L·H =
// cos θd and L·V = cos 2θd. So, with a unit white light and the lab's specular term Ks·S (no N·L):
//   * Blinn-Phong: S = (N·H)^n = cos^n θh — a function of θh alone: vertical stripes;
//   * Phong: R·V = 2(N·L)(N·V) − L·V = 2cos²θh cos²θd − cos 2θd = cos²θd cos 2θh + sin²θd;
//   * Cook-Torrance: S = D(cos θh)·F(cos θd)·G/(4 N·V); with G off, S·4(N·V)/D = F is Schlick's
//     F0 + (1 − F0)(1 − cos θd)^5, a function of θd alone;
//   * diffuse: Kd·cos θh cos θd.
// Ks and Kd are read as their Rec. 709 luminance. Away from the 90° edges, within 1e-5 relative:
// the model runs in float, so the exponents are kept where n·(float's ε) stays below that (n ≤ 40), and
// Phong's power is compared relatively where its R·V is not lost to cancellation (see there).
#include "core/plots/slice.h"

#include "core/lighting/lighting.h"
#include "core/plots/plot_data.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace lab {
namespace {

double cosd(double deg) { return std::cos(deg * 3.14159265358979323846 / 180.0); }

Preset coloured(BrdfModel brdf, float shininess) {
    Preset p;
    p.brdf = brdf;
    p.material.shininess = shininess;
    p.material.specular = {0.9f, 0.6f, 0.3f};
    p.material.diffuse = {0.2f, 0.5f, 0.7f};
    return p;
}

void expectRelative(double expected, double actual, const std::string& where) {
    EXPECT_NEAR(actual, expected, 1e-5 * std::max(std::fabs(expected), 1e-30)) << where;
}

TEST(Slice, VectorsFollowTheConstruction) {
    for (float h : {0.0f, 10.0f, 37.0f, 80.0f}) {
        for (float d : {0.0f, 5.0f, 45.0f, 89.0f}) {
            const SliceVectors v = sliceVectors(h, d);
            const std::string at = "θh " + std::to_string(h) + " θd " + std::to_string(d);
            EXPECT_NEAR(glm::length(v.L), 1.0f, 1e-6f) << at;
            EXPECT_NEAR(glm::length(v.V), 1.0f, 1e-6f) << at;
            EXPECT_NEAR(glm::dot(v.N, v.H), cosd(h), 1e-6) << at;
            EXPECT_NEAR(glm::dot(v.L, v.H), cosd(d), 1e-6) << at;
            EXPECT_NEAR(glm::dot(v.V, v.H), cosd(d), 1e-6) << at;
            EXPECT_NEAR(glm::dot(v.L, v.V), cosd(2.0 * d), 1e-6) << at;
            EXPECT_NEAR(glm::dot(v.N, v.L), cosd(h) * cosd(d), 1e-6) << at;
            if (d > 0.0f) { // H bisects L and V
                const glm::vec3 bisector = glm::normalize(v.L + v.V);
                EXPECT_NEAR(glm::dot(bisector, v.H), 1.0f, 1e-6f) << at;
            }
            // φd = 90°: L − V is across the plane of N and H (along the binormal y).
            EXPECT_NEAR((v.L - v.V).x, 0.0f, 1e-6f) << at;
            EXPECT_NEAR((v.L - v.V).z, 0.0f, 1e-6f) << at;
        }
    }
}

TEST(Slice, BlinnPhongIsVerticalStripesOfCosToTheN) {
    for (float n : {1.0f, 8.0f, 20.0f}) {
        const Preset p = coloured(BrdfModel::BlinnPhong, n);
        const SurfaceUniforms s = packSurfaceUniforms(p);
        const SliceImage image = sampleSlice(s);
        const double ks = luminance(p.material.specular);
        for (int row = 0; row <= 85; row += 5) {
            for (int column = 0; column <= 85; ++column) {
                const std::string at = "n " + std::to_string(n) + " θh " + std::to_string(column) + " θd " + std::to_string(row);
                const float value = image.specular[static_cast<std::size_t>(image.index(column, row))];
                expectRelative(ks * std::pow(cosd(column), n), value, at);
                // The same in every row: stripes.
                expectRelative(image.specular[static_cast<std::size_t>(image.index(column, 0))], value, at);
            }
        }
    }
}

TEST(Slice, PhongFollowsItsClosedForm) {
    for (float n : {1.0f, 20.0f, 40.0f}) {
        const Preset p = coloured(BrdfModel::Phong, n);
        const SurfaceUniforms s = packSurfaceUniforms(p);
        const double ks = luminance(p.material.specular);
        for (int d = 0; d <= 85; d += 5) {
            for (int h = 0; h <= 85; h += 1) {
                const double c2d = cosd(d) * cosd(d), s2d = 1.0 - c2d;
                const double rv = std::max(0.0, c2d * cosd(2.0 * h) + s2d);
                const double expected = ks * std::pow(rv, n);
                const float value = sliceValue(s, static_cast<float>(h), static_cast<float>(d)).specular;
                const std::string at = "n " + std::to_string(n) + " θh " + std::to_string(h) + " θd " + std::to_string(d);
                // R·V = 1 − 2cos²θd sin²θh is a difference near 1: a float's is up to 1e-7 off, which
                // the n-th power makes n·1e-7/(R·V) relative. Compared relatively where that is < 1e-5.
                if (rv > 0.01 * n) {
                    expectRelative(expected, value, at);
                } else {
                    EXPECT_NEAR(value, expected, 1e-6 * ks) << at;
                }
            }
        }
    }
}

TEST(Slice, CookTorranceSchlickFresnelDependsOnThetaDOnly) {
    for (Distribution dist : {Distribution::Beckmann, Distribution::Ggx}) {
        Preset p = coloured(BrdfModel::CookTorrance, 1.0f);
        p.cookTorrance.distribution = dist;
        p.cookTorrance.roughness = 0.4f;
        p.cookTorrance.ior = 1.8f;
        p.cookTorrance.geometry = false; // S = D F / (4 N·V)
        const SurfaceUniforms s = packSurfaceUniforms(p);
        const double ks = luminance(p.material.specular);
        const double f0 = std::pow((1.8 - 1.0) / (1.8 + 1.0), 2.0);
        for (int d = 0; d <= 85; d += 5) {
            const double schlick = f0 + (1.0 - f0) * std::pow(1.0 - cosd(d), 5.0);
            for (int h = 0; h <= 60; h += 4) { // beyond, Beckmann's exp(−tan²θh/m²) loses float digits
                const float value = sliceValue(s, static_cast<float>(h), static_cast<float>(d)).specular;
                const double NoV = cosd(h) * cosd(d);
                const double D = glsl::distributionTerm(static_cast<float>(cosd(h)), s.brdf);
                const double F = value * 4.0 * NoV / (ks * D);
                expectRelative(schlick, F, "θh " + std::to_string(h) + " θd " + std::to_string(d));
            }
        }
    }
}

TEST(Slice, DiffuseIsKdTimesCosThetaHCosThetaDAndEdgesAreZero) {
    const Preset p = coloured(BrdfModel::Phong, 10.0f);
    const SurfaceUniforms s = packSurfaceUniforms(p);
    const SliceImage image = sampleSlice(s);
    ASSERT_EQ(image.side(), kSliceSide);
    const double kd = luminance(p.material.diffuse);
    for (int d = 0; d <= 90; d += 3) {
        for (int h = 0; h <= 90; h += 3) {
            const std::size_t k = static_cast<std::size_t>(image.index(h, d));
            if (h == 90 || d == 90) {
                EXPECT_EQ(image.diffuse[k], 0.0f);
                EXPECT_EQ(image.specular[k], 0.0f);
                EXPECT_EQ(image.total[k], 0.0f);
            } else {
                expectRelative(kd * cosd(h) * cosd(d), image.diffuse[k], "θh " + std::to_string(h) + " θd " + std::to_string(d));
                EXPECT_EQ(image.total[k], image.diffuse[k] + image.specular[k]);
            }
        }
    }
}

TEST(Slice, TermSwitchesApplyAsInThePlots) {
    Preset p = coloured(BrdfModel::BlinnPhong, 10.0f);
    p.terms.specular = false;
    const SliceValue v = sliceValue(packSurfaceUniforms(p), 10.0f, 20.0f);
    EXPECT_EQ(v.specular, 0.0f);
    EXPECT_GT(v.diffuse, 0.0f);
}

// The mirror direction is on every slice (θh = 0): the plane plot's sample at θo = θi is the
// slice's value at (0, θi), by two different constructions of L and V.
TEST(Slice, MeetsThePlanePlotAtTheMirrorDirection) {
    for (BrdfModel brdf : {BrdfModel::Phong, BrdfModel::BlinnPhong, BrdfModel::CookTorrance}) {
        const Preset p = coloured(brdf, 30.0f);
        for (int deg : {0, 20, 45, 70}) {
            const std::vector<PlotSample> plane = reflectedIntensity(p, static_cast<float>(deg));
            const PlotSample& at = plane[static_cast<std::size_t>(deg + 90)];
            const SliceValue v = sliceValue(packSurfaceUniforms(p), 0.0f, static_cast<float>(deg));
            expectRelative(at.specular, v.specular, "θi " + std::to_string(deg));
            expectRelative(at.diffuse, v.diffuse, "θi " + std::to_string(deg));
            const SliceMarker m = planeToSlice(static_cast<float>(deg), static_cast<float>(deg));
            EXPECT_EQ(m.thetaHDeg, 0.0f);
            EXPECT_EQ(m.thetaDDeg, static_cast<float>(deg));
            EXPECT_TRUE(m.onSlice);
        }
    }
}

TEST(Slice, PlaneDirectionsMapToTheirHalfAndDifferenceAngles) {
    SliceMarker m = planeToSlice(30.0f, 50.0f);
    EXPECT_EQ(m.thetaHDeg, 10.0f);
    EXPECT_EQ(m.thetaDDeg, 40.0f);
    EXPECT_FALSE(m.onSlice);
    m = planeToSlice(30.0f, -60.0f); // V on L's side, 30° from it
    EXPECT_EQ(m.thetaHDeg, 45.0f);
    EXPECT_EQ(m.thetaDDeg, 15.0f);
    EXPECT_FALSE(m.onSlice);
    m = planeToSlice(30.0f, -30.0f); // V = L: θd = 0, on every slice
    EXPECT_EQ(m.thetaDDeg, 0.0f);
    EXPECT_TRUE(m.onSlice);
}

TEST(Slice, CsvHasTheHeaderAnd91By91RowsThetaHFastest) {
    const Preset p = coloured(BrdfModel::BlinnPhong, 20.0f);
    const SliceImage image = sampleSlice(packSurfaceUniforms(p));
    std::istringstream csv(sliceCsv(image));
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    EXPECT_EQ(line, "theta_h_deg,theta_d_deg,diffuse,specular,total");
    int rows = 0;
    while (std::getline(csv, line)) {
        const int h = rows % 91, d = rows / 91;
        float th = 0, td = 0, diffuse = 0, specular = 0, total = 0;
        ASSERT_EQ(std::sscanf(line.c_str(), "%f,%f,%f,%f,%f", &th, &td, &diffuse, &specular, &total), 5) << line;
        EXPECT_EQ(th, static_cast<float>(h));
        EXPECT_EQ(td, static_cast<float>(d));
        EXPECT_EQ(specular, image.specular[static_cast<std::size_t>(image.index(h, d))]) << line;
        EXPECT_EQ(total, image.total[static_cast<std::size_t>(image.index(h, d))]) << line;
        ++rows;
    }
    EXPECT_EQ(rows, 91 * 91);
}

TEST(Slice, CoarseImageHasTheFullImagesNumbersAndDifferenceIsSigned) {
    const Preset a = coloured(BrdfModel::BlinnPhong, 20.0f), b = coloured(BrdfModel::Phong, 20.0f);
    const SliceImage full = sampleSlice(packSurfaceUniforms(a)), coarse = sampleSlice(packSurfaceUniforms(a), 5);
    ASSERT_EQ(coarse.side(), 19);
    for (int row = 0; row < 19; ++row) {
        for (int column = 0; column < 19; ++column) {
            EXPECT_EQ(coarse.total[static_cast<std::size_t>(coarse.index(column, row))],
                      full.total[static_cast<std::size_t>(full.index(column * 5, row * 5))]);
        }
    }
    const SliceImage other = sampleSlice(packSurfaceUniforms(b));
    const SliceImage d = sliceDifference(full, other);
    const std::size_t k = static_cast<std::size_t>(full.index(20, 80));
    EXPECT_EQ(d.specular[k], full.specular[k] - other.specular[k]);
    EXPECT_LT(d.specular[k], 0.0f); // Phong keeps more at large θd (its lobe is round about R)
}

} // namespace
} // namespace lab
