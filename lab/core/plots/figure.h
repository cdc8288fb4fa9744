// figure.h — a plain vector figure (lines, filled polygons, discs, text) and its two writers:
// SVG text and a PNG-ready Image at any scale. The plots' figures (core/plots/figures.h) are built as
// one Figure and written by both, so the SVG and the PNG of a figure cannot disagree.
//
// Coordinates are pixels at scale 1, x right, y down, origin at the top left. A text's `at` is
// the start, middle or end of its baseline. Shapes are painted in order.
//
// Not here: what the figures show (core/plots/figures.h), curves (polylines only), clipping, transforms,
// fonts other than DejaVu Sans (core/plots/text_raster.h draws the PNG's text; the SVG names the family).
#pragma once

#include "core/io/image.h"
#include "core/plots/text_raster.h"

#include <glm/vec2.hpp>

#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace lab {

using FigureColor = TextColor;

struct FigureLine {
    std::vector<glm::vec2> points; // an open polyline, round joins and caps
    float width = 1.0f;
    FigureColor color;
    std::string id; // the SVG element's id when not empty ("lobe-total"): what the tests find
    // Dashes: lengths along the line, on, off, on, off… (an even count; an "on" of 0 is a round
    // dot); empty: solid. SVG's stroke-dasharray; the PNG and the screen draw dashRuns().
    std::vector<float> dash = {};
};

struct FigurePolygon {
    std::vector<glm::vec2> points; // closed, filled (arrowheads, legend swatches)
    FigureColor fill;
};

struct FigureDisc {
    glm::vec2 centre{0.0f};
    float radius = 1.0f;
    FigureColor fill;
};

// A raster image (the slice's values through a palette) stretched over the rectangle at `at` of
// `size`, each of its pixels a sharp-edged cell: SVG's <image> (a PNG inside, image-rendering
// pixelated), the PNG's nearest pixel.
struct FigureImage {
    glm::vec2 at{0.0f}, size{0.0f};
    std::shared_ptr<const Image> image; // shared: a figure's copies do not copy its pixels
    std::string id; // the SVG element's id when not empty
};

enum class TextAnchor { Start, Middle, End };

struct FigureText {
    glm::vec2 at{0.0f}; // on the baseline
    std::string text;   // UTF-8, any characters (escaped by the SVG writer)
    float size = 14.0f; // the em size in pixels (SVG's font-size)
    FigureColor color;
    TextAnchor anchor = TextAnchor::Start;
    bool bold = false; // the title; the PNG draws it twice, half a pixel apart
};

using FigureShape = std::variant<FigureLine, FigurePolygon, FigureDisc, FigureText, FigureImage>;

struct Figure {
    float width = 0.0f, height = 0.0f;
    FigureColor background{255, 255, 255};
    std::string title; // the SVG's <title>
    std::vector<FigureShape> shapes;
};

// The SVG document: a viewBox of width × height with the same width and height in px, numbers
// with two decimals, text XML-escaped (control characters and invalid UTF-8 shown as escapes,
// core/io/safe_text.h, so the document is always well-formed).
std::string figureSvg(const Figure& figure);

// The pieces of the polyline `points` that `dash` (FigureLine::dash) draws, each a polyline of its
// own, as SVG's stroke-dasharray cuts it; a dot is a piece of two equal points. The whole line when
// `dash` is empty or its lengths add up to less than half a pixel.
std::vector<std::vector<glm::vec2>> dashRuns(const std::vector<glm::vec2>& points, const std::vector<float>& dash);
// The same pieces handed to `draw` one by one, in order, each in `run` (a buffer the caller keeps:
// nothing is allocated a piece). dashRuns() collects them.
void forEachDashRun(const std::vector<glm::vec2>& points, const std::vector<float>& dash, std::vector<glm::vec2>& run,
                    const std::function<void(const std::vector<glm::vec2>&)>& draw);

// Smallest and largest PNG scales (the PNG is width·scale × height·scale pixels, rounded).
inline constexpr float kMinFigureScale = 0.25f;
inline constexpr float kMaxFigureScale = 8.0f;

// The figure painted on the CPU at `scale` (clamped to the range above): lines, polygons and discs
// anti-aliased by their coverage of each pixel, text through `font`.
Image rasterizeFigure(const Figure& figure, float scale, const TextFont& font = sharedTextFont());

} // namespace lab
