// plots_slice.h — the plots window's Slice view: the BRDF as an image over the half angle θh
// (across, 0° left … 90° right) and the difference angle θd (up, 0° at the bottom) at φd = 90°
// (core/plots/slice.h, Rusinkiewicz 1998, as Disney's BRDF Explorer shows it).
//
//   * the image of the chosen component (diffuse, specular or total) in the view's palette
//     (DisplaySettings::palette: viridis or grey), linear or log as the plane plots (PlotSettings::scale),
//     with a legend bar: its values at the ends and the middle, and what it shows;
//   * a marker at the plane plot's (θh, θd) = (|θo − θi|/2, |θi + θo|/2): filled where that is on this
//     slice (θo = θi), hollow and labelled "off this slice" otherwise (in-plane L and V have φd 0° or 180°);
//   * the readout: under the pointer θh, θd, the exact value (sliceValue) and L and V; the marker's angles;
//   * compare mode: B's image beside A's at the same scale (the larger maximum), and A − B in a
//     diverging palette (divergingColor) with a signed legend; where three images do not fit, a
//     selector shows "A | B" or "A − B".
// The images are computed once per material, BRDF and term switches (91 × 91 = 8281 values, kept in
// SliceState), their vertices once per view (inputs, component, scale, palette and where they lie), so
// a frame in which nothing changed copies them. While the inputs change frame after frame (a slider
// dragged: ui/plots/plot_cache.h's ChangeWatch) the view draws a coarse image (every 5°, 19 × 19) that
// lags like the albedo — the inputs of at most 0.5 s ago, its legend's numbers muted — and owes the app
// a frame: the first frame after the change draws the full one. The image does not depend
// on the incident angle or on plots at the probe (only the marker follows the plane plot's θi and V).
// What it does not do: call GL (ImGui draw lists only), or scroll (it fits the region it is given).
#pragma once

#include "core/plots/plot_data.h"
#include "core/plots/slice.h"
#include "core/scene/preset.h"
#include "core/scene/view_mode.h"
#include "ui/plots/plot_cache.h"

#include <imgui.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace lab::ui {

struct PlotSettings;

// The coarse image's step while the inputs change (19 × 19 samples).
inline constexpr int kSliceCoarseStepDeg = 5;

// Where three images do not fit (compare mode in a small region): which the view shows.
enum class SliceCompare { Both, Difference };

// The colour of each sample of `values` (index row·side + column, as SliceImage keeps them): the
// palette at plotRadius(value, outer, scale), outer = outerRing(largest) — linear value / largest, or
// the plots' 3-decade log position. What the image draws at its vertices (tested).
std::vector<ImU32> sliceColors(const std::vector<float>& values, float largest, RadialScale scale, ValuePalette palette);
// A − B's: divergingColor(value / largest |A − B|); 0 (near-white) everywhere when A and B agree.
std::vector<ImU32> differenceColors(const std::vector<float>& values, float largestAbs,
                                    RadialScale scale = RadialScale::Linear);
// The largest |value| (0 for none).
float largestMagnitude(const std::vector<float>& values);

// One frame's images, as kept: the vertices of each image's samples (their colours from sliceColors or
// differenceColors) and the triangles between them.
using SliceMesh = KeptMesh;

struct SliceKey {
    LobeInputs a, b; // the surfaces (the incident angle left at 0: the image does not depend on it)
    bool hasB = false, coarse = false;
    PlotComponent component = PlotComponent::Specular;
    RadialScale scale = RadialScale::Linear;
    ValuePalette palette = ValuePalette::Viridis;
    std::array<ImVec4, 3> rects{}; // x, y, w, h of A's, B's and A − B's images (w 0: not drawn)
};
bool operator==(const SliceKey& x, const SliceKey& y);

struct SliceState {
    PlotComponent component = PlotComponent::Specular;
    SliceCompare compare = SliceCompare::Both;
    // An image by its surface and whether it is the coarse one: A's and B's, full and coarse.
    using ImageKey = std::pair<LobeInputs, bool>;
    RecentlyUsed<ImageKey, SliceImage> images{6};
    RecentlyUsed<std::pair<ImageKey, ImageKey>, SliceImage> differences{2};
    RecentlyUsed<SliceKey, SliceMesh> meshes{2};
    ChangeWatch watchA, watchB; // whether A's and B's inputs are in a change (the coarse image then)
    // During a change, the inputs A's and B's coarse images show (B's: with a compare set, draftHasB).
    LaggingDraft<std::array<LobeInputs, 2>> draft;
    bool draftHasB = false;
    // The readout strip's height (slice_parts.h readoutHeight: two readouts written and measured) for
    // the latest inputs it was asked for, at up to two widths a frame (whether three images fit, the view),
    // full or brief (slice_parts.h placeReadout).
    struct ReadoutHeight {
        bool made = false, hasB = false, brief = false;
        LobeInputs a, b;
        PlotComponent component = PlotComponent::Specular;
        float markerH = 0.0f, markerD = 0.0f;
        bool onSlice = false;
        float incidentDeg = 0.0f, viewerDeg = 0.0f, font = 0.0f, width = 0.0f;
        float height = 0.0f;
    };
    std::array<ReadoutHeight, 4> readoutHeights;
    // The scales of the images last drawn (each a scan of 8,281 values), found again while the images
    // and the component stay the same.
    struct Scales {
        std::shared_ptr<const SliceImage> a, b, difference;
        PlotComponent component = PlotComponent::Specular;
        float largest = 0.0f, largestDifference = 0.0f;
    };
    Scales scales;
    // How many images and meshes were computed rather than found (for the tests).
    std::size_t computed() const { return images.made() + differences.made() + meshes.made(); }
};

// Draws the Slice view into the current window's remaining content region (in settings.palette).
void slicePanel(const Preset& a, const Preset* b, PlotSettings& settings);

} // namespace lab::ui
