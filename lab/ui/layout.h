// layout.h — where the panel, the plots and the model's viewport go in the window: a pure function.
//
// Window units (ImGui's). The panel is on the left; the plots on the right whenever the model still
// has room beside them (presenter mode included), below the view only on narrow or portrait
// windows; the view takes the rest and grows with the window. Either panel may be hidden. In compare mode the
// view is split in two: side by side, or A above B where halves side by side would be narrow
// (the field of view is vertical, so a narrow half would crop the model).
//
// Phones, tablets in portrait and narrow windows get the compact layout instead: the model on
// top across the whole width, then a row of tabs (Model · Material · Lights · Plots) and below it
// the chosen tab's contents, the plots by default. No ImGui here.
#pragma once

#include <array>

namespace lab::ui {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

// The compact layout's tabs, in the order they are shown: the control panel in three parts and
// the plots.
enum class PanelTab { Model, Material, Lights, Plots };
inline constexpr PanelTab kPanelTabs[] = {PanelTab::Model, PanelTab::Material, PanelTab::Lights, PanelTab::Plots};
const char* toString(PanelTab tab);

struct LayoutInput {
    float width = 0, height = 0; // the window
    float uiScale = 1.0f;        // font size / 13: the panels grow with the UI
    bool showPanel = true;       // the control panel
    bool showPlots = true;       // the plots
    PanelTab tab = PanelTab::Plots; // the compact layout's chosen tab
};

struct Layout {
    Rect panel, plots;  // empty when hidden
    Rect viewport;      // where the model is shown (never empty)
    std::array<Rect, 2> halves; // in compare mode, the viewport's halves: A's and B's
    bool plotsBelow = false;
    bool compareStacked = false; // A above B rather than beside it
    // Compact: the view on top, then the tab row (`tabs`, empty when the control panel is
    // hidden), then the chosen tab's contents in `panel` (Model, Material, Lights) or `plots`.
    bool compact = false;
    Rect tabs;
    PanelTab tab = PanelTab::Plots; // what `panel` or `plots` holds in the compact layout

    // Where side `side` (0: A, 1: B) is shown: its half in compare mode, else the viewport.
    const Rect& viewportOf(int side, bool compare) const { return compare ? halves[static_cast<std::size_t>(side)] : viewport; }
};

// Phones, portrait tablets and narrow windows: taller than wide, or narrower than 640 units
// (whatever the UI's scale: a projector at presenter scale keeps its columns).
bool isCompact(float width, float height);

Layout computeLayout(const LayoutInput& input);

} // namespace lab::ui
