// sweep_grid.cpp — the sweep's grid image: layout, labels, cells.
#include "core/plots/sweep_grid.h"

#include "core/plots/text_raster.h"

#include <cmath>

namespace lab {

//----------------------------------------------------------------------------------------
// The grid image
//----------------------------------------------------------------------------------------

namespace {

const TextColor kInk{25, 25, 25};
const TextColor kKeyInk{90, 90, 90};
constexpr std::uint8_t kPage = 255;

int ceilPixels(float f) { return static_cast<int>(std::ceil(f)); }

} // namespace

SweepGridLayout sweepGridLayout(const std::vector<SweepAxis>& axes, int cellWidth, int cellHeight) {
    const TextFont& font = sharedTextFont();
    SweepGridLayout g;
    g.cellWidth = cellWidth;
    g.cellHeight = cellHeight;
    g.columns = axes.empty() ? 0 : static_cast<int>(axes[0].values.size());
    g.rows = axes.size() > 1 ? static_cast<int>(axes[1].values.size()) : 1;
    g.fontSize = std::clamp(std::round(static_cast<float>(std::min(cellWidth, cellHeight)) * 0.1f), 12.0f, 40.0f);
    g.gap = std::max(2, static_cast<int>(g.fontSize * 0.3f));
    const int pad = static_cast<int>(g.fontSize * 0.6f);
    const int line = ceilPixels(font.measure("Ag", g.fontSize).height);
    g.top = pad + 2 * line + pad / 2;
    g.left = pad;
    if (axes.size() > 1) {
        float widest = font.measure(axes[1].key, g.fontSize).width;
        for (const std::string& v : axes[1].values) {
            widest = std::max(widest, std::min(font.measure(v, g.fontSize).width, g.fontSize * 12));
        }
        g.left = pad + ceilPixels(widest) + pad;
    }
    g.width = g.left + g.columns * cellWidth + std::max(0, g.columns - 1) * g.gap + pad;
    g.height = g.top + g.rows * cellHeight + std::max(0, g.rows - 1) * g.gap + pad;
    return g;
}

Image composeSweepGrid(const std::vector<SweepAxis>& axes, const std::vector<Image>& cells, int cellWidth,
                       int cellHeight) {
    const TextFont& font = sharedTextFont();
    SweepGridLayout g = sweepGridLayout(axes, cellWidth, cellHeight);
    Image image;
    image.width = g.width;
    image.height = g.height;
    image.rgb.assign(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height) * 3, kPage);
    for (int row = 0; row < g.rows; ++row) {
        for (int column = 0; column < g.columns; ++column) {
            std::size_t i = static_cast<std::size_t>(row * g.columns + column);
            if (i >= cells.size() || cells[i].width != cellWidth || cells[i].height != cellHeight) {
                continue;
            }
            for (int y = 0; y < cellHeight; ++y) {
                const std::uint8_t* from = cells[i].rgb.data() + static_cast<std::size_t>(y) * cellWidth * 3;
                std::uint8_t* to = image.rgb.data() +
                                   (static_cast<std::size_t>(g.cellY(row) + y) * g.width + g.cellX(column)) * 3;
                std::copy(from, from + static_cast<std::size_t>(cellWidth) * 3, to);
            }
        }
    }
    if (axes.empty()) {
        return image;
    }
    const float size = g.fontSize;
    const float line = font.measure("Ag", size).height;
    const float pad = std::floor(size * 0.6f);
    // The first key above the columns, centred on them; its values above each column.
    const float gridWidth = static_cast<float>(g.cellX(g.columns - 1) + cellWidth - g.left);
    std::string key0 = font.fitted(axes[0].key, size, gridWidth);
    font.draw(image, key0, static_cast<float>(g.left) + (gridWidth - font.measure(key0, size).width) / 2, pad, size, kKeyInk);
    for (int column = 0; column < g.columns; ++column) {
        std::string v = font.fitted(axes[0].values[static_cast<std::size_t>(column)], size, static_cast<float>(cellWidth));
        float x = static_cast<float>(g.cellX(column)) + (static_cast<float>(cellWidth) - font.measure(v, size).width) / 2;
        font.draw(image, v, x, pad + line, size, kInk);
    }
    // The second key in the corner above the row headers; its values beside each row.
    if (axes.size() > 1) {
        const float headerWidth = static_cast<float>(g.left) - 2 * pad;
        font.draw(image, font.fitted(axes[1].key, size, headerWidth), pad, pad + line, size, kKeyInk);
        for (int row = 0; row < g.rows; ++row) {
            std::string v = font.fitted(axes[1].values[static_cast<std::size_t>(row)], size, headerWidth);
            float y = static_cast<float>(g.cellY(row)) + (static_cast<float>(cellHeight) - line) / 2;
            font.draw(image, v, pad, y, size, kInk);
        }
    }
    return image;
}

std::optional<Image> renderSweep(const LoadedPreset& base, const std::vector<SweepAxis>& axes, int cellWidth,
                                 int cellHeight, const RenderCell& renderCell, std::string& error) {
    std::optional<SweepCells> cells = sweepCells(base, axes, error);
    if (!cells) {
        return std::nullopt;
    }
    SweepGridLayout g = sweepGridLayout(axes, cellWidth, cellHeight);
    if (g.width > kMaxSweepSide || g.height > kMaxSweepSide ||
        static_cast<long long>(g.width) * g.height > kMaxSweepPixels) {
        error = "the grid would be " + std::to_string(g.width) + "x" + std::to_string(g.height) +
                " pixels (at most " + std::to_string(kMaxSweepSide) + " a side and " +
                std::to_string(kMaxSweepPixels >> 20) + " Mpixels): give smaller cells";
        return std::nullopt;
    }
    std::vector<Image> images;
    for (const LoadedPreset& cell : cells->presets) {
        std::optional<Image> image = renderCell(cell, cellWidth, cellHeight, error);
        if (!image) {
            return std::nullopt;
        }
        images.push_back(std::move(*image));
    }
    return composeSweepGrid(axes, images, cellWidth, cellHeight);
}

} // namespace lab
