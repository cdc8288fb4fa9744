// finite_test.cpp — no accepted preset makes the lighting model's arithmetic leave the finite
// floats (issue 14): the model evaluated at the corners of every range in core/scene/limits.h.
//
// On the CPU, every term of every light (glsl::lightContribution, the function both faces run)
// and the shaded colour, at random points and normals and at the awkward ones (N.H = 1, N.L = 0,
// a grazing view, a surface point at the light), for every BRDF; and every sample of `lab plot`.
// On the GPU, the same corners rendered as probes and compared with the CPU, clamped as the
// screen clamps: a NaN or an infinity on either side shows as a probe that disagrees.
#include "gl_suite.h"
#include "probes.h"

#include "core/scene/transforms.h"
#include "core/lighting/lighting.h"
#include "core/plots/plot_data.h"
#include "core/scene/limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace lab {
namespace {

using namespace limits;

struct Corner {
    const char* name;
    std::function<void(Preset&)> apply;
};

void allLights(Preset& p, const std::function<void(LightDesc&)>& f) {
    for (LightDesc& l : p.lights) {
        f(l);
    }
}

// The corners: each pushes several ranges to an end at once.
const Corner kCorners[] = {
    {"smallest", [](Preset& p) {
         p.cookTorrance.roughness = kRoughness.min;
         p.cookTorrance.ior = kIor.min;
         p.material.shininess = kShininess.min;
         allLights(p, [](LightDesc& l) {
             l.direction = glm::normalize(l.direction) * kMinDirectionLength;
             l.exponent = kShininess.min;
             l.attenuation = {0.0f, 0.0f, kAttenuation.min};
         });
     }},
    {"largest", [](Preset& p) {
         p.cookTorrance.roughness = kRoughness.max;
         p.cookTorrance.ior = kIor.max;
         p.material.shininess = kShininess.max;
         p.material = {glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f), kShininess.max};
         p.ambientLight = glm::vec3(kAmbientLight.max);
         allLights(p, [](LightDesc& l) {
             l.ambient = l.diffuse = l.specular = glm::vec3(kLightColor.max);
             l.exponent = kSpotExponent.max;
             l.attenuation = glm::vec3(kAttenuation.max);
             l.direction *= kCoordinate.max / glm::length(l.direction);
         });
     }},
    {"sharpest-highlight-brightest-light", [](Preset& p) {
         p.cookTorrance.roughness = kRoughness.min;
         p.cookTorrance.ior = kIor.max;
         p.material.shininess = kShininess.max;
         allLights(p, [](LightDesc& l) {
             l.diffuse = l.specular = glm::vec3(kLightColor.max);
             l.attenuation = {0.0f, 0.0f, 0.0f};
         });
     }},
    {"farthest-lights-and-camera", [](Preset& p) {
         float m = kCoordinate.max;
         allLights(p, [m](LightDesc& l) {
             l.position = {m, -m, m};
             l.attenuation = {kAttenuation.min, kAttenuation.max, kAttenuation.max};
             l.cutoffDeg = kCutoffDeg.max;
         });
         p.camera.eye = {-m, m, m};
         p.camera.target = {m, -m, -m};
         p.camera.near = kNear.min;
         p.camera.far = kFar.max;
         p.model.translate = {m, -m, -m};
         p.model.scale = glm::vec3(m);
         p.model.rotateDeg = glm::vec3(kRotationDeg.max);
     }},
    {"tiniest-model-and-view", [](Preset& p) {
         p.model.scale = {kMinScale, -kMinScale, kCoordinate.max};
         p.camera.fovyDeg = kFovyDeg.min;
         p.camera.near = kNear.min;
         p.camera.far = kNear.min * 10.0f;
         p.camera.eye = p.camera.target + glm::vec3(0.0f, 0.0f, 2.0f * kMinDirectionLength);
         p.cookTorrance.roughness = kRoughness.min;
     }},
};

using test::Variant;

// Every BRDF once: the CPU's corners take the preset's shading, GpuCorners draws each with two.
// GGX with Schlick and no geometry term keeps the name "ct_ggx_schlick" in this test's names.
constexpr Variant named(Variant v, const char* name) {
    v.name = name;
    return v;
}

const Variant kVariants[] = {test::kPhong,
                             test::kBlinnPhong,
                             test::kCtBeckmannSchlick,
                             test::kCtBeckmannFull,
                             test::kCtGaussianFull,
                             named(test::kCtGgxSchlickNoGeometry, "ct_ggx_schlick"),
                             test::kCtGgxFull};

// A scene with one light of each type, every term on.
Preset basePreset(const Variant& v) {
    Preset p;
    p.brdf = v.brdf;
    p.cookTorrance.distribution = v.distribution;
    p.cookTorrance.fresnel = v.fresnel;
    p.cookTorrance.geometry = v.geometry;
    p.material.emissive = glm::vec3(0.05f);
    p.lights = {test::pointLight(), test::spotLight(), test::sunLight()};
    return p;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Every term of every light and the colour at eye-space point p with unit normal N; "" when all
// are finite, else what was not.
std::string nonFinite(const ShadingInputs& in, const glm::vec3& p, const glm::vec3& N) {
    glm::vec3 V = glm::dot(p, p) > 1e-30f ? glm::normalize(-p) : glm::vec3(0.0f, 0.0f, 1.0f);
    for (int i = 0; i < in.lightCount; ++i) {
        glsl::LightTerms c = glsl::lightContribution(in.material, in.brdf, in.terms, in.lights[i], p, N, V);
        if (!finite(c.L) || !std::isfinite(c.attenuation) || !std::isfinite(c.NoL) || !std::isfinite(c.specularFactor) ||
            !finite(c.ambient) || !finite(c.diffuse) || !finite(c.specular)) {
            return "light " + std::to_string(i) + ": L.x " + std::to_string(c.L.x) + ", Att " + std::to_string(c.attenuation) +
                   ", S " + std::to_string(c.specularFactor) + ", specular.r " + std::to_string(c.specular.r);
        }
    }
    glm::vec3 color = shade(in, p, N);
    return finite(color) ? "" : "the colour";
}

class Corners : public testing::TestWithParam<Variant> {};

TEST_P(Corners, EveryTermStaysFiniteOnTheCpu) {
    std::mt19937 random(99);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (const Corner& corner : kCorners) {
        Preset preset = basePreset(GetParam());
        corner.apply(preset);
        const Transforms t = computeTransforms(preset, 1.0f);
        const ShadingInputs in = packShading(preset, t.view);
        const float scale = std::max(1.0f, glm::length(glm::vec3(t.modelView[3])));
        std::vector<std::pair<glm::vec3, glm::vec3>> points; // (p, N) in eye space
        for (int k = 0; k < 3000; ++k) {
            // One by one, last first (as GCC evaluated the arguments): the points do not depend on
            // the compiler's order of a call's arguments.
            const float pz = unit(random), py = unit(random), px = unit(random);
            const float nz = unit(random), ny = unit(random), nx = unit(random);
            glm::vec3 p = glm::vec3(px, py, pz) * scale;
            glm::vec3 N = glm::normalize(glm::vec3(nx, ny, nz) + glm::vec3(1e-3f));
            points.emplace_back(p, N);
        }
        for (int i = 0; i < in.lightCount; ++i) {
            const glsl::Light& l = in.lights[i];
            glm::vec3 p(0.3f, -0.2f, -2.0f);
            glm::vec3 V = glm::normalize(-p);
            glm::vec3 L = l.type == glsl::LIGHT_DIRECTIONAL ? -l.direction : glm::normalize(l.position - p);
            glm::vec3 H = glm::normalize(L + V);
            points.emplace_back(p, H);                                            // N.H = 1
            points.emplace_back(p, glm::normalize(glm::cross(L, V) + 1e-9f * V)); // N.L = 0, N.V = 0
            points.emplace_back(p, glm::normalize(V + 1e-7f * L));                // along V
            points.emplace_back(l.position, V);                                   // at the light
            points.emplace_back(glm::vec3(0.0f), V);                              // at the eye
        }
        for (const auto& [p, N] : points) {
            std::string bad = nonFinite(in, p, N);
            ASSERT_EQ(bad, "") << corner.name << " at p (" << p.x << ", " << p.y << ", " << p.z << "), N (" << N.x << ", "
                               << N.y << ", " << N.z << ")";
        }
        // `lab plot`'s samples, at every incident angle it accepts.
        for (float incident : {kPlotIncidentDeg.min, -45.0f, 0.0f, 1e-3f, 60.0f, kPlotIncidentDeg.max}) {
            for (const PlotSample& s : reflectedIntensity(preset, incident)) {
                ASSERT_TRUE(std::isfinite(s.diffuse) && std::isfinite(s.specular) && std::isfinite(s.total))
                    << corner.name << ", incident " << incident << ", at " << s.thetaOutDeg;
            }
        }
    }
}

std::string variantName(const testing::TestParamInfo<Variant>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(EveryBrdf, Corners, testing::ValuesIn(kVariants), variantName);

// The GPU at the same corners: probes through the real shaders (per pixel and per vertex),
// against the CPU clamped to [0, 1] as the screen is. Where a highlight is a thousandth of a
// radian wide (roughness 0.001, shininess 10^6) the two faces' last-bit differences in N.H can
// put a probe on either side of its edge, so a few probes may differ; a NaN or an infinity on
// one side would show on a whole light's worth of probes.
class GpuCorners : public GlSuite<> {};

TEST_F(GpuCorners, TheShadersAgreeWithTheCpu) {
    ASSERT_NE(renderer_, nullptr);
    constexpr int kSize = 32;
    int lit = 0, probed = 0; // the comparison must be of lit probes, not black with black
    for (const Variant& v : kVariants) {
        for (const Corner& corner : kCorners) {
            for (Shading shading : {Shading::Phong, Shading::Gouraud}) {
                Preset preset = basePreset(v);
                corner.apply(preset);
                preset.shading = shading;
                const float zNear = preset.camera.near, zFar = preset.camera.far;
                std::mt19937 random(7);
                std::uniform_real_distribution<float> depth(0.05f, 0.55f);
                test::Probes probes =
                    test::makeProbes(preset, kSize, random, [&] { return zNear + (zFar - zNear) * depth(random); });
                for (glm::vec3& cpu : probes.expected) {
                    ASSERT_TRUE(finite(cpu)) << v.name << ", " << corner.name;
                    cpu = glm::clamp(cpu, 0.0f, 1.0f);
                }
                const std::vector<glm::vec3>& expected = probes.expected;
                Image image = test::drawProbes(*renderer_, preset, probes, kSize);
                ASSERT_EQ(image.width, kSize) << "no framebuffer";
                int differing = 0;
                for (int py = 0; py < kSize; ++py) {
                    for (int px = 0; px < kSize; ++px) {
                        const glm::vec3& cpu = expected[std::size_t(py * kSize + px)];
                        const std::uint8_t* gpu = &image.rgb[std::size_t(((kSize - 1 - py) * kSize + px) * 3)];
                        bool differs = false;
                        for (int k = 0; k < 3; ++k) {
                            differs |= std::abs(float(gpu[k]) - cpu[k] * 255.0f) > 2.0f;
                        }
                        differing += differs;
                        lit += cpu.r > 0.05f;
                        ++probed;
                    }
                }
                EXPECT_LE(differing, kSize * kSize / 50) << v.name << ", " << corner.name << ", " << toString(shading)
                                                         << ": probes that differ from the CPU";
            }
        }
    }
    EXPECT_GT(lit, probed / 4) << "lit probes";
}

} // namespace
} // namespace lab
