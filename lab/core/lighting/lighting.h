// lighting.h — the C++ face of the lighting model, and the scene transforms.
//
// The equations are not written here: lab::glsl is shaders/lighting_api.glsl and
// shaders/lighting.glsl compiled as C++ with GLM, so the plots, `lab plot` and the tests run the
// very code the GPU runs. This header adds what both faces need from a Preset: the matrices
// (model, view, projection, normal matrix) and the packing of material, BRDF and lights into the
// structs the shaders take as uniforms. The renderer uploads exactly what packShading returns.
#pragma once

#include "core/scene/preset.h"

#include <glm/glm.hpp>

namespace lab {

namespace glsl {
using namespace glm;
#include "lighting_api.glsl"
} // namespace glsl

// Everything lit.vert/lit.frag read as uniforms, minus the matrices.
struct ShadingInputs {
    glsl::Material material;
    glsl::Brdf brdf;
    glsl::Terms terms;
    glm::vec3 ambientLight;
    glsl::Light lights[glsl::MAX_LIGHTS];
    int lightCount = 0; // enabled lights only, in preset order
};

struct Transforms {
    glm::mat4 model;
    glm::mat4 view;
    glm::mat4 projection;
    glm::mat4 modelView;
    glm::mat3 normalMatrix; // per the preset's normal_matrix mode
};

// Model = T·Rz·Ry·Rx·S; view = lookAt; projection = perspective(fovy, aspect, near, far).
glm::mat4 modelMatrix(const Model& model);
Transforms computeTransforms(const Preset& preset, float aspect);

// Material, BRDF, terms and the enabled lights moved into eye space with `view`.
ShadingInputs packShading(const Preset& preset, const glm::mat4& view);
glsl::Brdf packBrdf(const Preset& preset);

// glsl::shade with the packed inputs: the colour at eye-space point p with unit normal N.
glm::vec3 shade(const ShadingInputs& in, const glm::vec3& p, const glm::vec3& N);

// Rec. 709 luminance.
inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

} // namespace lab
