// gpu_parity_test.cpp — the GLSL face of the lighting model equals the C++ face.
//
// Renders single-pixel probes through the real shaders (lit.vert/lit.frag, real uniforms, real
// model-view and normal matrices) with headless EGL, and compares every probe with the C++
// evaluation of the same point and normal (lab::shade). Each probe's object-space position is
// chosen so that it projects onto the centre of its own pixel. Per-vertex shading (flat,
// Gouraud) evaluates in lit.vert, Phong shading in lit.frag: both paths are covered for every BRDF.
#include "core/lighting/lighting.h"
#include "gl_suite.h"
#include "platform/headless_gl.h"
#include "probes.h"
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <random>

namespace lab {
namespace {

constexpr int kSize = 48; // 48 x 48 probes, one per pixel

using test::Variant;

Preset probePreset(const Variant& v) {
    Preset p;
    p.brdf = v.brdf;
    p.shading = v.shading;
    p.cookTorrance = {v.distribution, 0.35f, v.fresnel, 1.6f, v.geometry};
    p.model.scale = {1.2f, 0.8f, 1.0f};
    p.model.rotateDeg = {10.0f, 20.0f, 30.0f};
    p.model.translate = {0.2f, -0.1f, 0.3f};
    p.camera.eye = {1.0f, 2.0f, 5.0f};
    p.material = {{0.05f, 0.02f, 0.0f}, {0.3f, 0.3f, 0.4f}, {0.5f, 0.4f, 0.3f}, {0.6f, 0.6f, 0.5f}, 24.0f};
    p.ambientLight = {0.1f, 0.1f, 0.1f};
    LightDesc spot = test::spotLight();
    spot.diffuse = {0.6f, 0.6f, 0.9f};
    spot.specular = {0.5f, 0.5f, 0.5f};
    LightDesc sun = test::sunLight();
    sun.diffuse = {0.3f, 0.25f, 0.2f};
    sun.specular = {0.4f, 0.4f, 0.4f};
    LightDesc off; // disabled lights must not count on either side
    off.enabled = false;
    off.diffuse = glm::vec3(10.0f);
    p.lights = {test::pointLight(), off, spot, sun};
    return p;
}

class GpuParity : public GlSuite<testing::TestWithParam<Variant>> {};


TEST_P(GpuParity, ShadersMatchTheCpuWithinOneLevel) {
    ASSERT_NE(renderer_, nullptr);
    const Preset preset = probePreset(GetParam());
    std::mt19937 random(1234);
    std::uniform_real_distribution<float> depth(2.5f, 6.5f);
    const test::Probes probes = test::makeProbes(preset, kSize, random, [&] { return depth(random); });
    const std::vector<glm::vec3>& expected = probes.expected;
    Image image = test::drawProbes(*renderer_, preset, probes, kSize); // top row first
    ASSERT_EQ(image.width, kSize) << "no framebuffer";

    int lit = 0, worstLevel = 0;
    float worst = 0.0f;
    for (int py = 0; py < kSize; ++py) {
        for (int px = 0; px < kSize; ++px) {
            const glm::vec3& cpu = expected[std::size_t(py * kSize + px)];
            const std::uint8_t* gpu = &image.rgb[std::size_t(((kSize - 1 - py) * kSize + px) * 3)];
            for (int k = 0; k < 3; ++k) {
                float d = std::abs(float(gpu[k]) - cpu[k] * 255.0f);
                if (d > worst) {
                    worst = d;
                    worstLevel = gpu[k];
                }
                ASSERT_LE(d, 1.0f) << "probe (" << px << ", " << py << ") channel " << k << ": GPU " << int(gpu[k])
                                   << ", CPU " << cpu[k] * 255.0f;
            }
            lit += cpu.r > 0.1f;
        }
    }
    // The probes must exercise the lighting, not compare black with black.
    EXPECT_GT(lit, kSize * kSize / 2);
    RecordProperty("worst_difference_levels", std::to_string(worst));
    (void)worstLevel;
}

INSTANTIATE_TEST_SUITE_P(EveryBrdfAndShading, GpuParity,
                         testing::ValuesIn(test::brdfVariants({Shading::Flat, Shading::Gouraud, Shading::Phong})),
                         test::variantName<testing::TestParamInfo<Variant>>);

TEST(Shaders, CompileErrorsNameTheFileAndLine) {
    HeadlessGl gl;
    std::string error;
    ASSERT_TRUE(gl.create(error)) << error;
    Renderer renderer;
    Diagnostics d;
    ASSERT_TRUE(renderer.init(d)) << toString(d);
    StageSources broken = renderer.stageSources();
    broken.fragment = "out vec4 o_color;\nvoid main() {\n    o_color = vec4(undefinedThing, 1.0);\n}\n";
    EXPECT_FALSE(renderer.setStageSources(broken, d));
    ASSERT_FALSE(d.empty());
    bool named = false;
    for (const Diagnostic& x : d) {
        named |= x.message.find("lit.frag:3") != std::string::npos && x.message.find("undefinedThing") != std::string::npos;
    }
    EXPECT_TRUE(named) << toString(d);
    // The previous programs keep running.
    EXPECT_EQ(renderer.stageSources().fragment, builtinStageSources().fragment);
}

} // namespace
} // namespace lab
