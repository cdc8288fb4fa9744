// layout.cpp — the window's arithmetic.
#include "ui/layout.h"

#include <algorithm>

namespace lab::ui {

Layout computeLayout(const LayoutInput& in) {
    const float s = in.uiScale, W = in.width, H = in.height;
    Layout l;
    if (!in.showPanels) {
        l.view = {0, 0, W, H};
    } else {
        float panelW = std::min(360.0f * s, W * 0.4f);
        float plotsW = std::min(380.0f * s, W * 0.35f);
        l.panel = {0, 0, panelW, H};
        l.plotsBelow = W - panelW - plotsW < 420.0f * s;
        if (l.plotsBelow) {
            float plotsH = std::max(H * 0.42f, 200.0f);
            l.view = {panelW, 0, W - panelW, H - plotsH};
            l.plots = {panelW, H - plotsH, W - panelW, plotsH};
        } else {
            l.view = {panelW, 0, W - panelW - plotsW, H};
            l.plots = {W - plotsW, 0, plotsW, H};
        }
    }
    l.view.w = std::max(l.view.w, 1.0f);
    l.view.h = std::max(l.view.h, 1.0f);
    const Rect& v = l.view;
    l.compareStacked = v.w * 0.5f < v.h * 0.8f;
    if (l.compareStacked) {
        l.viewA = {v.x, v.y, v.w, v.h * 0.5f};
        l.viewB = {v.x, v.y + v.h * 0.5f, v.w, v.h * 0.5f};
    } else {
        l.viewA = {v.x, v.y, v.w * 0.5f, v.h};
        l.viewB = {v.x + v.w * 0.5f, v.y, v.w * 0.5f, v.h};
    }
    return l;
}

} // namespace lab::ui
