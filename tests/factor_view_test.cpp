// factor_view_test.cpp — the factor views (issue 26) against the C++ face of the lighting model:
// what the shaders write for each factor is equationFactor() of lighting.glsl, within one level in
// grey; the factors compose to the specular term; gouraud-error is the difference of the Phong- and
// Gouraud-shaded renders; the automatic range spans the values on the model.
#include "core/scene/transforms.h"
#include "core/lighting/lighting.h"
#include "core/scene/view_mode.h"
#include "gl_suite.h"
#include "probes.h"
#include "render/offscreen.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace lab {
namespace {

constexpr int kSize = 24; // probes per side

// One Cook-Torrance or Phong preset with a spot light first (attenuation and a cone) and a point
// light second; `oneLight` keeps the spot alone.
Preset factorPreset(BrdfModel brdf, Distribution d, FresnelMode f, bool geometry, bool oneLight = false) {
    Preset p;
    p.brdf = brdf;
    p.cookTorrance.distribution = d;
    p.cookTorrance.fresnel = f;
    p.cookTorrance.geometry = geometry;
    p.cookTorrance.roughness = 0.35f;
    p.cookTorrance.ior = 1.8f;
    p.material.shininess = 24.0f;
    p.material.specular = {0.7f, 0.5f, 0.3f};
    p.camera.eye = {0.0f, 0.0f, 5.0f};
    LightDesc spot = test::spotLight({0.5f, 2.5f, 3.0f}, glm::normalize(glm::vec3(-0.1f, -0.6f, -1.0f)), 3.0f);
    spot.attenuation = {0.6f, 0.15f, 0.04f};
    spot.specular = {0.9f, 0.8f, 1.0f};
    LightDesc point = test::pointLight({-3.0f, 1.0f, 2.0f}, {1.0f, 0.1f, 0.0f}, glm::vec3(0.0f)); // no ambient
    p.lights = oneLight ? std::vector<LightDesc>{spot} : std::vector<LightDesc>{spot, point};
    return p;
}

struct EyeProbe {
    glm::vec3 p, N;
};

// The probes' eye-space points and normals, as the shaders see them.
std::vector<EyeProbe> eyeProbes(const Preset& preset, const test::Probes& probes) {
    const Transforms t = computeTransforms(preset, 1.0f);
    std::vector<EyeProbe> out;
    for (const FlatVertex& v : probes.vertices) {
        out.push_back({glm::vec3(t.modelView * glm::vec4(v.position, 1.0f)), glm::normalize(t.normalMatrix * v.faceNormal)});
    }
    return out;
}

test::Probes makeFactorProbes(const Preset& preset) {
    std::mt19937 random(4321);
    std::uniform_real_distribution<float> depth(2.5f, 6.0f);
    return test::makeProbes(preset, kSize, random, [&] { return depth(random); });
}

// The probes drawn with `options`, read back as RGBA bytes (GL's bottom row first: probe i at i).
std::vector<std::uint8_t> drawRgba(Renderer& renderer, const Preset& preset, const test::Probes& probes,
                                   const DrawOptions& options, bool bits) {
    Framebuffer target(kSize, kSize);
    target.bind();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer.drawPoints(preset, probes.vertices, kSize, kSize, options, bits);
    std::vector<std::uint8_t> rgba(std::size_t(kSize) * kSize * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    return rgba;
}

// The values the shaders computed, from their float bits.
std::vector<float> drawValues(Renderer& renderer, const Preset& preset, const test::Probes& probes, ViewMode view,
                              int light = 0) {
    DrawOptions o;
    o.view = view;
    o.light = light;
    std::vector<std::uint8_t> rgba = drawRgba(renderer, preset, probes, o, true);
    std::vector<float> values;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        values.push_back(std::bit_cast<float>(std::uint32_t(rgba[i]) | std::uint32_t(rgba[i + 1]) << 8 |
                                              std::uint32_t(rgba[i + 2]) << 16 | std::uint32_t(rgba[i + 3]) << 24));
    }
    return values;
}

float cpuFactor(const Preset& preset, ViewMode view, int light, const EyeProbe& e) {
    const Transforms t = computeTransforms(preset, 1.0f);
    const ShadingInputs in = packShading(preset, t.view);
    return glsl::equationFactor(factorIndex(view), in.brdf, in.lights[packedLightIndex(preset, light)], e.p, e.N,
                                glsl::viewVector(e.p));
}

using test::Variant;

class FactorViews : public GlSuite<testing::TestWithParam<Variant>> {};

// Every factor that applies, for both lights: grey over [min, max] of the CPU's values is the
// CPU's factor within one level, at every probe.
TEST_P(FactorViews, GreyIsTheCpuFactorWithinOneLevel) {
    ASSERT_NE(renderer_, nullptr);
    const Variant& v = GetParam();
    Preset preset = factorPreset(v.brdf, v.distribution, v.fresnel, v.geometry);
    preset.shading = v.shading;
    const test::Probes probes = makeFactorProbes(preset);
    const std::vector<EyeProbe> eye = eyeProbes(preset, probes);
    int checked = 0, varied = 0;
    for (ViewMode view : kViewModes) {
        for (int light : {0, 1}) {
            if (!isFactor(view) || !notApplicable(view, preset, light).empty()) {
                continue;
            }
            SCOPED_TRACE(std::string(viewName(view)) + " light " + std::to_string(light + 1));
            std::vector<float> cpu;
            for (const EyeProbe& e : eye) {
                cpu.push_back(cpuFactor(preset, view, light, e));
            }
            const float lo = *std::min_element(cpu.begin(), cpu.end()), hi = *std::max_element(cpu.begin(), cpu.end());
            ValueRange range = autoRange(lo, hi);
            DrawOptions o{view, light, ValuePalette::Grey, range};
            std::vector<std::uint8_t> rgba = drawRgba(*renderer_, preset, probes, o, false);
            int distinct = 0, last = -1;
            for (std::size_t i = 0; i < cpu.size(); ++i) {
                float expected = 255.0f * rangePosition(cpu[i], range);
                ASSERT_LE(std::abs(float(rgba[i * 4]) - expected), 1.0f)
                    << "probe " << i << ": GPU " << int(rgba[i * 4]) << ", CPU " << expected << " (value " << cpu[i] << ")";
                ASSERT_EQ(rgba[i * 4], rgba[i * 4 + 1]);
                ASSERT_EQ(rgba[i * 4], rgba[i * 4 + 2]);
                distinct += rgba[i * 4] != last;
                last = rgba[i * 4];
            }
            if (hi - lo > 0.01f) { // (a point light's spot factor is 1 throughout; G is 1 when switched off)
                EXPECT_GT(distinct, 10) << "the probes must spread over the range, not compare one grey";
                ++varied;
            }
            ++checked;
        }
    }
    // (a point light has no spot factor to view: core/scene/view_mode.h notApplicable)
    EXPECT_GE(checked, v.brdf == BrdfModel::CookTorrance ? 15 : 11);
    EXPECT_GE(varied, checked - (v.geometry ? 1 : 3)); // G where it is all but 1
}

// With one light and N.L > 0, the views compose: D F G / denominator * Ks Is * attenuation * spot is
// the specular term (Phong: R.V^n * Ks Is * attenuation * spot), each factor as the GPU wrote it.
TEST_P(FactorViews, TheFactorsComposeToTheSpecularTerm) {
    ASSERT_NE(renderer_, nullptr);
    const Variant& v = GetParam();
    Preset preset = factorPreset(v.brdf, v.distribution, v.fresnel, v.geometry, true);
    preset.shading = Shading::Phong; // per pixel: each probe's own point and normal
    const test::Probes probes = makeFactorProbes(preset);
    const std::vector<EyeProbe> eye = eyeProbes(preset, probes);
    auto values = [&](ViewMode m) { return drawValues(*renderer_, preset, probes, m); };
    std::vector<float> att = values(ViewMode::Attenuation), spot = values(ViewMode::Spot), nol = values(ViewMode::NdotL);
    std::vector<float> lobe(att.size());
    if (v.brdf == BrdfModel::CookTorrance) {
        std::vector<float> d = values(ViewMode::D), f = values(ViewMode::F), g = values(ViewMode::G),
                           den = values(ViewMode::Denominator);
        for (std::size_t i = 0; i < lobe.size(); ++i) {
            lobe[i] = d[i] * f[i] * g[i] / den[i];
        }
    } else {
        std::vector<float> rv = values(v.brdf == BrdfModel::Phong ? ViewMode::RdotV : ViewMode::NdotH);
        for (std::size_t i = 0; i < lobe.size(); ++i) {
            lobe[i] = std::pow(rv[i], preset.material.shininess);
        }
    }
    const Transforms t = computeTransforms(preset, 1.0f);
    const ShadingInputs in = packShading(preset, t.view);
    DrawOptions specular;
    specular.view = ViewMode::Specular;
    std::vector<std::uint8_t> specularView = drawRgba(*renderer_, preset, probes, specular, false);
    int lit = 0;
    for (std::size_t i = 0; i < eye.size(); ++i) {
        if (!(nol[i] > 1e-3f)) {
            continue; // S is 0 where N.L <= 0
        }
        glsl::LightTerms terms = glsl::lightContribution(in.material, in.brdf, in.terms, in.lights[0], eye[i].p, eye[i].N,
                                                         glsl::viewVector(eye[i].p));
        glm::vec3 composed = lobe[i] * in.material.specular * in.lights[0].specular * att[i] * spot[i];
        for (int k = 0; k < 3; ++k) {
            ASSERT_NEAR(composed[k], terms.specular[k], 2e-4f * std::max(1.0f, terms.specular[k])) << "probe " << i;
            if (composed[k] < 1.0f) { // before the final clamp: the specular view's own pixel
                ASSERT_LE(std::abs(255.0f * composed[k] - float(specularView[i * 4 + std::size_t(k)])), 1.0f) << "probe " << i;
            }
        }
        lit += composed.r > 1e-4f;
    }
    EXPECT_GT(lit, 50) << "the probes must see the lobe, not compare zeros";
}

INSTANTIATE_TEST_SUITE_P(EveryBrdf, FactorViews, testing::ValuesIn(test::brdfVariants({Shading::Gouraud, Shading::Phong})),
                         test::variantName<testing::TestParamInfo<Variant>>);

class ViewRenders : public GlSuite<testing::Test, OffscreenRenderer> {};

Image renderAs(OffscreenRenderer& r, const LoadedPreset& preset, const ViewportDraw& view, int size = 160) {
    Diagnostics d;
    std::optional<Rendered> out = r.renderView(preset, size, size, view, d);
    EXPECT_TRUE(out) << toString(d);
    return out ? out->image : Image{};
}

// gouraud-error in grey over [0, 1] is, pixel by pixel, the largest channel difference of the
// preset rendered with Phong shading and with Gouraud shading (within the two renders' rounding).
TEST_F(ViewRenders, GouraudErrorIsTheDifferenceOfThePhongAndGouraudRenders) {
    Diagnostics problems;
    std::optional<LoadedPreset> loaded =
        loadPreset(std::filesystem::path(LAB_SOURCE_DIR) / "presets" / "10-coarse-gouraud.json", problems);
    ASSERT_TRUE(loaded) << toString(problems);
    const LoadedPreset& coarse = *loaded;
    LoadedPreset phong = coarse, gouraud = coarse;
    phong.preset.shading = Shading::Phong;
    gouraud.preset.shading = Shading::Gouraud;
    Image a = renderAs(*renderer_, phong, {}), b = renderAs(*renderer_, gouraud, {});
    ViewportDraw error;
    error.options = DrawOptions{ViewMode::GouraudError, 0, ValuePalette::Grey, ValueRange{0.0f, 1.0f}};
    Image e = renderAs(*renderer_, coarse, error);
    ASSERT_EQ(e.rgb.size(), a.rgb.size());
    int large = 0;
    for (std::size_t px = 0; px < a.rgb.size(); px += 3) {
        int d = 0;
        for (int k = 0; k < 3; ++k) {
            d = std::max(d, std::abs(int(a.rgb[px + k]) - int(b.rgb[px + k])));
        }
        ASSERT_LE(std::abs(int(e.rgb[px]) - d), 1) << "pixel " << px / 3;
        large += d > 40;
    }
    EXPECT_GT(large, 50) << "the coarse sphere's highlight must differ between the two";
}

// The automatic range is the smallest and largest value on the model: the distance from a point
// light at (0, 0, 3) to a unit sphere seen from (0, 0, 5) runs from 2 (the nearest point) to about
// 2.97 (the silhouette, where the view's tangent touches z = 0.2).
TEST_F(ViewRenders, TheAutomaticRangeSpansTheValuesOnTheModel) {
    LoadedPreset p;
    p.preset.camera.eye = {0.0f, 0.0f, 5.0f};
    p.preset.model.subdivisions = {128, 64};
    p.preset.lights[0].position = {0.0f, 0.0f, 3.0f};
    ViewportDraw view;
    view.options.view = ViewMode::Distance;
    view.automatic = true;
    Diagnostics d;
    std::optional<Rendered> r = renderer_->renderView(p, 300, 200, view, d);
    ASSERT_TRUE(r && r->range) << toString(d);
    EXPECT_NEAR(r->range->lo, 2.0f, 0.01f);
    EXPECT_NEAR(r->range->hi, std::sqrt(0.96f + 2.8f * 2.8f), 0.03f);
    // A constant shows as what it is: a directional light's attenuation, 1 everywhere, spans [0, 1].
    p.preset.lights[0].type = LightType::Directional;
    view.options.view = ViewMode::Attenuation;
    r = renderer_->renderView(p, 64, 64, view, d);
    ASSERT_TRUE(r && r->range);
    EXPECT_EQ(r->range->lo, 0.0f);
    EXPECT_EQ(r->range->hi, 1.0f);
    ASSERT_TRUE(r->range->constant); // and the legend says so
    EXPECT_EQ(*r->range->constant, 1.0f);
    EXPECT_EQ(r->range->spread, 0.0f);
}

// The background of a value view is black; the model's pixels are the palette's.
TEST_F(ViewRenders, AValueViewIsDrawnOnBlack) {
    LoadedPreset p;
    p.preset.background = {0.3f, 0.6f, 0.9f};
    ViewportDraw view;
    view.options.view = ViewMode::NdotL;
    view.automatic = true;
    Image image = renderAs(*renderer_, p, view, 64);
    ASSERT_FALSE(image.rgb.empty());
    EXPECT_EQ(image.rgb[0] + image.rgb[1] + image.rgb[2], 0); // a corner
    const std::uint8_t* centre = &image.rgb[(32 * 64 + 32) * 3];
    EXPECT_GT(centre[0] + centre[1] + centre[2], 0);
}

} // namespace
} // namespace lab
