// sweep_grid.h — a sweep's cells (core/scene/sweep.h) as one labelled grid image: cells placed
// in rows and columns with the values as column and row headers and the keys' names, drawn with
// core/plots/text_raster.h. The first key runs along the columns, the second (if any) down the rows.
//
// It does not render (the caller passes a function that renders one cell: `lab render` passes
// the OffscreenRenderer, the GUI its own renderer) and does not write files.
#pragma once

#include "core/io/image.h"
#include "core/scene/sweep.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lab {

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
