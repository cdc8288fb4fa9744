// plots.cpp — the plots window: the views' selector, and the chosen view drawn below it (the
// Plane view, plots_plane.cpp; the 3D lobe, plots_3d.cpp; Energy, plots_energy.cpp; Slice, plots_slice.cpp).
#include "ui/plots/plots.h"
#include "ui/plots/plots_energy.h"
#include "ui/plots/plots_plane.h"
#include "ui/plots/plots_slice.h"

#include "ui/widgets.h"

#include <imgui.h>

#include <algorithm>
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
    // Tabs keep their whole names where the row is short of room (presenter mode on a projector):
    // their text is drawn smaller (down to 0.7), not shortened to "3D l..." as ImGui would.
    float names = 0.0f;
    for (const ViewEntry& v : kViews) {
        names += ImGui::CalcTextSize(v.name).x + 2.0f * thin.x + ImGui::GetStyle().ItemInnerSpacing.x;
    }
    const float tabScale = std::clamp(ImGui::GetContentRegionAvail().x / std::max(names * 1.05f, 1.0f), 0.7f, 1.0f);
    ImGui::SetWindowFontScale(tabScale);
    if (!ImGui::BeginTabBar("plots.view")) {
        ImGui::SetWindowFontScale(1.0f);
        ImGui::PopStyleVar();
        return;
    }
    // A view chosen from outside (a test, the first frame) is selected until its tab opens; after
    // that the tabs decide.
    const bool pending = s.shownView != static_cast<int>(s.view);
    for (const ViewEntry& v : kViews) {
        const bool select = pending && s.view == v.view;
        ImGui::SetWindowFontScale(tabScale);
        const bool open = ImGui::BeginTabItem(v.name, nullptr, select ? ImGuiTabItemFlags_SetSelected : 0);
        mark(v.mark);
        if (ImGui::GetItemRectSize().x + 1.0f < ImGui::CalcTextSize(v.name).x + 2.0f * thin.x) { // a name shortened: cut
            widgets().set(std::string("clipped:") + v.mark, {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                                                             ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y});
        }
        ImGui::SetWindowFontScale(1.0f);
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
