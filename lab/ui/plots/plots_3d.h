// plots_3d.h — the plots window's "3D lobe" view: the reflected intensity for the current L over
// the whole hemisphere, as a surface (radius = intensity, like BRDF Explorer) and as a map seen
// from above.
//
//   * the surface of core/plots/lobe3d.h's grid (θo by 1°, φ by 4°) for the chosen component (diffuse,
//     specular or total), coloured by intensity and shaded, drawn back to front (painter's
//     algorithm) over the surface plane's disc grid, with N, L, R, V and H as arrows and the peak
//     marked; the compare set B as a wireframe over it, at the same scale;
//   * an orbit camera of its own (orthographic, drag to orbit: yaw about N, elevation 0° to 90°;
//     at 0°/0° it looks along the plane plot's view, R to the right);
//   * the intensity map: the same values as a disc seen from above (θo as the radius, the plane
//     of incidence as the horizontal axis, R's side to the right), with its colour legend.
// The numbers come from core/plots/lobe3d.h (the same lighting function as the plane plots, whose
// samples it reproduces in the plane of incidence). The grid is computed once per LobeInputs and
// the projected, sorted mesh once per view (inputs, component, scale, camera and canvas), both
// kept in Lobe3dState's cache with the peak: a frame in which nothing changed copies the kept
// mesh (the surface and the map are 8,281 vertices each: ImGui's 16-bit indices have room). While
// the inputs change (a drag: ui/plots/plot_cache.h's ChangeWatch), the view draws the coarse grid
// (kLobeCoarseGrid, 589 samples) and its peak, the numbers muted, lagging like the albedo (the inputs
// of at most 0.5 s ago), and owes the app a frame: the first frame after the change draws the full grid. What it does not do: call GL
// (ImGui draw lists only), or scroll (it fits the region it is given).
#pragma once

#include "core/plots/lobe3d.h"
#include "core/plots/plot_data.h"
#include "core/plots/probe_lobe.h"
#include "core/scene/preset.h"
#include "ui/plots/plot_cache.h"

#include <imgui.h>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace lab::ui {

struct PlotSettings;

// A projected, sorted mesh as the draw list takes it (plot_cache.h's KeptMesh), triangles far to near;
// the map's; and B's wireframe polylines.
struct Lobe3dMesh {
    KeptMesh surface; // its triangles far to near
    KeptMesh map;
    std::vector<std::vector<ImVec2>> rings;     // the surface plane's
    std::vector<std::vector<ImVec2>> wireframe; // B
    std::uint64_t serial = 0; // which mesh this is, never another's (B's wireframe is kept as painted by it)
};

struct Lobe3dKey {
    LobeInputs a, b;
    bool hasB = false;
    bool coarseA = false, coarseB = false; // drawn from the coarse grids
    PlotComponent component = PlotComponent::Total;
    RadialScale scale = RadialScale::Linear;
    float outer = 1.0f;
    float yawDeg = 0.0f, pitchDeg = 0.0f;
    ImVec4 lobeRect, mapRect; // x, y, w, h of the two canvases' drawing areas
};
bool operator==(const Lobe3dKey& x, const Lobe3dKey& y);

struct Lobe3dState {
    float yawDeg = -35.0f;  // about N, from the plane plot's view (camera on +z)
    float pitchDeg = 25.0f; // above the surface, 0 to 90
    PlotComponent component = PlotComponent::Total;
    // A grid by its inputs and whether it is the coarse one: A's and B's, full and coarse.
    using GridKey = std::pair<LobeInputs, bool>;
    RecentlyUsed<GridKey, HemisphereGrid> grids{6};
    RecentlyUsed<Lobe3dKey, Lobe3dMesh> meshes{2};
    RecentlyUsed<std::pair<GridKey, PlotComponent>, LobeMaximum> peaks{2}; // A's, for the readout
    ChangeWatch watchA, watchB; // whether A's and B's inputs are in a change (a coarse plot then)
    // The inputs A's and B's coarse grids show during a change: drafted again ten times a second (the
    // 3D lobe is its tab's picture, and a drag should move it; a draft costs about 0.15 ms).
    static constexpr double kDraftSeconds = 0.1;
    LaggingDraft<LobeInputs> draftA{kDraftSeconds}, draftB{kDraftSeconds};
    // The largest value of the grids last drawn (a scan of 8,281 values each), found again while the
    // grids and the component stay the same.
    struct Largest {
        std::shared_ptr<const HemisphereGrid> a, b;
        PlotComponent component = PlotComponent::Total;
        float value = 0.0f;
    };
    Largest largest;
    // How many grids, meshes and peaks were computed rather than found (for the tests).
    std::size_t computed() const { return grids.made() + meshes.made() + peaks.made(); }
};

// Draws the 3D lobe view into the current window's remaining content region; at the probed point
// `point` when given (plots at the probe, ui/plots/plots.h: its θi, arriving light and real V).
void lobe3dPanel(const Preset& a, const Preset* b, PlotSettings& settings, const ProbeLobe* point = nullptr);

} // namespace lab::ui
