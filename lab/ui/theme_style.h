// theme_style.h — a theme (core/plots/theme.h) as ImGui's style: every ImGui colour from the
// theme's named colours, opaque, and a border round each control (WCAG 1.4.11 wants a control's
// edge 3:1 against the window; a fill alone does not reach it). The theme in use is remembered
// here for the plots' painter (plots/plot_kit.h), as ImGui remembers its style.
//
// Not here: the colours themselves (core/plots/theme.h), choosing a theme (the panel, the app).
#pragma once

#include "core/plots/theme.h"

namespace lab::ui {

// Sets ImGui's colours and control borders to `theme`'s and makes it the current theme. Call
// between frames or before the first widget of a frame.
void applyTheme(Theme theme);
// The theme applyTheme last set (Dark before any).
Theme currentTheme();
// Its colours.
inline const ThemeColors& currentColors() { return themeColors(currentTheme()); }

} // namespace lab::ui
