// plot_data_test.cpp — the polar-plot samples follow the documented geometry and the lighting model.
#include "core/plots/plot_data.h"

#include "core/lighting/lighting.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>

namespace lab {
namespace {

TEST(Plot, SamplesEveryDegreeFromMinus90To90) {
    std::vector<PlotSample> s = reflectedIntensity(Preset{}, 45.0f);
    ASSERT_EQ(s.size(), 181u);
    EXPECT_EQ(s.front().thetaOutDeg, -90.0f);
    EXPECT_EQ(s[90].thetaOutDeg, 0.0f);
    EXPECT_EQ(s.back().thetaOutDeg, 90.0f);
}

// A coarse plot (the overlay's while it changes) is the same samples at every 3rd degree; a step that
// does not divide 90 gives every degree.
TEST(Plot, ACoarseLobeIsEveryStepDegreesOfTheSamples) {
    Preset p;
    p.material.shininess = 60.0f;
    const LobeInputs in = lobeInputs(p, 30.0f);
    const std::vector<PlotSample> full = reflectedIntensity(in), coarse = reflectedIntensity(in, 3);
    ASSERT_EQ(coarse.size(), 61u);
    for (std::size_t i = 0; i < coarse.size(); ++i) {
        const PlotSample& f = full[3 * i];
        EXPECT_EQ(coarse[i].thetaOutDeg, f.thetaOutDeg);
        EXPECT_EQ(coarse[i].diffuse, f.diffuse);
        EXPECT_EQ(coarse[i].specular, f.specular);
        EXPECT_EQ(coarse[i].total, f.total);
    }
    EXPECT_EQ(reflectedIntensity(in, 7).size(), 181u);
    EXPECT_EQ(reflectedIntensity(in, 0).size(), 181u);
}

TEST(Plot, DiffuseIsLambertAndTheSameInEveryDirection) {
    Preset p;
    p.material.diffuse = {0.5f, 0.25f, 1.0f};
    std::vector<PlotSample> s = reflectedIntensity(p, 60.0f);
    float expected = (0.2126f * 0.5f + 0.7152f * 0.25f + 0.0722f * 1.0f) * 0.5f; // luminance(Kd) cos 60
    for (const PlotSample& x : s) {
        EXPECT_NEAR(x.diffuse, expected, 1e-6f);
        EXPECT_FLOAT_EQ(x.total, x.diffuse + x.specular);
    }
}

TEST(Plot, PhongLobePeaksAtTheMirrorAngle) {
    Preset p;
    p.material.shininess = 50.0f;
    std::vector<PlotSample> s = reflectedIntensity(p, 30.0f);
    auto peak = std::max_element(s.begin(), s.end(), [](auto& a, auto& b) { return a.specular < b.specular; });
    EXPECT_EQ(peak->thetaOutDeg, 30.0f);
    EXPECT_NEAR(peak->specular, luminance(p.material.specular), 1e-5f);
    EXPECT_EQ(s[0].specular, 0.0f); // -90 degrees: R.V < 0
}

TEST(Plot, SpecularMatchesTheSharedLightingFunctions) {
    for (BrdfModel model : {BrdfModel::Phong, BrdfModel::BlinnPhong, BrdfModel::CookTorrance}) {
        Preset p;
        p.brdf = model;
        p.material.specular = {1.0f, 0.5f, 0.25f};
        std::vector<PlotSample> s = reflectedIntensity(p, 25.0f);
        for (int deg : {-60, -10, 0, 25, 40, 89}) {
            float ti = glm::radians(25.0f), to = glm::radians(float(deg));
            float S = glsl::specularFactor(glm::vec3(0, 1, 0), glm::vec3(-std::sin(ti), std::cos(ti), 0),
                                           glm::vec3(std::sin(to), std::cos(to), 0), p.material.shininess, packSurfaceUniforms(p).brdf);
            EXPECT_FLOAT_EQ(s[std::size_t(deg + 90)].specular, luminance(p.material.specular * S)) << deg;
        }
    }
}

// The plot follows the preset's term switches as the shaders do: a switched-off term reads 0.
TEST(Plot, SwitchedOffTermsReadZero) {
    Preset p;
    p.terms.specular = false;
    for (const PlotSample& x : reflectedIntensity(p, 30.0f)) {
        EXPECT_EQ(x.specular, 0.0f) << x.thetaOutDeg;
        EXPECT_GT(x.diffuse, 0.0f) << x.thetaOutDeg;
        EXPECT_EQ(x.total, x.diffuse);
    }
    p.terms = {};
    p.terms.diffuse = false;
    std::vector<PlotSample> s = reflectedIntensity(p, 30.0f);
    for (const PlotSample& x : s) {
        EXPECT_EQ(x.diffuse, 0.0f) << x.thetaOutDeg;
        EXPECT_EQ(x.total, x.specular);
    }
    EXPECT_GT(s[120].specular, 0.0f); // the mirror direction, 30 degrees
    // Emissive and ambient are not plotted: switching them changes nothing.
    Preset q;
    q.terms.emissive = false;
    q.terms.ambient = false;
    std::vector<PlotSample> a = reflectedIntensity(q, 30.0f), b = reflectedIntensity(Preset{}, 30.0f);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].total, b[i].total);
    }
}

// The shipped "ambient only" preset: no diffuse, no specular anywhere in the plot.
TEST(Plot, AmbientOnlyPresetPlotsNothing) {
    Diagnostics diagnostics;
    std::optional<LoadedPreset> p = loadPreset(std::filesystem::path(LAB_SOURCE_DIR) / "presets/01-ambient-only.json", diagnostics);
    ASSERT_TRUE(p);
    for (const PlotSample& x : reflectedIntensity(p->preset, p->preset.plotIncidentDeg)) {
        EXPECT_EQ(x.diffuse, 0.0f);
        EXPECT_EQ(x.specular, 0.0f);
        EXPECT_EQ(x.total, 0.0f);
    }
}

// The plots keep samples keyed on LobeInputs: every preset setting the samples depend on must
// change the inputs (or a cached lobe would stay as it was), and what they do not depend on
// (camera, lights, shading, model) must not (or an orbit would recompute every lobe).
TEST(Plot, LobeInputsChangeExactlyWithWhatTheSamplesDependOn) {
    const Preset base;
    const LobeInputs reference = lobeInputs(base, 30.0f);
    EXPECT_TRUE(reference == lobeInputs(base, 30.0f));
    EXPECT_FALSE(reference == lobeInputs(base, 31.0f));
    const std::vector<std::pair<const char*, void (*)(Preset&)>> relevant{
        {"diffuse", [](Preset& p) { p.material.diffuse.g = 0.5f; }},
        {"specular", [](Preset& p) { p.material.specular.b = 0.5f; }},
        {"shininess", [](Preset& p) { p.material.shininess = 31.0f; }},
        {"brdf", [](Preset& p) { p.brdf = BrdfModel::BlinnPhong; }},
        {"distribution", [](Preset& p) { p.cookTorrance.distribution = Distribution::Gaussian; }},
        {"roughness", [](Preset& p) { p.cookTorrance.roughness = 0.31f; }},
        {"fresnel", [](Preset& p) { p.cookTorrance.fresnel = FresnelMode::Full; }},
        {"ior", [](Preset& p) { p.cookTorrance.ior = 1.6f; }},
        {"geometry", [](Preset& p) { p.cookTorrance.geometry = false; }},
        {"terms.diffuse", [](Preset& p) { p.terms.diffuse = false; }},
        {"terms.specular", [](Preset& p) { p.terms.specular = false; }},
    };
    for (const auto& [what, edit] : relevant) {
        Preset p = base;
        edit(p);
        EXPECT_FALSE(lobeInputs(p, 30.0f) == reference) << what;
        // And the samples through the inputs are the samples of the preset.
        std::vector<PlotSample> direct = reflectedIntensity(p, 30.0f), viaInputs = reflectedIntensity(lobeInputs(p, 30.0f));
        for (std::size_t i = 0; i < direct.size(); ++i) {
            EXPECT_EQ(direct[i].total, viaInputs[i].total) << what;
        }
    }
    const std::vector<std::pair<const char*, void (*)(Preset&)>> irrelevant{
        {"camera", [](Preset& p) { p.camera.eye = {1, 2, 3}; }},
        {"lights", [](Preset& p) { p.lights[0].position = {0, 5, 0}; }},
        {"shading", [](Preset& p) { p.shading = Shading::Gouraud; }},
        {"model", [](Preset& p) { p.model.scale = {2, 1, 1}; }},
        {"plot incident angle (the caller passes the angle)", [](Preset& p) { p.plotIncidentDeg = 10.0f; }},
        {"background", [](Preset& p) { p.background = {1, 1, 1}; }},
    };
    for (const auto& [what, edit] : irrelevant) {
        Preset p = base;
        edit(p);
        EXPECT_TRUE(lobeInputs(p, 30.0f) == reference) << what;
    }
}

TEST(Plot, CsvHasTheDocumentedHeaderAndOneRowPerDegree) {
    std::string csv = plotCsv(reflectedIntensity(Preset{}, 45.0f));
    EXPECT_EQ(csv.rfind("theta_out_deg,diffuse,specular,total\n-90,", 0), 0u) << csv.substr(0, 80);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 182);
}

} // namespace
} // namespace lab

namespace lab {
namespace {

// The geometry the GUI draws: each lobe point is radius × (sin θo, cos θo), the radius being
// the sampled intensity (from the lighting functions) over the outer circle's.
TEST(PlotGeometry, LobePointsFollowTheLightingFunctions) {
    Preset p;
    p.brdf = BrdfModel::BlinnPhong;
    p.material.shininess = 20.0f;
    std::vector<PlotSample> s = reflectedIntensity(p, 30.0f);
    float maxI = maxTotal({s});
    std::vector<glm::vec2> points = lobePoints(s, PlotComponent::Specular, maxI, RadialScale::Linear);
    ASSERT_EQ(points.size(), s.size());
    glsl::Brdf b = packSurfaceUniforms(p).brdf;
    float ti = glm::radians(30.0f);
    for (int deg : {-45, 0, 10, 30, 60, 90}) {
        float to = glm::radians(float(deg));
        float S = glsl::specularFactor(glm::vec3(0, 1, 0), glm::vec3(-std::sin(ti), std::cos(ti), 0),
                                       glm::vec3(std::sin(to), std::cos(to), 0), p.material.shininess, b);
        float r = luminance(p.material.specular * S) / maxI;
        const glm::vec2& pt = points[std::size_t(deg + 90)];
        EXPECT_NEAR(pt.x, r * std::sin(to), 1e-6f) << deg;
        EXPECT_NEAR(pt.y, r * std::cos(to), 1e-6f) << deg;
    }
}

TEST(PlotGeometry, TheTotalLobeReachesTheOuterCircle) {
    std::vector<PlotSample> s = reflectedIntensity(Preset{}, 45.0f);
    std::vector<glm::vec2> total = lobePoints(s, PlotComponent::Total, maxTotal({s}), RadialScale::Linear);
    float longest = 0.0f;
    for (const glm::vec2& pt : total) {
        longest = std::max(longest, glm::length(pt));
    }
    EXPECT_NEAR(longest, 1.0f, 1e-6f);
}

TEST(PlotGeometry, LogarithmicRadius) {
    EXPECT_FLOAT_EQ(plotRadius(1.0f, 1.0f, RadialScale::Log), 1.0f);
    EXPECT_NEAR(plotRadius(0.1f, 1.0f, RadialScale::Log), 1.0f - 1.0f / kLogDecades, 1e-6f);
    EXPECT_NEAR(plotRadius(0.001f, 1.0f, RadialScale::Log), 0.0f, 1e-6f);
    EXPECT_EQ(plotRadius(1e-6f, 1.0f, RadialScale::Log), 0.0f); // below the shown decades
    EXPECT_EQ(plotRadius(0.0f, 1.0f, RadialScale::Log), 0.0f);
    EXPECT_FLOAT_EQ(plotRadius(0.25f, 1.0f, RadialScale::Linear), 0.25f);
}

TEST(PlotGeometry, AttenuationCurveUsesTheModel) {
    std::vector<glm::vec2> c = attenuationCurve(glm::vec3(0, 0, 1), 4.0f, 5);
    ASSERT_EQ(c.size(), 5u);
    EXPECT_FLOAT_EQ(c[0].y, 1.0f);        // d = 0: clamped
    EXPECT_FLOAT_EQ(c[2].y, 0.25f);       // d = 2: 1/d^2
    EXPECT_FLOAT_EQ(c[4].x, 4.0f);
    EXPECT_FLOAT_EQ(c[4].y, 1.0f / 16.0f);
}

} // namespace
} // namespace lab

#include "core/io/number_format.h"

namespace lab {
namespace {

TEST(NumberFormat, ShortestTextThatRoundTrips) {
    EXPECT_EQ(shortestFloat(0.8f), "0.8");
    EXPECT_EQ(shortestFloat(32.0f), "32");
    EXPECT_EQ(shortestFloat(-90.0f), "-90");
    EXPECT_EQ(shortestFloat(1500.0f), "1500");
    EXPECT_EQ(shortestFloat(150.5f), "150.5");
    EXPECT_EQ(shortestFloat(-0.0f), "-0");
    EXPECT_EQ(shortestFloat(-0.25f), "-0.25");
    EXPECT_EQ(shortestFloat(1e-7f), "1e-07");
    for (float f : {0.1f, 1.0f / 3.0f, 123456.789f, 3.4028235e38f, 1.17549435e-38f, 0.123456f}) {
        EXPECT_EQ(std::strtof(shortestFloat(f).c_str(), nullptr), f) << shortestFloat(f);
    }
}

} // namespace
} // namespace lab
