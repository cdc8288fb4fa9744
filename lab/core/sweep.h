// sweep.h — one preset and one or two parameter ranges, rendered as a labelled grid of images
// (the lectures' grid of spheres: shininess along one axis, k_s along the other).
//
// This file owns the sweep's arguments ("KEY=V1,V2,..."), their validation against a preset,
// the cells' presets, and the grid image: cells placed in rows and columns with the values as
// column and row headers and the keys' names, drawn with core/text_raster.h. The first key runs
// along the columns, the second (if any) down the rows.
//
// A KEY is a path into the preset's JSON as a preset file writes it: `material.shininess`,
// `cook_torrance.roughness`, `lights[0].attenuation`, `lights[1].attenuation[2]`, `brdf`. A value is
// what the file would hold there: a number, a name (`blinn-phong`), true or false, or for a
// triplet `[r,g,b]`; a single number for a triplet means all three (`material.specular=0.5` is
// [0.5, 0.5, 0.5]). Each value is validated exactly as a preset's: written into the preset's JSON
// and read back by the preset reader (core/preset.h), so core/limits.h's ranges and the
// reader's rules apply, and a refusal names the key, the value and the reader's message.
//
// It does not render (the caller passes a function that renders one cell: `lab render` passes
// the OffscreenRenderer, the GUI its own renderer) and does not write files.
#pragma once

#include "core/image.h"
#include "core/preset.h"

#include <functional>
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
// relative to it). Frame `base` first (frameOmitted, core/model_loader.h: `lab render --sweep`
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

// Where everything goes in the grid image, for cells of cellWidth × cellHeight.
struct SweepGridLayout {
    int width = 0, height = 0;  // the whole image
    int left = 0, top = 0;      // the first cell's top-left corner
    int cellWidth = 0, cellHeight = 0;
    int gap = 0;                // between cells
    float fontSize = 0.0f;      // the labels' pixel size
    int columns = 0, rows = 0;
    int cellX(int column) const { return left + column * (cellWidth + gap); }
    int cellY(int row) const { return top + row * (cellHeight + gap); }
};
SweepGridLayout sweepGridLayout(const std::vector<SweepAxis>& axes, int cellWidth, int cellHeight);

// The grid image: `cells` (row by row, each cellWidth × cellHeight) on a white page, the first
// key's name and values above the columns, the second's to the left of the rows.
Image composeSweepGrid(const std::vector<SweepAxis>& axes, const std::vector<Image>& cells, int cellWidth,
                       int cellHeight);

// sweepCells, then `renderCell` for each cell, then composeSweepGrid. Nullopt with `error` (the
// first cell that failed to render stops it; `renderCell` says why in its own string).
using RenderCell = std::function<std::optional<Image>(const LoadedPreset&, int width, int height, std::string& error)>;
std::optional<Image> renderSweep(const LoadedPreset& base, const std::vector<SweepAxis>& axes, int cellWidth,
                                 int cellHeight, const RenderCell& renderCell, std::string& error);

} // namespace lab
