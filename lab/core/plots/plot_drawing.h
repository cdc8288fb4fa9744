// plot_drawing.h — the plots' one drawing vocabulary. The lab's plots on screen (lab/ui) and the
// figures (figures.h) are built with it as a Figure (figure.h): shapes, text and colours, in
// window pixels or page pixels. A Figure is painted twice: onto ImGui's draw list for the screen
// (ui/plots/plot_kit.h's paint) and into SVG and PNG for the figures (figure.h's writers).
//
// Colours are roles (Ink); a Palette gives each its colour, one palette a theme (theme.h: dark,
// light on near black; light, dark on white), the same on screen and in the figures. The curves
// also differ by their dash (dashOf), so that no legend tells them apart by colour alone. Sizes
// are the figures' page sizes times a PlotStyle's scale: 1 for the figures, the UI's font size
// over the figures' text size on screen, so a plot grows with presenter mode. Text is measured
// with the style's own measure: the font the figure's PNG draws with, or ImGui's.
//
// Not here: the numbers plotted (plot_data.h, energy.h, lobe3d.h), where plots go in a window
// (plot_layout.h), what each figure shows (figures.cpp), the screen's widgets (lab/ui).
#pragma once

#include "core/plots/figure.h"
#include "core/plots/plot_data.h"
#include "core/plots/plot_layout.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

//----------------------------------------------------------------------------------------
// Colours, sizes, text
//----------------------------------------------------------------------------------------

enum class Ink {
    Text,       // labels and values
    Muted,      // secondary text: ring values, captions, subtitles
    Grid,       // rings, spokes, grid lines
    Axis,       // axes, the outer circle, N
    Background, // the plot's own background
    Diffuse,    // the diffuse term's curves
    Specular,   // the specular term's curves (and markers on the attenuation curve)
    Total,      // the total
    Compare,    // set B's total in compare mode
    Light,      // L and the incident angle
    Mirror,     // R, the mirror direction
    Viewer,     // V, the reading direction
    Half,       // H, the half vector
    Probe,      // the pixel probe's vectors
    Warning,    // a scale that cuts a lobe
    Overlay1,   // the three incident angles overlaid
    Overlay2,
    Overlay3,
    Count
};
using Palette = std::array<FigureColor, static_cast<std::size_t>(Ink::Count)>;
inline Ink overlayInk(std::size_t i) { return static_cast<Ink>(static_cast<std::size_t>(Ink::Overlay1) + i); }
inline FigureColor colorOf(const Palette& palette, Ink ink) { return palette[static_cast<std::size_t>(ink)]; }

// The width of `text` at em size `size`, in the figure's pixels.
using TextMeasure = float (*)(std::string_view text, float size);

// The figures' page sizes (pixels at scale 1) times `scale`, the palette and the text measure.
struct PlotStyle {
    const Palette* palette = nullptr;
    float scale = 1.0f;
    TextMeasure measure;
    float arcStep = 0.0f; // a ring's segments on screen: about one per arcStep pixels (0: the figures' 120)

    constexpr float text() const { return 14.0f * scale; }   // labels, legends, arrow names
    constexpr float small() const { return 12.5f * scale; }  // ring values and captions
    constexpr float title() const { return 18.0f * scale; }
    constexpr float pad() const { return 6.0f * scale; }     // text from what it labels
    constexpr float thin() const { return 1.0f * scale; }    // grid lines
    constexpr float stroke() const { return 2.0f * scale; }  // curves, axes, arrows
    constexpr float bold() const { return 3.0f * scale; }    // the total and L
    constexpr float head() const { return 11.0f * scale; }   // an arrowhead's length at most
    FigureColor color(Ink ink) const { return colorOf(*palette, ink); }
    float width(std::string_view t, float size) const { return measure(t, size); }
};
// The width of text as the figures' PNG draws it (text_raster.h's shared font).
float printedWidth(std::string_view text, float size);
// The figures' sizes (scale 1, measured with the PNG's font); their colours are a theme's (theme.h figureStyle).
inline constexpr PlotStyle kFigureSizes{nullptr, 1.0f, &printedWidth};

// How a curve's ink is dashed, at `scale` (FigureLine::dash): the total and the overlay's first
// angle solid, the diffuse term and the second angle dashed, the specular term and the third
// dotted, set B's total dash-dot; every other ink solid (empty).
std::vector<float> dashOf(Ink ink, float scale);

inline constexpr const char* kDeg = "\xc2\xb0";   // °
inline constexpr const char* kTheta = "\xce\xb8"; // θ

// printf into a string (up to 95 bytes).
std::string format(const char* f, ...) __attribute__((format(printf, 1, 2)));
// A value on an axis or a ring: 3 significant digits, no trailing zeros.
std::string tickText(float v);
// "30°": whole degrees.
std::string degrees(float deg);

//----------------------------------------------------------------------------------------
// A plot being drawn
//----------------------------------------------------------------------------------------

// Shapes appended to `figure` in `style`'s palette. Coordinates in pixels, y down.
class PlotCanvas {
public:
    PlotCanvas(Figure& figure, const PlotStyle& style) : figure_(figure), style_(style) {}
    const PlotStyle& style() const { return style_; }

    void line(std::vector<glm::vec2> points, float width, Ink ink, std::string id = {});
    // Text whose capitals are centred on `at.y` (DejaVu's cap height is 0.73 em).
    void text(glm::vec2 at, std::string text, float size, Ink ink, TextAnchor anchor = TextAnchor::Start, bool bold = false);
    void disc(glm::vec2 centre, float radius, Ink ink);
    void polygon(std::vector<glm::vec2> points, Ink ink);
    // An arrow from `from` to `to` with its name (bold) beside the tip, on the side away from the
    // arrow's own line; one too short to point anywhere (a 3D vector seen end on) is a dot.
    void arrow(glm::vec2 from, glm::vec2 to, Ink ink, float width, const std::string& label);

private:
    Figure& figure_;
    const PlotStyle& style_;
};

//----------------------------------------------------------------------------------------
// Polar plots: the plane of incidence's half-disc
//----------------------------------------------------------------------------------------

// The plot's unit half-disc (x along the surface towards the viewer's side, y up along N) in
// pixels: `origin` where N starts, `radius` the outer circle's.
struct Polar {
    glm::vec2 origin{0.0f};
    float radius = 1.0f;
    glm::vec2 at(glm::vec2 unit) const { return {origin.x + unit.x * radius, origin.y - unit.y * radius}; }
    glm::vec2 unitAt(glm::vec2 point) const; // at()'s inverse (a radius below 1 pixel taken as 1)
};

// (side · sin θ, cos θ) for θ in degrees: L's side is -1, R's and V's +1.
glm::vec2 dirFromDeg(float deg, float side);

// The room around the half-disc: the angle labels beside and above the rim, the ring values
// and 90° labels under the surface line, and (with `caption`, a figure's page) the caption
// under them; without, compact (a plot among others in a window).
PlotMargins polarMargins(const PlotStyle& style, bool caption);
// The largest half-disc in the area (x, y, width, height) with those margins.
Polar polarFrame(glm::vec2 corner, float width, float height, const PlotStyle& style, bool caption);
// The tallest a polar plot is worth at `width`: the half-disc as wide as it can be.
float polarMaxHeight(const PlotStyle& style, float width, bool caption);

// Rings with their values under the surface line, spokes every 30° with their angles outside
// the rim, the outer circle, a log scale's 2…9 marks, the surface line and (with `caption`)
// what the radius is. A half-disc too small for labels gets the surface line only.
void polarGrid(PlotCanvas& canvas, const Polar& polar, float outer, RadialScale scale, bool caption);

//----------------------------------------------------------------------------------------
// Cartesian plots
//----------------------------------------------------------------------------------------

// A plot box: lo the bottom left, hi the top right (pixels); at(u, v) for u, v in [0, 1].
struct Box {
    glm::vec2 lo{0.0f}, hi{0.0f};
    glm::vec2 at(float u, float v) const { return {lo.x + u * (hi.x - lo.x), lo.y + v * (hi.y - lo.y)}; }
};

// A tick: where on its axis (in [0, 1]) and the value written there (tickText), or `text`.
struct AxisTick {
    float at, value;
    std::string text = {};
};

// Grid lines (none at 0) and values along both axes, the axes themselves, and their names:
// `outside` puts y's name above its axis and x's under the middle of its values (the figures);
// otherwise x's name stands at the end of its axis, above the line, and y has none (the screen's
// small plots).
void axes(PlotCanvas& canvas, const Box& box, const std::vector<AxisTick>& xTicks, const std::vector<AxisTick>& yTicks,
          const std::string& xName, const std::string& yName, bool outside);

// A log scale's marks of 2…9 times each decade below `outer`, innermost decade first: each one's
// radius in (0, 1) and its length (the 5× mark the longer).
struct DecadeMark {
    float radius, length;
};
std::vector<DecadeMark> decadeMarks(float outer, const PlotStyle& style);

} // namespace lab
