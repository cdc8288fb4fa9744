// slice_parts.h — what the Slice view (ui/plots/plots_slice.h) draws around its images: where the
// images and legends go, the readout, each image's axes, the marker and the legends. Not a public
// API: plots_slice.cpp is its only user; the images themselves (cache, vertices) are there.
#pragma once

#include "ui/plots/plot_kit.h"
#include "ui/plots/plots_slice.h"

#include "core/plots/slice.h"

#include <imgui.h>

#include <array>
#include <memory>
#include <string>

namespace lab::ui::slice {

// One frame's images: A's, and in compare mode B's and A − B, all full or all coarse.
struct Images {
    LobeInputs inA, inB;         // this frame's surfaces (the readout's exact values)
    LobeInputs imageA, imageB;   // the images': the same, or during a change a lagging draft's (plots_slice.cpp)
    std::shared_ptr<const SliceImage> a, b, difference;
    bool coarse = false;
    float largest = 0.0f;           // the component's, of A and B: the value images' common scale
    float largestDifference = 0.0f; // the largest |A − B| of the component
};

// Which images a frame shows: A alone; in compare mode all three, or where they do not fit A | B or A − B.
enum class Shown { A, AB, All, Difference };
// Whether image i (0 A, 1 B, 2 A − B) is shown, and whether the value and the difference legends are.
bool showsImage(Shown shown, int i);
bool showsValueLegend(Shown shown);
bool showsDifferenceLegend(Shown shown);

// Where things go (x, y, w, h; w 0: not there): the images' canvas, each image's square, the legends.
struct Layout {
    ImVec4 area{0, 0, 0, 0};
    std::array<ImVec4, 3> images{};
    ImVec4 valueLegend{0, 0, 0, 0}, differenceLegend{0, 0, 0, 0};
};
// The images in a grid (one row, one column or two by two: whichever gives the largest side) at the
// top of `region`, each with room for its axes' labels and title, and the legends under them.
Layout arrangeImages(const ImVec4& region, Shown shown, const plotkit::Pens& p);
// Whether all three compare images fit `region` at a readable size (else the view offers a choice).
bool threeFit(const ImVec4& region, const plotkit::Pens& p);

struct Frame {
    Images images;
    PlotComponent component = PlotComponent::Specular;
    SliceMarker marker;
    float incidentDeg = 0.0f, viewerDeg = 0.0f; // the plane plot's θi and V
    Shown shown = Shown::A;
    Layout layout;
    SliceState* state = nullptr; // where readoutHeight keeps what it measured (none: measured each time)
    bool brief = false;          // the readout without its explanations (placeReadout: where the images need the room)
};

// What the pointer is over: an image (-1 none) and the angles there (to 0.1°).
struct Hover {
    int image = -1;
    float thetaHDeg = 0.0f, thetaDDeg = 0.0f;
};
Hover hoverOf(const Layout& layout);

// The readout: under the pointer θh, θd, the exact values (sliceValue), L and V; else what to do; and
// where the plane plot's marker is. Its strip is as high as the higher of the two, so that nothing
// moves as the pointer comes and goes. A brief one (f.brief) leaves out what the angles are and why
// the marker is off the slice.
plotkit::Readout readout(const Frame& f, const Hover& hover, const plotkit::Pens& p);
float readoutHeight(const Frame& f, const plotkit::Pens& p, float width);

// Where the readout and the images go in the region at `origin`: the readout a strip above the images,
// in a low band a column at their right. Where the strip would leave the images (f.shown) too little
// room (fewer than 12 lines, or a side under 3 em), the readout is brief; where even that is too high,
// it keeps only the whole lines that leave them the room (its first: what is under the pointer), and
// says so (`cut`: the view marks "clipped:plot.slice.readout"). In a column too narrow for such
// images whatever the strip, the readout keeps the whole lines that leave 12.
struct Placement {
    ImVec4 strip{0, 0, 0, 0}, images{0, 0, 0, 0};
    bool brief = false, cut = false;
};
Placement placeReadout(const Frame& f, ImVec2 origin, ImVec2 room, const plotkit::Pens& p);

// An image's axes (θh across, θd up, their degrees and names) and its title, into `plot`.
void imageAxes(plotkit::ScreenPlot& plot, const ImVec4& r, const std::string& title);
// The plane plot's point on an image: filled on this slice, hollow and labelled "off this slice" otherwise.
void drawMarker(ImDrawList* dl, const plotkit::Pens& p, const ImVec4& r, const SliceMarker& marker);
// The legends the frame shows, in its layout's rectangles.
void drawLegends(ImDrawList* dl, const plotkit::Pens& p, const Frame& f, RadialScale scale, ValuePalette palette);

const char* componentName(PlotComponent c);
Ink componentInk(PlotComponent c);

} // namespace lab::ui::slice
