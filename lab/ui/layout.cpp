// layout.cpp — the window's arithmetic.
#include "ui/layout.h"

#include <algorithm>

namespace lab::ui {

const char* toString(PanelTab tab) {
    switch (tab) {
    case PanelTab::Model: return "Model";
    case PanelTab::Material: return "Material";
    case PanelTab::Lights: return "Lights";
    case PanelTab::Plots: return "Plots";
    }
    return "?";
}

bool isCompact(float width, float height) { return width < height || width < 640.0f; }

namespace {

// The model on top (at most as tall as it is wide, at least 45% of the height when the tabs have
// the rest), the tab row, the tab's contents.
Layout compactLayout(const LayoutInput& in) {
    const float s = in.uiScale, W = in.width, H = in.height;
    Layout l;
    l.compact = true;
    l.tab = in.showPanel ? in.tab : PanelTab::Plots;
    if (!in.showPanel && !in.showPlots) {
        l.viewport = {0, 0, W, H};
        return l;
    }
    float tabsH = in.showPanel ? 36.0f * s : 0.0f;
    float viewH = std::clamp(std::min(H * 0.45f, W), std::min(120.0f, H * 0.3f), H * 0.6f);
    l.viewport = {0, 0, W, viewH};
    l.tabs = in.showPanel ? Rect{0, viewH, W, tabsH} : Rect{};
    Rect contents{0, viewH + tabsH, W, std::max(H - viewH - tabsH, 1.0f)};
    if (l.tab == PanelTab::Plots) {
        l.plots = contents;
        l.plotsBelow = true;
    } else {
        l.panel = contents;
    }
    return l;
}

void splitForCompare(Layout& l) {
    const Rect& v = l.viewport;
    l.compareStacked = v.w * 0.5f < v.h * 0.8f;
    if (l.compareStacked) {
        l.halves[0] = {v.x, v.y, v.w, v.h * 0.5f};
        l.halves[1] = {v.x, v.y + v.h * 0.5f, v.w, v.h * 0.5f};
    } else {
        l.halves[0] = {v.x, v.y, v.w * 0.5f, v.h};
        l.halves[1] = {v.x + v.w * 0.5f, v.y, v.w * 0.5f, v.h};
    }
}

} // namespace

// The panels' widths grow with the UI scale up to a third of the window each; the plots stay
// beside the model while the model keeps at least 240 units and 0.4 of the window's height.
Layout computeLayout(const LayoutInput& in) {
    const float s = in.uiScale, W = in.width, H = in.height;
    if (isCompact(W, H)) {
        Layout l = compactLayout(in);
        l.viewport.w = std::max(l.viewport.w, 1.0f);
        l.viewport.h = std::max(l.viewport.h, 1.0f);
        splitForCompare(l);
        return l;
    }
    Layout l;
    float panelW = in.showPanel ? std::min(360.0f * s, W * 0.34f) : 0.0f;
    // Without the control panel the plots may take more of the width (presenter mode on a projector).
    float plotsW = in.showPlots ? std::min(380.0f * s, W * (in.showPanel ? 0.34f : 0.45f)) : 0.0f;
    float besideW = W - panelW - plotsW;
    l.plotsBelow = in.showPlots && besideW < std::max(240.0f, H * 0.4f);
    if (in.showPanel) {
        l.panel = {0, 0, panelW, H};
    }
    if (!in.showPlots) {
        l.viewport = {panelW, 0, W - panelW, H};
    } else if (l.plotsBelow) {
        float plotsH = std::max(H * 0.42f, 200.0f);
        l.viewport = {panelW, 0, W - panelW, H - plotsH};
        l.plots = {panelW, H - plotsH, W - panelW, plotsH};
    } else {
        l.viewport = {panelW, 0, besideW, H};
        l.plots = {W - plotsW, 0, plotsW, H};
    }
    l.viewport.w = std::max(l.viewport.w, 1.0f);
    l.viewport.h = std::max(l.viewport.h, 1.0f);
    splitForCompare(l);
    return l;
}

} // namespace lab::ui
