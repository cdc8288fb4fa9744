// lighting.cpp — compiles shaders/lighting.glsl as C++, and packs a Preset for it.
#include "core/lighting/lighting.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lab {

namespace glsl {
#include "lighting.glsl"
} // namespace glsl

glm::mat4 modelMatrix(const Model& model) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), model.translate);
    m = glm::rotate(m, glm::radians(model.rotateDeg.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(model.rotateDeg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(model.rotateDeg.x), glm::vec3(1, 0, 0));
    return glm::scale(m, model.scale);
}

Transforms computeTransforms(const Preset& preset, float aspect) {
    Transforms t;
    t.model = modelMatrix(preset.model);
    t.view = glm::lookAt(preset.camera.eye, preset.camera.target, preset.camera.up);
    t.projection = glm::perspective(glm::radians(preset.camera.fovyDeg), aspect, preset.camera.near, preset.camera.far);
    t.modelView = t.view * t.model;
    glm::mat3 mv(t.modelView);
    // The correct normal matrix is the inverse-transpose; the model-view matrix itself is the
    // classic mistake, visible as soon as the scale is not uniform. Both are renormalized in
    // the shader.
    t.normalMatrix = preset.normalMatrix == NormalMatrixMode::InverseTranspose ? glm::transpose(glm::inverse(mv)) : mv;
    return t;
}

glsl::Brdf packBrdf(const Preset& preset) {
    glsl::Brdf b;
    b.model = static_cast<int>(preset.brdf);
    b.distribution = static_cast<int>(preset.cookTorrance.distribution);
    b.fresnel = static_cast<int>(preset.cookTorrance.fresnel);
    b.geometry = preset.cookTorrance.geometry;
    b.roughness = preset.cookTorrance.roughness;
    b.ior = preset.cookTorrance.ior;
    return b;
}

ShadingInputs packShading(const Preset& preset, const glm::mat4& view) {
    static_assert(static_cast<int>(BrdfModel::CookTorrance) == glsl::BRDF_COOK_TORRANCE);
    static_assert(static_cast<int>(BrdfModel::BlinnPhong) == glsl::BRDF_BLINN_PHONG);
    static_assert(static_cast<int>(Distribution::Ggx) == glsl::DISTRIBUTION_GGX);
    static_assert(static_cast<int>(Distribution::Gaussian) == glsl::DISTRIBUTION_GAUSSIAN);
    static_assert(static_cast<int>(FresnelMode::Full) == glsl::FRESNEL_FULL);
    static_assert(static_cast<int>(LightType::Spot) == glsl::LIGHT_SPOT);
    static_assert(static_cast<int>(LightType::Directional) == glsl::LIGHT_DIRECTIONAL);
    static_assert(kMaxLights == glsl::MAX_LIGHTS);

    ShadingInputs in;
    in.material.emissive = preset.material.emissive;
    in.material.ambient = preset.material.ambient;
    in.material.diffuse = preset.material.diffuse;
    in.material.specular = preset.material.specular;
    in.material.shininess = preset.material.shininess;
    in.brdf = packBrdf(preset);
    in.terms.emissive = preset.terms.emissive;
    in.terms.ambient = preset.terms.ambient;
    in.terms.diffuse = preset.terms.diffuse;
    in.terms.specular = preset.terms.specular;
    in.ambientLight = preset.ambientLight;
    glm::mat3 rotate(view);
    for (const LightDesc& l : preset.lights) {
        if (!l.enabled || in.lightCount == glsl::MAX_LIGHTS) {
            continue;
        }
        glsl::Light& g = in.lights[in.lightCount++];
        g.type = static_cast<int>(l.type);
        g.position = glm::vec3(view * glm::vec4(l.position, 1.0f));
        g.direction = glm::normalize(rotate * l.direction);
        g.ambient = l.ambient;
        g.diffuse = l.diffuse;
        g.specular = l.specular;
        g.attenuation = l.attenuation;
        g.cosCutoff = std::cos(glm::radians(l.cutoffDeg));
        g.exponent = l.exponent;
    }
    // Unused slots are zeroed so uploads and comparisons are deterministic.
    for (int i = in.lightCount; i < glsl::MAX_LIGHTS; ++i) {
        in.lights[i] = glsl::Light{};
    }
    return in;
}

glm::vec3 shade(const ShadingInputs& in, const glm::vec3& p, const glm::vec3& N) {
    glsl::Light lights[glsl::MAX_LIGHTS];
    std::copy(std::begin(in.lights), std::end(in.lights), lights);
    return glsl::shade(in.material, in.brdf, in.terms, in.ambientLight, lights, in.lightCount, p, N);
}

} // namespace lab
