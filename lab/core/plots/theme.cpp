// theme.cpp — the two themes' colours (theme.h). The curves' colours are chosen from Okabe & Ito's
// and Paul Tol's colour-blind-safe sets and adjusted until tests/theme_test.cpp's checks pass with
// room to spare (the least ΔE76 between curves under any simulation: 40 dark, 32 light).
#include "core/plots/theme.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

namespace lab {

namespace {

constexpr Palette paletteOf(std::initializer_list<std::pair<Ink, FigureColor>> entries) {
    Palette p{};
    for (auto [ink, color] : entries) {
        p[static_cast<std::size_t>(ink)] = color;
    }
    return p;
}

// Light on near black, bright enough for a projector in a dark room. The curves: Okabe & Ito's
// sky blue, a lighter orange, Tol's red; the overlay's angles take the same three.
constexpr FigureColor kDarkBlue{86, 180, 233}, kDarkOrange{238, 188, 76}, kDarkRose{238, 102, 119};
constexpr ThemeColors kDark{
    UiColors{
        {26, 27, 32},    // window
        {44, 56, 78},    // control
        {56, 74, 104},   // controlHover
        {36, 84, 150},   // controlActive
        {112, 118, 135}, // controlBorder
        {110, 170, 255}, // accent
        {255, 200, 60},  // focusRing
        {255, 140, 130}, // error
        {110, 215, 130}, // success
    },
    paletteOf({
        {Ink::Text, {228, 228, 235}},  {Ink::Muted, {190, 190, 200}},  {Ink::Grid, {120, 120, 135}},
        {Ink::Axis, {215, 215, 225}},  {Ink::Background, {16, 16, 20}}, {Ink::Diffuse, kDarkBlue},
        {Ink::Specular, kDarkOrange},  {Ink::Total, {255, 255, 255}},  {Ink::Compare, kDarkRose},
        {Ink::Light, {255, 230, 90}},  {Ink::Mirror, {120, 220, 120}}, {Ink::Viewer, {90, 220, 230}},
        {Ink::Half, {255, 140, 140}},  {Ink::Probe, {180, 180, 186}},  {Ink::Warning, {255, 130, 110}},
        {Ink::Overlay1, kDarkOrange},  {Ink::Overlay2, kDarkBlue},     {Ink::Overlay3, kDarkRose},
    }),
};

// Dark on white: a projector in a lit room, slides and paper (the figures' default). The curves:
// Tol's vibrant blue and red and his muted rose, darkened to 4.5:1 on white (they also write text).
constexpr FigureColor kLightBlue{0, 101, 159}, kLightRed{173, 43, 14}, kLightRose{153, 76, 89};
constexpr ThemeColors kLight{
    UiColors{
        {244, 244, 247}, // window
        {222, 227, 236}, // control
        {204, 214, 232}, // controlHover
        {178, 200, 236}, // controlActive
        {118, 122, 134}, // controlBorder
        {0, 90, 180},    // accent
        {170, 60, 0},    // focusRing
        {175, 30, 20},   // error
        {20, 110, 40},   // success
    },
    paletteOf({
        {Ink::Text, {20, 20, 24}},     {Ink::Muted, {80, 80, 90}},      {Ink::Grid, {135, 135, 145}},
        {Ink::Axis, {60, 60, 70}},     {Ink::Background, {255, 255, 255}}, {Ink::Diffuse, kLightBlue},
        {Ink::Specular, kLightRed},    {Ink::Total, {20, 20, 20}},      {Ink::Compare, kLightRose},
        {Ink::Light, {140, 95, 0}},    {Ink::Mirror, {25, 115, 45}},    {Ink::Viewer, {0, 110, 130}},
        {Ink::Half, {190, 50, 50}},    {Ink::Probe, {95, 95, 105}},     {Ink::Warning, {180, 40, 20}},
        {Ink::Overlay1, kLightRed},    {Ink::Overlay2, kLightBlue},     {Ink::Overlay3, kLightRose},
    }),
};

} // namespace

std::string_view toString(Theme theme) { return theme == Theme::Light ? "light" : "dark"; }

std::optional<Theme> themeFrom(std::string_view name) {
    for (Theme t : kThemes) {
        if (toString(t) == name) {
            return t;
        }
    }
    return std::nullopt;
}

std::string themeNames() {
    std::string out;
    for (Theme t : kThemes) {
        out += (out.empty() ? "" : ", ") + std::string(toString(t));
    }
    return out;
}

const ThemeColors& themeColors(Theme theme) { return theme == Theme::Light ? kLight : kDark; }

std::vector<std::vector<Ink>> legendSets() {
    return {{Ink::Diffuse, Ink::Specular, Ink::Total, Ink::Compare}, {Ink::Overlay1, Ink::Overlay2, Ink::Overlay3}};
}

PlotStyle figureStyle(Theme theme) { return PlotStyle{&themeColors(theme).plot, 1.0f, &printedWidth}; }

FigureColor shaded(FigureColor c, float k) {
    auto channel = [k](std::uint8_t v) { return static_cast<std::uint8_t>(std::clamp(std::lround(float(v) * k), 0L, 255L)); };
    return {channel(c.r), channel(c.g), channel(c.b)};
}

} // namespace lab
