// probes.h — single-pixel probes that compare the shaders with the C++ face of the lighting model
// (gpu_parity_test.cpp, finite_test.cpp, factor_view_test.cpp), and the BRDFs and lights they draw.
//
// One probe per pixel centre of a size × size view: an eye-space point on that pixel's ray at a
// depth the caller draws, with a random normal, mostly towards the viewer, some grazing or turned
// away. Each probe is moved into object space so that the real shaders, uniforms and matrices
// draw it (Renderer::drawPoints), and its C++ colour is computed from the same object-space data
// through the same matrices.
#pragma once

#include "core/scene/transforms.h"
#include "core/io/image.h"
#include "core/lighting/lighting.h"
#include "core/scene/mesh.h"
#include "core/scene/preset.h"
#include "render/offscreen.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <functional>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace lab::test {

// One BRDF and shading mode the probe tests run.
struct Variant {
    const char* name;
    BrdfModel brdf;
    Distribution distribution;
    FresnelMode fresnel;
    bool geometry;
    Shading shading = Shading::Phong; // the preset's default
};

inline void PrintTo(const Variant& v, std::ostream* os) { *os << v.name << "/" << toString(v.shading); }

// The BRDFs: Phong, Blinn-Phong, and Cook-Torrance with each distribution and Fresnel, the geometry
// term on and off.
inline constexpr Variant kPhong{"phong", BrdfModel::Phong, Distribution::Beckmann, FresnelMode::Schlick, true};
inline constexpr Variant kBlinnPhong{"blinnphong", BrdfModel::BlinnPhong, Distribution::Beckmann, FresnelMode::Schlick, true};
inline constexpr Variant kCtBeckmannSchlick{"ct_beckmann_schlick", BrdfModel::CookTorrance, Distribution::Beckmann,
                                            FresnelMode::Schlick, true};
inline constexpr Variant kCtBeckmannFull{"ct_beckmann_full", BrdfModel::CookTorrance, Distribution::Beckmann, FresnelMode::Full,
                                         true};
inline constexpr Variant kCtGaussianFull{"ct_gaussian_full", BrdfModel::CookTorrance, Distribution::Gaussian, FresnelMode::Full,
                                         true};
inline constexpr Variant kCtGgxSchlickNoGeometry{"ct_ggx_schlick_nogeometry", BrdfModel::CookTorrance, Distribution::Ggx,
                                                 FresnelMode::Schlick, false};
inline constexpr Variant kCtGgxFull{"ct_ggx_full", BrdfModel::CookTorrance, Distribution::Ggx, FresnelMode::Full, true};

// Five of them (Phong, Blinn-Phong and three Cook-Torrance: each distribution and Fresnel, the
// geometry term on and off) under each of `shadings`.
inline std::vector<Variant> brdfVariants(std::initializer_list<Shading> shadings) {
    std::vector<Variant> v;
    for (Shading s : shadings) {
        for (Variant b : {kPhong, kBlinnPhong, kCtBeckmannSchlick, kCtGaussianFull, kCtGgxSchlickNoGeometry}) {
            b.shading = s;
            v.push_back(b);
        }
    }
    return v;
}

// "phong_Gouraud": a test's name suffix.
template <typename Info> std::string variantName(const Info& info) {
    return std::string(info.param.name) + "_" + std::string(toString(info.param.shading));
}

// The probe scenes' lights. With no arguments, the three of finite_test's and gpu_parity_test's
// scene: a point light with attenuation and a little ambient, a spot light, a sun; white unless a
// test colours them.
inline LightDesc pointLight(glm::vec3 position = {2.0f, 3.0f, 2.0f}, glm::vec3 attenuation = {1.0f, 0.1f, 0.02f},
                            glm::vec3 ambient = glm::vec3(0.05f)) {
    LightDesc l;
    l.position = position;
    l.attenuation = attenuation;
    l.ambient = ambient;
    return l;
}

inline LightDesc spotLight(glm::vec3 position = {-1.0f, 3.0f, 3.0f}, glm::vec3 direction = {0.3f, -0.6f, -0.5f},
                           float exponent = 4.0f, float cutoffDeg = 35.0f) {
    LightDesc l;
    l.type = LightType::Spot;
    l.position = position;
    l.direction = direction;
    l.cutoffDeg = cutoffDeg;
    l.exponent = exponent;
    return l;
}

inline LightDesc sunLight(glm::vec3 direction = {-0.5f, -1.0f, -0.3f}) {
    LightDesc l;
    l.type = LightType::Directional;
    l.direction = direction;
    return l;
}

struct Probes {
    std::vector<FlatVertex> vertices; // object space, as drawPoints takes them
    std::vector<glm::vec3> expected;  // the C++ colour of each, row by row from the bottom
};

// `eyeDepth` gives each probe's distance from the eye along -z; `random` the normals.
inline Probes makeProbes(const Preset& preset, int size, std::mt19937& random, const std::function<float()>& eyeDepth) {
    const Transforms t = computeTransforms(preset, 1.0f);
    const ShadingInputs inputs = packShading(preset, t.view);
    const glm::mat4 toObject = glm::inverse(t.modelView);
    const glm::mat3 normalToObject = glm::inverse(t.normalMatrix);
    const float tanHalf = std::tan(glm::radians(preset.camera.fovyDeg) / 2.0f);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    Probes probes;
    for (int py = 0; py < size; ++py) {
        for (int px = 0; px < size; ++px) {
            float z = -eyeDepth();
            glm::vec2 ndc(2.0f * (px + 0.5f) / size - 1.0f, 2.0f * (py + 0.5f) / size - 1.0f);
            glm::vec3 eye(ndc.x * -z * tanHalf, ndc.y * -z * tanHalf, z);
            // Drawn one by one: the order of a call's arguments is unspecified (GCC takes the last
            // first, clang the first), and the probes must not depend on the compiler. Last first,
            // as the tests' thresholds were set with GCC.
            const float nz = unit(random), ny = unit(random), nx = unit(random);
            glm::vec3 N = glm::normalize(glm::vec3(nx, ny, nz) + 0.6f * glm::normalize(-eye));
            glm::vec3 position = glm::vec3(toObject * glm::vec4(eye, 1.0f));
            glm::vec3 normal = normalToObject * N;
            probes.vertices.push_back({position, normal, position});
            glm::vec3 p = glm::vec3(t.modelView * glm::vec4(position, 1.0f));
            probes.expected.push_back(shade(inputs, p, glm::normalize(t.normalMatrix * normal)));
        }
    }
    return probes;
}

// The probes drawn by `renderer` into a size × size framebuffer: the image, top row first (so
// probe (px, py) is at row size - 1 - py); an empty image when no framebuffer could be made.
inline Image drawProbes(Renderer& renderer, const Preset& preset, const Probes& probes, int size) {
    Framebuffer target(size, size);
    if (!target.complete()) {
        return {};
    }
    target.bind();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer.drawPoints(preset, probes.vertices, size, size);
    return target.readRgb();
}

} // namespace lab::test
