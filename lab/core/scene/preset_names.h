// preset_names.h — the names of preset.h's enumerations as preset files spell them.
//
// Internal to lab/core/preset*.cpp: preset.cpp writes them (toString), preset_read.cpp reads them
// back (with a suggestion for a near miss). Everyone else asks preset.h's toString().
#pragma once

#include "core/scene/preset.h"

#include <array>
#include <string_view>
#include <utility>

namespace lab::preset_names {

template <typename E, std::size_t N>
using NameTable = std::array<std::pair<E, std::string_view>, N>;

inline constexpr NameTable<Builtin, 4> kBuiltin{
    {{Builtin::Sphere, "sphere"}, {Builtin::Cube, "cube"}, {Builtin::Plane, "plane"}, {Builtin::Torus, "torus"}}};
inline constexpr NameTable<Shading, 3> kShading{
    {{Shading::Flat, "flat"}, {Shading::Gouraud, "gouraud"}, {Shading::Phong, "phong"}}};
inline constexpr NameTable<NormalMatrixMode, 2> kNormalMatrix{
    {{NormalMatrixMode::InverseTranspose, "inverse-transpose"}, {NormalMatrixMode::ModelView, "model-view"}}};
inline constexpr NameTable<BrdfModel, 3> kBrdf{
    {{BrdfModel::Phong, "phong"}, {BrdfModel::BlinnPhong, "blinn-phong"}, {BrdfModel::CookTorrance, "cook-torrance"}}};
inline constexpr NameTable<Distribution, 3> kDistribution{
    {{Distribution::Beckmann, "beckmann"}, {Distribution::Gaussian, "gaussian"}, {Distribution::Ggx, "ggx"}}};
inline constexpr NameTable<FresnelMode, 2> kFresnel{{{FresnelMode::Schlick, "schlick"}, {FresnelMode::Full, "full"}}};
inline constexpr NameTable<LightType, 3> kLightType{
    {{LightType::Point, "point"}, {LightType::Directional, "directional"}, {LightType::Spot, "spot"}}};

} // namespace lab::preset_names
