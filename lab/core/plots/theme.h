// theme.h — every theme's colours, written once: the UI's (the ImGui style: windows, controls,
// their borders, the focus ring) and the plots' inks (plot_drawing.h's Palette: text, grid, each
// curve's colour), which the plots on screen, the figures' SVG and PNG and the ImGui style all
// read. Dark (light on near black, the lab's first look) and Light (dark on white: a projector in
// a lit room, and paper).
//
// What the colours promise (tests/theme_test.cpp checks it over every theme): text 4.5:1 against
// every background it stands on, controls' borders, the focus ring, grid and curves 3:1
// (WCAG 2.1, 1.4.3 and 1.4.11); every pair of curves a legend tells apart at least 20 ΔE76 apart
// for normal vision and under simulated protanopia, deuteranopia and tritanopia. The curves also
// differ by their dash (plot_drawing.h dashOf), so colour is never the only cue.
//
// Not here: painting (ui/theme_style.h sets ImGui's colours; plot_kit and the figures paint), the
// value views' palettes (viridis, grey: core/scene/view_mode.h), the model's colours (the preset).
#pragma once

#include "core/plots/plot_drawing.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

enum class Theme { Dark, Light };
inline constexpr std::array kThemes{Theme::Dark, Theme::Light};
std::string_view toString(Theme theme); // "dark", "light": the command line's and the settings file's names
std::optional<Theme> themeFrom(std::string_view name);
std::string themeNames(); // "dark, light", for messages

// The UI's colours beside the plots' inks. Text and muted text are the palette's Ink::Text and
// Ink::Muted; every colour is opaque.
struct UiColors {
    FigureColor window;        // windows, panels, popups
    FigureColor control;       // a field's, a button's, a header's, a tab's fill
    FigureColor controlHover;  // ... under the pointer
    FigureColor controlActive; // ... pressed, or the chosen one
    FigureColor controlBorder; // the line round every control (3:1 against the window)
    FigureColor accent;        // slider grabs, check marks, progress bars (3:1 against the control)
    FigureColor focusRing;     // keyboard navigation's highlight (ImGuiCol_NavHighlight)
    FigureColor error;         // an error's text
    FigureColor success;       // a solved exercise, shaders that compiled
};

struct ThemeColors {
    UiColors ui;
    Palette plot; // the plots' and figures' inks; Ink::Background is the plots' background
};

const ThemeColors& themeColors(Theme theme);

// The sets of inks a legend tells apart: the lobe's and the albedo's curves (the attenuation's
// curve and marker are two of them), and the overlay's three angles. Every pair in a set must
// stay apart (theme_test.cpp); a new curve joins a set here.
std::vector<std::vector<Ink>> legendSets();

// The plots in `theme` for the figures: scale 1, text measured with the PNG's font.
PlotStyle figureStyle(Theme theme);

// A colour's darker shade (each channel × k): the overlay's angle fields, white text on them.
FigureColor shaded(FigureColor c, float k);
// The shades of the overlay's fields: idle, under the pointer, being dragged.
inline constexpr std::array<float, 3> kFieldShades{0.40f, 0.48f, 0.55f};

} // namespace lab
