// plots.cpp — the plots window: the views' selector, and the chosen view drawn below it (the
// Plane view, plots_plane.cpp; the 3D lobe, plots_3d.cpp; Energy, plots_energy.cpp; Slice, plots_slice.cpp).
#include "ui/plots/plots.h"
#include "ui/plots/plots_energy.h"
#include "ui/plots/plots_plane.h"
#include "ui/plots/plots_slice.h"

#include "ui/widgets.h"

#include <imgui.h>

#include <cmath>

namespace lab::ui {

namespace {

// The views in the selector's order: a further view is its PlotTab and one line here.
struct ViewEntry {
    PlotTab view;
    const char* name;
    const char* mark;
    void (*draw)(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe, const ProbeLobe* point);
};
const ViewEntry kViews[] = {
    {PlotTab::Plane, "Plane", "plot.view.plane", planeView},
    {PlotTab::Lobe3d, "3D lobe", "plot.view.lobe3d",
     [](Preset& a, const Preset* b, PlotSettings& s, const ProbeResult*, const ProbeLobe* point) { lobe3dPanel(a, b, s, point); }},
    {PlotTab::Energy, "Energy", "plot.view.energy",
     [](Preset& a, const Preset* b, PlotSettings& s, const ProbeResult*, const ProbeLobe*) { energyPanel(a, b, s); }},
    {PlotTab::Slice, "Slice", "plot.view.slice",
     [](Preset& a, const Preset* b, PlotSettings& s, const ProbeResult*, const ProbeLobe*) { slicePanel(a, b, s); }},
};

static_assert(std::size(kViews) == std::size(kPlotTabNames), "a plots tab without its name in display.plots, or one too many");

} // namespace

std::optional<PlotTab> plotTabNamed(std::string_view name) {
    for (std::size_t i = 0; i < std::size(kPlotTabNames); ++i) {
        if (kPlotTabNames[i] == name) {
            return kViews[i].view;
        }
    }
    return std::nullopt;
}

void plotsPanel(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe, const ProbeLobe* point) {
    // A change in progress is not over while the pointer holds the widget making it (PlotCache).
    s.cache.beginFrame(ImGui::IsMouseDown(ImGuiMouseButton_Left) && ImGui::IsAnyItemActive());
    // The selector's row as low as the text allows (a row less for the views below it): thinner
    // tabs, the views' own widgets at the usual padding.
    const ImVec2 padding = ImGui::GetStyle().FramePadding;
    const ImVec2 thin(padding.x, std::floor(padding.y * 0.35f));
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, thin);
    if (!ImGui::BeginTabBar("plots.view")) {
        ImGui::PopStyleVar();
        return;
    }
    // A view chosen from outside (a test, the first frame) is selected until its tab opens; after
    // that the tabs decide.
    const bool pending = s.shownView != static_cast<int>(s.view);
    for (const ViewEntry& v : kViews) {
        const bool select = pending && s.view == v.view;
        const bool open = ImGui::BeginTabItem(v.name, nullptr, select ? ImGuiTabItemFlags_SetSelected : 0);
        mark(v.mark);
        if (open) {
            ImGui::PopStyleVar();
            if (!pending) {
                s.view = v.view;
            }
            s.shownView = static_cast<int>(v.view);
            v.draw(a, b, s, probe, point);
            ImGui::EndTabItem();
            ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, thin);
        }
    }
    ImGui::EndTabBar();
    ImGui::PopStyleVar();
}

} // namespace lab::ui
