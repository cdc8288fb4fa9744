// lighting.cpp — compiles shaders/lighting.glsl as C++, and packs a Preset for it.
#include "core/lighting/lighting.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace lab {

namespace glsl {
#include "lighting.glsl"
#include "view.glsl"
} // namespace glsl

int viewKind(ViewMode mode) {
    if (mode == ViewMode::Normals) {
        return glsl::VIEW_NORMALS;
    }
    if (mode == ViewMode::GouraudError) {
        return glsl::VIEW_GOURAUD_ERROR;
    }
    return isFactor(mode) ? glsl::VIEW_FACTOR : glsl::VIEW_SHADE;
}

int factorIndex(ViewMode mode) {
    static_assert(static_cast<int>(ViewMode::RdotV) - static_cast<int>(ViewMode::NdotL) == glsl::FACTOR_R_DOT_V);
    static_assert(static_cast<int>(ViewMode::D) - static_cast<int>(ViewMode::NdotL) == glsl::FACTOR_D);
    static_assert(static_cast<int>(ViewMode::Denominator) - static_cast<int>(ViewMode::NdotL) ==
                  glsl::FACTOR_DENOMINATOR);
    static_assert(static_cast<int>(ViewMode::Distance) - static_cast<int>(ViewMode::NdotL) == glsl::FACTOR_DISTANCE);
    return isFactor(mode) ? static_cast<int>(mode) - static_cast<int>(ViewMode::NdotL) : 0;
}

int paletteIndex(ValuePalette palette) {
    static_assert(static_cast<int>(ValuePalette::Viridis) == glsl::PALETTE_VIRIDIS);
    static_assert(static_cast<int>(ValuePalette::Grey) == glsl::PALETTE_GREY);
    return static_cast<int>(palette);
}

glm::vec3 paletteColor(ValuePalette palette, float t) { return glsl::paletteColor(paletteIndex(palette), t); }

int packedLightIndex(const Preset& preset, int light) {
    if (light < 0 || light >= static_cast<int>(preset.lights.size()) ||
        !preset.lights[static_cast<std::size_t>(light)].enabled) {
        return -1;
    }
    int packed = 0;
    for (int i = 0; i < light; ++i) {
        packed += preset.lights[static_cast<std::size_t>(i)].enabled ? 1 : 0;
    }
    return packed < glsl::MAX_LIGHTS ? packed : -1;
}

//----------------------------------------------------------------------------------------
// The shaders' structs as rows
//----------------------------------------------------------------------------------------

namespace {

using glsl::Brdf, glsl::Light, glsl::Material, glsl::Terms;
constexpr ShaderField kMaterialFields[] = {
    {"emissive", FieldType::Vec3, offsetof(Material, emissive)},
    {"ambient", FieldType::Vec3, offsetof(Material, ambient)},
    {"diffuse", FieldType::Vec3, offsetof(Material, diffuse)},
    {"specular", FieldType::Vec3, offsetof(Material, specular)},
    {"shininess", FieldType::Float, offsetof(Material, shininess)},
};
constexpr ShaderField kBrdfFields[] = {
    {"model", FieldType::Int, offsetof(Brdf, model)},
    {"distribution", FieldType::Int, offsetof(Brdf, distribution)},
    {"fresnel", FieldType::Int, offsetof(Brdf, fresnel)},
    {"geometry", FieldType::Bool, offsetof(Brdf, geometry)},
    {"roughness", FieldType::Float, offsetof(Brdf, roughness)},
    {"ior", FieldType::Float, offsetof(Brdf, ior)},
};
constexpr ShaderField kTermsFields[] = {
    {"emissive", FieldType::Bool, offsetof(Terms, emissive)},
    {"ambient", FieldType::Bool, offsetof(Terms, ambient)},
    {"diffuse", FieldType::Bool, offsetof(Terms, diffuse)},
    {"specular", FieldType::Bool, offsetof(Terms, specular)},
};
constexpr ShaderField kLightFields[] = {
    {"type", FieldType::Int, offsetof(Light, type)},
    {"position", FieldType::Vec3, offsetof(Light, position)},
    {"direction", FieldType::Vec3, offsetof(Light, direction)},
    {"ambient", FieldType::Vec3, offsetof(Light, ambient)},
    {"diffuse", FieldType::Vec3, offsetof(Light, diffuse)},
    {"specular", FieldType::Vec3, offsetof(Light, specular)},
    {"attenuation", FieldType::Vec3, offsetof(Light, attenuation)},
    {"cosCutoff", FieldType::Float, offsetof(Light, cosCutoff)},
    {"exponent", FieldType::Float, offsetof(Light, exponent)},
};

template <typename T>
bool equalAt(const void* a, const void* b, std::size_t offset) {
    return *reinterpret_cast<const T*>(static_cast<const char*>(a) + offset) ==
           *reinterpret_cast<const T*>(static_cast<const char*>(b) + offset);
}

} // namespace

const ShaderStruct kMaterialUniform{"u_material", kMaterialFields};
const ShaderStruct kBrdfUniform{"u_brdf", kBrdfFields};
const ShaderStruct kTermsUniform{"u_terms", kTermsFields};
const ShaderStruct kLightUniform{"u_lights[i]", kLightFields};

bool fieldsEqual(const void* a, const void* b, const ShaderStruct& shape) {
    for (const ShaderField& f : shape.fields) {
        bool equal = f.type == FieldType::Int    ? equalAt<int>(a, b, f.offset)
                     : f.type == FieldType::Bool  ? equalAt<bool>(a, b, f.offset)
                     : f.type == FieldType::Float ? equalAt<float>(a, b, f.offset)
                                                  : equalAt<glm::vec3>(a, b, f.offset);
        if (!equal) {
            return false;
        }
    }
    return true;
}

bool operator==(const SurfaceUniforms& x, const SurfaceUniforms& y) {
    return fieldsEqual(&x.material, &y.material, kMaterialUniform) && fieldsEqual(&x.brdf, &y.brdf, kBrdfUniform) &&
           fieldsEqual(&x.terms, &y.terms, kTermsUniform);
}

//----------------------------------------------------------------------------------------
// Packing a preset
//----------------------------------------------------------------------------------------

SurfaceUniforms packSurfaceUniforms(const Preset& preset) {
    static_assert(static_cast<int>(BrdfModel::CookTorrance) == glsl::BRDF_COOK_TORRANCE);
    static_assert(static_cast<int>(BrdfModel::BlinnPhong) == glsl::BRDF_BLINN_PHONG);
    static_assert(static_cast<int>(Distribution::Ggx) == glsl::DISTRIBUTION_GGX);
    static_assert(static_cast<int>(Distribution::Gaussian) == glsl::DISTRIBUTION_GAUSSIAN);
    static_assert(static_cast<int>(FresnelMode::Full) == glsl::FRESNEL_FULL);
    SurfaceUniforms s;
    const MaterialDesc& m = preset.material;
    s.material = {.emissive = m.emissive, .ambient = m.ambient, .diffuse = m.diffuse, .specular = m.specular,
                  .shininess = m.shininess};
    const CookTorrance& ct = preset.cookTorrance;
    s.brdf = {.model = static_cast<int>(preset.brdf), .distribution = static_cast<int>(ct.distribution),
              .fresnel = static_cast<int>(ct.fresnel), .geometry = ct.geometry, .roughness = ct.roughness, .ior = ct.ior};
    const TermSwitches& t = preset.terms;
    s.terms = {.emissive = t.emissive, .ambient = t.ambient, .diffuse = t.diffuse, .specular = t.specular};
    return s;
}

ShadingInputs packShading(const Preset& preset, const glm::mat4& view) {
    static_assert(static_cast<int>(LightType::Spot) == glsl::LIGHT_SPOT);
    static_assert(static_cast<int>(LightType::Directional) == glsl::LIGHT_DIRECTIONAL);
    static_assert(kMaxLights == glsl::MAX_LIGHTS);

    ShadingInputs in;
    static_cast<SurfaceUniforms&>(in) = packSurfaceUniforms(preset);
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
