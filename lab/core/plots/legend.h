// legend.h — a value view's legend: the palette as a bar, the values at its ends and middle, and
// what the view shows. `lab render --legend` adds it under the render; the GUI draws the same
// parts with ImGui (ui/viewport/viewport.cpp), from legendTicks().
#pragma once

#include "core/io/image.h"
#include "core/scene/view_mode.h"

#include <string>
#include <vector>

namespace lab {

struct LegendSpec {
    std::string title; // "D: microfacet distribution, light 1"
    ValueRange range;
    ValuePalette palette = ValuePalette::Viridis;
};

// What a (nearly) constant view's legend says (core/scene/view_mode.h ValueRange::constant), after
// its title "F: Fresnel term, light 1": "F = 0.0400 on the whole model, ± 5e-06"; "" for a range
// that is not constant.
std::string constantWords(const std::string& title, const ValueRange& range);

// A value as a legend writes it: `digits` significant digits ("0.0412", "12.5", "1.2e+03").
std::string legendNumber(float value, int digits = 3);
// The significant digits that tell `range`'s ends apart: 3, or more (up to 7) for a narrow range
// such as F's 0.040 to 0.045, which three digits would write as "0.04" twice.
int legendDigits(const ValueRange& range);

// The values a legend labels: lo, the middle, hi.
std::vector<float> legendTicks(const ValueRange& range);

// The title of `mode`'s legend: its label, and for a factor the light ("…, light 2").
std::string legendTitle(ViewMode mode, int light);

// The band's height for a render `width` pixels wide: max(48, width / 8).
int legendHeight(int width);

// `render` with the legend in a band of legendHeight(width) below it, on black like the value
// views' background: the title at the top left, the bar across, the ticks' values under it.
Image withLegend(const Image& render, const LegendSpec& spec);

} // namespace lab
