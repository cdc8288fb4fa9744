// layout.cpp — the window's arithmetic.
#include "ui/layout.h"

#include <algorithm>
#include <cmath>

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
    if (l.compareStacked) { // (whole units: the halves meet on a pixel's edge)
        float h = std::floor(v.h * 0.5f);
        l.halves[0] = {v.x, v.y, v.w, h};
        l.halves[1] = {v.x, v.y + h, v.w, v.h - h};
    } else {
        float w = std::floor(v.w * 0.5f);
        l.halves[0] = {v.x, v.y, w, v.h};
        l.halves[1] = {v.x + w, v.y, v.w - w, v.h};
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
        l.view = l.viewport;
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
    l.view = l.viewport;
    splitForCompare(l);
    return l;
}

void placeText(Layout& l, const TextRoom& room) {
    const Rect v = l.view;
    // At most a quarter of the view's height each for the header and the footer strips; the rest is the model's.
    // Whole units, so that the strips and the model's viewport meet on a pixel's edge.
    float header = std::ceil(std::min(room.header, v.h * 0.25f)), footer = std::ceil(std::min(room.footer, v.h * 0.25f));
    l.header = {v.x, v.y, v.w, header};
    l.footer = {v.x, v.y + v.h - footer, v.w, footer};
    // The legend above the footer, where the model leaves room for it (at most a quarter again).
    float legend = std::ceil(std::min(room.legend, std::max(v.h * 0.25f, 0.0f)));
    l.legend = legend > 0.0f ? Rect{v.x, v.y + v.h - footer - legend, v.w, legend} : Rect{};
    Rect model{v.x, v.y + header, v.w, std::max(v.h - header - footer - legend, 1.0f)};
    l.caption = l.captionBand = {};
    if (room.captionHeight) {
        // Across the top, under the header...
        float topW = std::min(room.captionWidth, v.w);
        float topH = std::ceil(std::min(room.captionHeight(topW), model.h * 0.5f));
        Rect top{model.x, model.y + topH, model.w, std::max(model.h - topH, 1.0f)};
        // ... or as a column at the left, when that leaves the model the larger narrower side.
        float sideW = std::ceil(std::min(room.sideWidth, v.w * 0.4f));
        float sideH = room.captionHeight(sideW);
        Rect side{model.x + sideW, model.y, std::max(model.w - sideW, 1.0f), model.h};
        auto narrower = [](const Rect& r) { return std::min(r.w, r.h); };
        if (sideH <= model.h && narrower(side) > narrower(top)) {
            l.caption = {model.x, model.y, sideW, sideH};
            l.captionBand = {model.x, model.y, sideW, model.h};
            model = side;
        } else {
            l.caption = {model.x, model.y, topW, topH};
            l.captionBand = {model.x, model.y, model.w, topH};
            model = top;
        }
    }
    l.viewport = model;
    splitForCompare(l);
    l.labels = {};
    if (room.label > 0.0f) {
        for (std::size_t i = 0; i < 2; ++i) {
            Rect& half = l.halves[i];
            float label = std::ceil(std::clamp(room.label, 0.0f, half.h - 1.0f));
            l.labels[i] = {half.x, half.y, half.w, label};
            half = {half.x, half.y + label, half.w, std::max(half.h - label, 1.0f)};
        }
    }
}

} // namespace lab::ui
