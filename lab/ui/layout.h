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
#include <functional>

namespace lab::ui {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
    bool overlaps(const Rect& o) const { return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h; }
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
    Rect view;          // the 3D view: the model's viewport and the text around it (placeText)
    Rect viewport;      // where the model is shown (never empty): the view less its text
    std::array<Rect, 2> halves; // in compare mode, the viewport's halves: A's and B's, under their labels
    // The view's text, each in a place of its own that the model's viewport does not cover
    // (empty when there is none): the header strip at the top, the caption (a strip under the
    // header or a column at the view's left, whichever leaves the model more room), the footer
    // strip at the bottom (toasts, the frame time) and, in compare mode, each half's label.
    Rect header, caption, footer;
    Rect legend;                // a value view's legend (ui/viewport/view_legend.h), above the footer; empty without
    Rect captionBand;           // the caption's strip (across the view) or column (down to the footer)
    std::array<Rect, 2> labels;
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

// The view and the model's viewport are the same rectangle until placeText() carves the text's
// places out of it.
Layout computeLayout(const LayoutInput& input);

// What the view's text needs (window units; ui/viewport/viewport.h measures it with the font).
struct TextRoom {
    float header = 0;   // the header strip's height
    float footer = 0;   // the footer strip's height
    float legend = 0;   // a value view's legend strip, above the footer (0: none)
    float label = 0;    // each compare half's label strip (0 outside compare mode)
    // The caption's height when it is `width` wide (wrapped), and the widths it may take: at most
    // `captionWidth` across the top, `sideWidth` as a column. No function: no caption.
    std::function<float(float width)> captionHeight;
    float captionWidth = 0, sideWidth = 0;
};

// Carves the text's places out of `layout.view` (see Layout): the header at the top, the
// footer at the bottom, the caption where the model keeps the larger narrower side, and
// re-splits the rest, the model's viewport, for compare mode with each half's label on top.
// The model's viewport keeps at least one unit each way.
void placeText(Layout& layout, const TextRoom& room);

} // namespace lab::ui
