// lighting.h — the C++ face of the lighting model.
//
// The equations are not written here: lab::glsl is shaders/lighting_api.glsl and
// shaders/lighting.glsl compiled as C++ with GLM, so the plots, `lab plot` and the tests run the
// very code the GPU runs. This header adds what both faces need from a Preset: the packing
// of material, BRDF and lights into the structs the shaders take as uniforms (the matrices are
// core/scene/transforms.h), and those structs' fields as rows (ShaderField). The
// renderer uploads exactly what packShading returns, by those rows.
#pragma once

#include "core/scene/preset.h"
#include "core/scene/view_mode.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <span>

namespace lab {

namespace glsl {
using namespace glm;
#include "lighting_api.glsl"
} // namespace glsl

// The material, BRDF and term switches as the shaders take them (their uniforms u_material,
// u_brdf, u_terms): what the renderer (through
// ShadingInputs) and the plots (plots/plot_data.h's LobeInputs) both evaluate with.
struct SurfaceUniforms {
    glsl::Material material{};
    glsl::Brdf brdf{};
    glsl::Terms terms{};
};

// Everything lit.vert/lit.frag read as uniforms, minus the matrices.
struct ShadingInputs : SurfaceUniforms {
    glm::vec3 ambientLight{0.0f};
    glsl::Light lights[glsl::MAX_LIGHTS]{};
    int lightCount = 0; // enabled lights only, in preset order
};

// The shaders' uniforms that come from the lighting model's structs, one row each: the field's
// GLSL name, its type, and where it lies in the C++ struct the same GLSL declares
// (lighting_api.glsl). The renderer uploads by these rows, SurfaceUniforms's equality compares by them,
// and a GL test checks that they and the linked program's active uniforms name the same fields.
// A new parameter of the lighting model is a field in lighting_api.glsl, a row here, its line in
// packSurfaceUniforms, its key in the preset (scene/preset.h) and its control in the panel.
enum class FieldType { Int, Bool, Float, Vec3 };
struct ShaderField {
    const char* name;
    FieldType type;
    std::size_t offset;
};
struct ShaderStruct {
    const char* uniform; // the uniform of that struct type ("u_material"), "u_lights[i]" for lights
    std::span<const ShaderField> fields;
};
extern const ShaderStruct kMaterialUniform, kBrdfUniform, kTermsUniform, kLightUniform;

// Every field of `a` and `b` equal by `shape`'s rows (floats exactly: a NaN is never equal).
bool fieldsEqual(const void* a, const void* b, const ShaderStruct& shape);
bool operator==(const SurfaceUniforms& x, const SurfaceUniforms& y);

// The preset's material, BRDF and term switches, as the shaders take them.
SurfaceUniforms packSurfaceUniforms(const Preset& preset);
// packSurfaceUniforms, the ambient light and the enabled lights moved into eye space with `view`.
ShadingInputs packShading(const Preset& preset, const glm::mat4& view);

// glsl::shade with the packed inputs: the colour at eye-space point p with unit normal N.
glm::vec3 shade(const ShadingInputs& in, const glm::vec3& p, const glm::vec3& N);

// The value views' side of the shaders (shaders/view.glsl, compiled here as C++ too): what lit.frag
// is told to write for `mode` (VIEW_*), the factor (FACTOR_*, for a factor view), the palette's
// number, and the palette itself, which the legends draw with.
int viewKind(ViewMode mode);
int factorIndex(ViewMode mode);
int paletteIndex(ValuePalette palette);
glm::vec3 paletteColor(ValuePalette palette, float t);

// The enabled light that preset.lights[light] is in packShading's lights; -1 when it is off or
// there is none.
int packedLightIndex(const Preset& preset, int light);

// Rec. 709 luminance.
inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

} // namespace lab
