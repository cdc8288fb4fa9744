// plot_layout.h — the plots' arithmetic on screen, as pure functions: how the plots share the
// height (and width) of their window, where a lobe's half-disc sits in its canvas, the values of
// the rings and axis ticks, and how readout text wraps into lines.
//
// Lengths are in window units (ImGui's pixels); nothing here knows ImGui, fonts or the preset.
// ui/plots/plots.cpp measures its text and rows, asks these functions where things go, and draws.
// The rule they keep: whatever the area, the plots fit it — a plot that has no room is shown as a
// tab, never scrolled to.
#pragma once

#include <glm/vec2.hpp>

#include <array>
#include <functional>
#include <vector>

namespace lab {

//----------------------------------------------------------------------------------------
// Readout text: tokens that wrap into lines
//----------------------------------------------------------------------------------------

// A token's width, or kLineBreak to start a new line. Tokens are placed left to right, `gap`
// apart; one that does not fit on the current line starts the next (a token wider than the
// line still gets a line of its own). Each token's x and line; a break's place is its line's end.
inline constexpr float kLineBreak = -1.0f;
struct FlowPlace {
    float x = 0;
    int line = 0;
};
std::vector<FlowPlace> flowTokens(const std::vector<float>& tokenWidths, float gap, float width);
// How many lines the tokens take (0 for none).
int flowLines(const std::vector<float>& tokenWidths, float gap, float width);

//----------------------------------------------------------------------------------------
// Dividing the area among the three plots (lobe, incident angles overlaid, attenuation)
//----------------------------------------------------------------------------------------

inline constexpr int kPlotCount = 3;

// One plot, measured at a given width: rows of fixed height (readout strips, sliders, gaps)
// and a canvas that is useful from minCanvas up to maxCanvas and no taller; narrower than
// minWidth it is not worth showing beside the others.
struct PlotNeeds {
    float fixed = 0.0f;
    float minWidth = 0.0f;
    float minCanvas = 0.0f;
    float maxCanvas = 0.0f;
};

// Canvas heights for plots stacked in a column of height `height`, `gap` between plots: each
// gets its minimum, then what is left is shared in proportion to how far each is below its
// maximum, never past it; what is still left stays empty below. Empty when even the minimums
// do not fit.
std::vector<float> splitHeights(float height, float gap, const std::vector<PlotNeeds>& plots);

enum class PlotArrangement {
    OneColumn,    // lobe, overlay and attenuation from top to bottom
    TwoColumns,   // the lobe on the left; overlay above attenuation on the right
    ThreeColumns, // side by side
    Tabs,         // one plot at a time, chosen by a tab bar
};

struct PlotBox {
    float x = 0, y = 0, w = 0, h = 0; // the plot's block, relative to the area's top left
    float canvas = 0;                 // its canvas's height (the block's other rows are fixed)
};

struct PlotsLayout {
    PlotArrangement arrangement = PlotArrangement::Tabs;
    std::array<PlotBox, kPlotCount> plots; // under Tabs: each the whole area below the tab bar
};

// What plot 0, 1 or 2 needs at a given block width (the caller's measurements: its fixed rows
// can depend on the width, since readouts wrap).
using PlotMeasure = std::function<PlotNeeds(int plot, float width)>;

// The arrangement that gives the plots the most useful canvas (the lobe's counting double)
// among those where every plot gets at least its minimum; columns are `gap` apart, as are
// plots in a column. Tabs when none fits: the tab bar takes `tabBar`, and each plot the rest.
PlotsLayout arrangePlots(float width, float height, float gap, float tabBar, const PlotMeasure& measure);

//----------------------------------------------------------------------------------------
// The lobe's frame in its canvas
//----------------------------------------------------------------------------------------

// The room a polar plot keeps around its half-disc for labels.
struct PlotMargins {
    float left = 0, right = 0, top = 0, bottom = 0;
};

// The half-disc's centre (origin, on the surface line) and radius in a canvas at (x, y) of
// size w × h: the largest radius for which the disc and the margins fit both the width and the
// height, centred horizontally and vertically in the room left. Radius 0 when there is none.
struct LobeFrame {
    float originX = 0, originY = 0, radius = 0;
};
LobeFrame lobeFrame(float x, float y, float w, float h, const PlotMargins& margins);

//----------------------------------------------------------------------------------------
// Curves
//----------------------------------------------------------------------------------------

// The polyline with the points it does not need: every point left out lies within `tolerance`
// of the segment between the kept points around it (Douglas–Peucker), so at a tolerance well
// under a pixel the drawn line looks the same. The first and last points are always kept, and
// so are the extremes (a lobe's tip); a run of equal points (a lobe lying at the origin) keeps
// only its ends.
std::vector<glm::vec2> thinPolyline(const std::vector<glm::vec2>& points, float tolerance);

//----------------------------------------------------------------------------------------
// Axis values
//----------------------------------------------------------------------------------------

// The intensity of the outer circle: `current` (the largest total now) while unlocked; while
// locked, the value it had when the lock was turned on, so that a change shows its real size.
// `held` carries that value from frame to frame (0 to start).
float scaleMaximum(float current, bool locked, float& held);

// 1, 2, 2.5 or 5 times a power of ten: the smallest such step ≥ `rough` (> 0).
float niceStep(float rough);

// Ring (or tick) values for a linear axis from 0 to maxValue: multiples of a nice step in
// (0, maxValue], at most maxCount of them (at least one, maxValue itself when nothing nicer fits).
std::vector<float> linearTicks(float maxValue, int maxCount);

// The powers of ten in [maxValue·10^-decades, maxValue], largest first: the decade rings of
// a logarithmic axis whose outer circle is maxValue.
std::vector<float> decadeTicks(float maxValue, float decades);

} // namespace lab
