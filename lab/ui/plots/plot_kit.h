// plot_kit.h — what the plot files of lab/ui share beyond core/plots/plot_drawing.h (not a public
// API): the screen's style (the figures' geometry at the UI's scale, the current theme's palette
// (ui/theme_style.h), ImGui's text measure), a Figure painted onto ImGui's draw list, the layout sizes of widgets (Pens),
// readouts of coloured tokens that wrap into strips of their own, and canvases.
//
// A plot on screen is drawn as the figures are: shapes built with plot_drawing.h's vocabulary
// into a Figure (ScreenPlot), then painted. Only what has no figure (the 3D lobe's surface, the
// colour bar) goes straight to the draw list, in the same palette.
#pragma once

#include "ui/plots/plot_cache.h"
#include "ui/plots/plot_settings.h"

#include "core/plots/plot_drawing.h"
#include "core/plots/plot_layout.h"

#include <imgui.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lab::ui::plotkit {

//----------------------------------------------------------------------------------------
// Style, colours, painting
//----------------------------------------------------------------------------------------

// The figures' geometry scaled to this frame's font (so the plots grow with presenter mode), the
// current theme's palette, text measured by ImGui's font.
PlotStyle screenStyle();
// An ink of the current theme's palette, for ImGui.
ImU32 ink(Ink ink);
// The figure's shapes onto `dl`, in order, lines dashed as the figures dash them; its coordinates
// are screen pixels. Text is drawn with ImGui's font at each text's size (the UI font is DejaVu
// Sans, as the figures'). With `kept`, lines long or dashed are copied from an earlier frame's
// painting where it has the same line (plot_cache.h's PaintedLines), and kept when new.
void paint(ImDrawList* dl, const Figure& figure, PaintedLines* kept = nullptr);
// paint(), or the figure copied whole from an earlier frame's painting of the same figure in the same
// clip rectangle, font and atlas (plot_cache.h's PaintedLines): for what stays the same from frame to
// frame (a grid, arrows, an axis' labels); what changes every frame (a curve during a drag) would pay
// for keeping a painting never found again.
void paintWhole(ImDrawList* dl, const Figure& figure, PaintedLines& kept);
// Appends the bytes of each value to `out`: a description of what a drawing is made from, field by
// field (no padding bytes), for drawKept.
template <class... Values> void describe(std::string& out, const Values&... values) {
    (out.append(reinterpret_cast<const char*>(&values), sizeof values), ...);
}
// draw(), or a copy of an earlier frame's drawing of the same `description` (what draw() draws from,
// written by describe(); the clip rectangle, font and atlas are added here) kept in `kept`: for
// drawings that are not a Figure (a readout, the 3D lobe's map marks). The description must name
// everything the drawing depends on, or a copy would show what an earlier frame drew.
void drawKept(ImDrawList* dl, std::string& description, PaintedLines& kept, const std::function<void()>& draw);
// Solid polylines of one width and colour painted as a Figure's lines, kept by drawKept under
// `description` (where the points come from: what makes them the same), the width and the colour.
void drawKeptLines(ImDrawList* dl, std::string& description, const std::vector<std::vector<ImVec2>>& lines, float width,
                   FigureColor color, PaintedLines& kept);

// A plot on screen: a Figure drawn in the screen style, painted by paint(). Not copyable (the
// canvas refers to the figure and the style).
struct ScreenPlot {
    PlotStyle style = screenStyle();
    Figure figure;
    PlotCanvas canvas{figure, style};
    ScreenPlot() = default;
    ScreenPlot(const ScreenPlot&) = delete;
    ScreenPlot& operator=(const ScreenPlot&) = delete;
    void paint(ImDrawList* dl, PaintedLines* kept = nullptr) const { plotkit::paint(dl, figure, kept); }
    void paintWhole(ImDrawList* dl, PaintedLines& kept) const { plotkit::paintWhole(dl, figure, kept); }
};

// Sizes of this frame's widgets, all from the font size so that they grow with presenter mode.
struct Pens {
    float s;      // UI scale: font size / 13
    float font;   // font size
    float line;   // text line height
    float frame;  // a slider's height
    float gap;    // vertical space between rows (ImGui's item spacing)
    float gapX;   // horizontal space between items
    float inner;  // between a widget and its label
    float pad;    // text offset from what it labels
    float thin;   // grid
    float stroke; // curves and arrows
    float bold;   // the total and L
};
Pens pens();

ImVec2 textSize(const std::string& t);

// Copies the kept mesh into the draw list. A mesh that would take the list past 65536 vertices is
// left out rather than drawn wrong (the 3D lobe's and the slices stay under). `whitePixel`: every
// vertex has the white pixel's texture coordinate, written again where the atlas has moved it.
void drawMesh(ImDrawList* dl, const KeptMesh& mesh, bool whitePixel = true);
inline ImVec2 toImVec2(glm::vec2 v) { return ImVec2(v.x, v.y); }
inline glm::vec2 toVec2(ImVec2 v) { return glm::vec2(v.x, v.y); }

//----------------------------------------------------------------------------------------
// Readouts: coloured tokens that wrap, in a strip of their own above a canvas
//----------------------------------------------------------------------------------------

struct Token {
    std::string text;
    Ink ink = Ink::Text;
    bool swatch = false; // a short line in the colour before the text: the curve it names
    float width = kLineBreak;
};

struct Readout {
    std::vector<Token> tokens;
    std::vector<float> widths;

    void add(std::string text, Ink ink, bool swatch = false) { tokens.push_back({std::move(text), ink, swatch, 0.0f}); }
    void lineBreak() { tokens.push_back({}); }
    void measure(const Pens& p);
    float height(const Pens& p, float width) const;
    // With `kept`, copied from an earlier frame's painting of the same tokens at the same place
    // (plot_cache.h's PaintedLines) where there is one.
    void draw(ImDrawList* dl, const Pens& p, ImVec2 at, float width, PaintedLines* kept = nullptr) const;

private:
    void drawTokens(ImDrawList* dl, const Pens& p, ImVec2 at, float width) const; // of a flowed() readout
    // The tokens as they flow in `width`: this readout, or (into `scratch`) one whose tokens wider
    // than `width` are broken at their spaces into pieces that fit, so that they wrap instead of
    // running past the plots' side (presenter mode's font in a projector's narrow plots).
    const Readout& flowed(float width, Readout& scratch) const;
};

// What the outer circle stands for, in words (in tokens that can wrap), with a warning when a
// locked scale cuts a lobe.
void scaleTokens(Readout& r, float outer, float largest, bool locked, const char* what, Ink ink = Ink::Text);

//----------------------------------------------------------------------------------------
// Canvases
//----------------------------------------------------------------------------------------

struct Canvas {
    ImVec2 corner;
    float width = 0, height = 0;
    ImDrawList* dl = nullptr;
    bool shown() const { return dl != nullptr; }
    glm::vec2 origin() const { return toVec2(corner); }
};

// A plot's area at the cursor: an invisible button (for the mouse), filled with the plot
// background, registered in the widget map as `name`. Not drawn when it has no room.
Canvas beginCanvas(const char* id, const char* name, float width, float height);

// Where a block's canvas and controls go. Normally the readout is a strip above the canvas and
// the controls a row below it. When even one plot at a time leaves the canvas too short (a low
// band at a large UI scale), the readout moves to a column at the right of the canvas instead.
struct Block {
    ImVec2 canvas;
    float canvasW = 0, canvasH = 0;
    ImVec2 controls;
    bool controlsFit = true; // false where the row would reach past the block: it is left out
};
// The block's readout drawn into its strip (registered as `readoutMark`), the cursor at the canvas.
// `box` in the area at `origin`; `cramped`: a low band; `controls`: a row of controls below.
Block placeBlock(const PlotBox& box, ImVec2 origin, const Pens& p, const Readout& r, const char* readoutMark,
                 bool cramped, bool controls, float minCanvas, const std::function<float(float)>& maxCanvas,
                 PaintedLines* kept = nullptr);

// A Cartesian plot's box in a canvas: room for the values left of the y axis (`yLabel` the widest)
// and under the x axis, half of the last x value (`xLabel`) right of the box. Nullopt when too small.
std::optional<Box> canvasBox(const Canvas& c, const PlotStyle& style, const std::string& yLabel, const std::string& xLabel);

// Where a curve's unit points go in a polar plot (plot_cache.h).
inline CurvePlacement placementOf(const Polar& p) { return {true, p.origin, {p.radius, -p.radius}}; }
inline CurvePlacement placementOf(const Box& b) { return {false, b.lo, b.hi - b.lo}; }

} // namespace lab::ui::plotkit
