// view_legend.h — what the value views (core/scene/view_mode.h) add to the 3D view: the legend
// strip under the model (the palette as a bar, its range, the value under the cursor, or why the
// view does not apply), and the wipe's divider across the model.
#pragma once

#include "core/scene/view_mode.h"
#include "ui/layout.h"

#include <optional>
#include <string>

struct ImDrawList;

namespace lab::ui {

struct LegendModel {
    std::string title;               // "D: microfacet distribution, light 1"
    std::optional<ValueRange> range; // the palette's span; none while the view does not apply
    ValuePalette palette = ValuePalette::Viridis;
    bool automatic = true;           // the range was found on the model (said beside it)
    std::optional<float> value;      // under the cursor, on the model
    std::string note;                // why the view does not apply (the lit model is shown)
};

// What a (nearly) constant view says (core/scene/view_mode.h ValueRange::constant): "F = 0.0400 on
// the whole model, ± 1e-05"; "" for a range that is not.
std::string constantWords(const LegendModel& legend);

// The legend strip's height: two lines.
float legendStripHeight();

// The legend in `r` (the strip placeText gave it): the title and the value under the cursor on the
// first line, the bar with its range's ends and middle on the second; named "view.legend" for the
// GUI tests, the bar "view.legend-bar".
void legendStrip(const LegendModel& legend, const Rect& r, ImDrawList* dl);

// The wipe's divider at `at` (a share of `r`'s width) with a handle, named "view.wipe".
void wipeDivider(float at, const Rect& r, bool active, ImDrawList* dl);

// How close (window units) a press must be to the divider to grab it.
float wipeGrabDistance();

} // namespace lab::ui
