// sweep.h — one preset and one or two parameter ranges: the lectures' grid of spheres
// (shininess along one axis, k_s along the other) as the presets of its cells. The grid image
// is core/plots/sweep_grid.h.
//
// This file owns the sweep's arguments ("KEY=V1,V2,..."), their validation against a preset and
// the cells' presets. The first key runs along the columns, the second (if any) down the rows.
//
// A KEY is a path into the preset's JSON as a preset file writes it: `material.shininess`,
// `cook_torrance.roughness`, `lights[0].attenuation`, `lights[1].attenuation[2]`, `brdf`. A value is
// what the file would hold there: a number, a name (`blinn-phong`), true or false, or for a
// triplet `[r,g,b]`; a single number for a triplet means all three (`material.specular=0.5` is
// [0.5, 0.5, 0.5]). Each value is validated exactly as a preset's: written into the preset's JSON
// and read back by the preset reader (core/scene/preset.h), so core/scene/limits.h's ranges and the
// reader's rules apply, and a refusal names the key, the value and the reader's message.
#pragma once

#include "core/io/image.h"
#include "core/scene/preset.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

inline constexpr std::size_t kMaxSweepKeys = 2;
inline constexpr std::size_t kMaxSweepValues = 10;
// The whole grid image, each side and in pixels (the cells and the labels).
inline constexpr int kMaxSweepSide = kMaxImageSide;
inline constexpr long long kMaxSweepPixels = 1LL << 26;

// One axis of the grid: a key and its values as typed (trimmed), which are also the labels.
struct SweepAxis {
    std::string key;
    std::vector<std::string> values;
    bool operator==(const SweepAxis&) const = default;
};

// "KEY=V1,V2,..." split into an axis: syntax only (commas inside [ ] belong to a value). Nullopt
// with a one-line `error` for no '=', an empty key or value, more than kMaxSweepValues values.
std::optional<SweepAxis> parseSweepAxis(std::string_view text, std::string& error);

// The grid's cells, row by row: cells[row * columns + column] is `base` with axes[0]'s
// column-th value and axes[1]'s row-th value applied.
struct SweepCells {
    int columns = 0;
    int rows = 0;
    std::vector<LoadedPreset> presets;
};

// Validates `axes` against `base` (1 or 2 axes, distinct keys that do not overlap however they
// are spelt, each key one a sweep can vary and that changes the render, each value one the
// preset reader accepts there) and makes the cells. The cells keep base's file (glTF paths stay
// relative to it). Frame `base` first (frameOmitted, core/gltf/model_loader.h: `lab render --sweep`
// does, and the GUI's scene is framed): a swept camera or light key then changes the framed
// camera or light. Of an unframed base the cells keep what it omitted, except the section a key
// sets (that camera or light is not framed). Nullopt with a one-line `error`.
std::optional<SweepCells> sweepCells(const LoadedPreset& base, const std::vector<SweepAxis>& axes, std::string& error);

// The keys the GUI offers for `preset` (the numeric and named ones that change its picture,
// per its BRDF and lights), each with a suggested range as "V1,V2,...".
struct SweepKeySuggestion {
    std::string key;
    std::string values;
};
std::vector<SweepKeySuggestion> sweepKeySuggestions(const Preset& preset);

} // namespace lab
