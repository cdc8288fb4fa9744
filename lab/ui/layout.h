// layout.h — where the panel, the plots and the 3D view go in the window: a pure function.
//
// Window units (ImGui's). The panel is on the left; the plots on the right whenever the model still
// has room beside them (presenter mode included), below the view only on narrow or portrait
// windows; the view takes the rest and grows with the window. Either panel may be hidden. In compare mode the
// view is split in two: side by side, or A above B where halves side by side would be narrow
// (the field of view is vertical, so a narrow half would crop the model). No ImGui here.
#pragma once

namespace lab::ui {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

struct LayoutInput {
    float width = 0, height = 0; // the window
    float uiScale = 1.0f;        // font size / 13: the panels grow with the UI
    bool showPanel = true;       // the control panel
    bool showPlots = true;       // the plots
};

struct Layout {
    Rect panel, plots;  // empty when hidden
    Rect view;          // the 3D view (never empty)
    Rect viewA, viewB;  // its halves in compare mode
    bool plotsBelow = false;
    bool compareStacked = false; // A above B rather than beside it
};

Layout computeLayout(const LayoutInput& input);

} // namespace lab::ui
