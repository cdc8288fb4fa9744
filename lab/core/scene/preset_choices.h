// preset_choices.h — every value of the preset's enumerations, in order, for cycling and for lists.
//
// The UI's radio buttons and combos and the B/V/M shortcuts walk these arrays, so no count is
// written anywhere else. The names in preset files are preset.h's toString().
#pragma once

#include "core/scene/field_table.h"
#include "core/scene/preset.h"

#include <array>
#include <cstddef>
#include <iterator>

namespace lab {

inline constexpr std::array kBuiltins{Builtin::Sphere, Builtin::Cube, Builtin::Plane, Builtin::Torus};
inline constexpr std::array kShadings{Shading::Flat, Shading::Gouraud, Shading::Phong};
inline constexpr std::array kNormalMatrixModes{NormalMatrixMode::InverseTranspose, NormalMatrixMode::ModelView};
inline constexpr std::array kBrdfModels{BrdfModel::Phong, BrdfModel::BlinnPhong, BrdfModel::CookTorrance};
inline constexpr std::array kDistributions{Distribution::Beckmann, Distribution::Gaussian, Distribution::Ggx};
inline constexpr std::array kFresnelModes{FresnelMode::Schlick, FresnelMode::Full};
inline constexpr std::array kLightTypes{LightType::Point, LightType::Directional, LightType::Spot};

// Names as the GUI shows them (preset files use preset.h's toString: "gouraud", "blinn-phong"),
// from the field table's choices, which are in the order of the values.
inline const char* label(Shading v) { return kShadingChoices[static_cast<std::size_t>(v)].label; }
inline const char* label(BrdfModel v) { return kBrdfChoices[static_cast<std::size_t>(v)].label; }

// The value after `value` in `all`, wrapping around.
template <typename E, std::size_t N>
constexpr E nextOf(const std::array<E, N>& all, E value) {
    for (std::size_t i = 0; i < N; ++i) {
        if (all[i] == value) {
            return all[(i + 1) % N];
        }
    }
    return all[0];
}

// The value before `value` in `all`, wrapping around.
template <typename E, std::size_t N>
constexpr E previousOf(const std::array<E, N>& all, E value) {
    for (std::size_t i = 0; i < N; ++i) {
        if (all[i] == value) {
            return all[(i + N - 1) % N];
        }
    }
    return all[0];
}

} // namespace lab
