// equation_panel.h — the lighting equation written out in the panel, for the BRDF the preset uses,
// each factor a button that shows it on the model (a factor view, core/scene/view_mode.h) and is
// highlighted while shown; with the value views' options (light, palette, range, the wipe).
#pragma once

#include "core/scene/preset.h"
#include "core/scene/view_mode.h"

namespace lab::ui {

// Named for the GUI tests: "equation.<view>" (equation.d, equation.n-dot-l, ...), "equation.light",
// "equation.palette", "equation.auto-range", "equation.range", "equation.wipe".
void equationSection(const Preset& preset, DisplaySettings& view);

} // namespace lab::ui
