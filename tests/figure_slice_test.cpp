// figure_slice_test.cpp — the (θh, θd) slice as a figure: its CSV is the slice's, its image's cells
// are the slice's values through the palette (the PNG read back at each cell's centre), θd grows
// upwards, and compare mode adds B and A − B.
#include "core/plots/figures.h"
#include "core/plots/slice.h"

#include "core/lighting/lighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace lab {
namespace {

Preset blinn(float n) {
    Preset p;
    p.name = "Blinn";
    p.brdf = BrdfModel::BlinnPhong;
    p.material.shininess = n;
    p.material.specular = glm::vec3(0.8f);
    return p;
}

FigureResult sliceOf(const Preset& a, const Preset* b, FigureRequest r = {}) {
    r.kind = FigureKind::Slice;
    std::string error;
    std::optional<FigureResult> f = makeFigure(a, b, r, error);
    EXPECT_TRUE(f.has_value()) << error;
    return f.value_or(FigureResult{});
}

std::array<int, 3> pixel(const Image& image, glm::vec2 at) {
    const std::size_t k = (std::size_t(at.y) * std::size_t(image.width) + std::size_t(at.x)) * 3;
    return {image.rgb[k], image.rgb[k + 1], image.rgb[k + 2]};
}

std::array<int, 3> bytes(glm::vec3 c) {
    auto b = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    return {b(c.r), b(c.g), b(c.b)};
}

TEST(FigureSlice, CsvIsTheSlicesAndCellsAreItsValuesThroughThePalette) {
    const Preset a = blinn(20.0f);
    for (RadialScale scale : {RadialScale::Linear, RadialScale::Log}) {
        FigureRequest r;
        r.scale = scale;
        const FigureResult f = sliceOf(a, nullptr, r);
        const SliceImage slice = sampleSlice(packSurfaceUniforms(a));
        EXPECT_EQ(f.csv, sliceCsv(slice));
        EXPECT_FLOAT_EQ(f.outer, slice.largest(PlotComponent::Specular));
        const Image png = rasterizeFigure(f.figure, 2.0f);
        for (int h : {0, 7, 30, 89}) {
            for (int d : {0, 45, 88}) {
                // Cell (h, d)'s centre: θh across from the left, θd up from the bottom.
                const glm::vec2 unit((h + 0.5f) / kSliceSide, (90 - d + 0.5f) / kSliceSide);
                const glm::vec2 at = (f.offset + unit * f.scale) * 2.0f;
                const float v = slice.specular[static_cast<std::size_t>(slice.index(h, d))];
                EXPECT_EQ(pixel(png, at), bytes(paletteColor(ValuePalette::Viridis, plotRadius(v, f.outer, scale))))
                    << "θh " << h << " θd " << d;
            }
        }
    }
}

TEST(FigureSlice, CompareModeDrawsAAndBOnOneScaleAndTheirDifference) {
    const Preset a = blinn(20.0f), b = blinn(80.0f);
    const FigureResult f = sliceOf(a, &b);
    const std::string svg = figureSvg(f.figure);
    for (const char* id : {"slice-a", "slice-b", "slice-difference", "slice-difference-bar"}) {
        EXPECT_NE(svg.find("<image id=\"" + std::string(id) + "\""), std::string::npos) << id;
    }
    EXPECT_NE(svg.find("A \xe2\x88\x92 B"), std::string::npos);
    // A's wider lobe reflects more than B's at θh = 20°: orange, A's side of the diverging palette.
    const Image png = rasterizeFigure(f.figure, 1.0f);
    const float side = f.scale.x;
    // The panels' pitch: the three span from A's left to the page's right margin (18 pixels).
    const float aLeft = f.offset.x, step = (f.figure.width - 18.0f - aLeft - side) / 2.0f;
    const glm::vec2 cell((20 + 0.5f) / kSliceSide * side, (90 - 30 + 0.5f) / kSliceSide * side);
    const std::array<int, 3> diff = pixel(png, glm::vec2(aLeft + 2.0f * step, f.offset.y) + cell);
    EXPECT_GT(diff[0], diff[2] + 60) << "orange: more red than blue";
}

TEST(FigureSlice, ExportedWithTheOtherFiguresAndNamedSlice) {
    EXPECT_EQ(toString(FigureKind::Slice), "slice");
    EXPECT_EQ(figureKindFrom("slice"), FigureKind::Slice);
    EXPECT_EQ(kFigureKinds.back(), FigureKind::Slice);
}

} // namespace
} // namespace lab
