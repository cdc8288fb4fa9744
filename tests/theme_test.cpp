// theme_test.cpp — every theme's colours (core/plots/theme.h) checked for what they promise:
// text contrast 4.5:1 on each background it stands on, 3:1 for control borders, the focus ring,
// the accent, the grid and every plot line (WCAG 2.1, success criteria 1.4.3 and 1.4.11), and
// every pair of curves a legend tells apart at least 20 ΔE76 apart for normal vision and under
// simulated protanopia, deuteranopia and tritanopia.
//
// The colour science, written out here so the test does not trust the code it checks:
// - sRGB's transfer function and its D65 matrix to CIE XYZ (IEC 61966-2-1:1999);
// - CIELAB with the D65 white (CIE 15:2004) and ΔE76, the Euclidean distance in L*a*b*;
// - Machado, Oliveira & Fernandes 2009, "A Physiologically-based Model for Simulation of Color
//   Vision Deficiency", IEEE TVCG 15(6):1291–1298, severity 1.0 matrices (the authors' published
//   table), applied to linear sRGB and clamped to [0, 1];
// - WCAG 2.1's relative luminance and contrast ratio ((L1 + 0.05) / (L2 + 0.05)).
#include "core/plots/theme.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace lab {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

Vec3 times(const Mat3& m, const Vec3& v) {
    Vec3 out{};
    for (int i = 0; i < 3; ++i) {
        out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    }
    return out;
}

double decode(std::uint8_t v) { // sRGB to linear (IEC 61966-2-1)
    double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
Vec3 linear(FigureColor c) { return {decode(c.r), decode(c.g), decode(c.b)}; }

enum class Vision { Normal, Protanopia, Deuteranopia, Tritanopia };
const char* name(Vision v) {
    switch (v) {
    case Vision::Normal: return "normal vision";
    case Vision::Protanopia: return "protanopia";
    case Vision::Deuteranopia: return "deuteranopia";
    case Vision::Tritanopia: return "tritanopia";
    }
    return "";
}
constexpr std::array kVisions{Vision::Normal, Vision::Protanopia, Vision::Deuteranopia, Vision::Tritanopia};

// Machado, Oliveira & Fernandes 2009, severity 1.0 (their table of matrices for linear RGB).
constexpr Mat3 kProtanopia{{{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}};
constexpr Mat3 kDeuteranopia{{{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}};
constexpr Mat3 kTritanopia{{{1.255528, -0.076749, -0.178779}, {-0.078411, 0.930809, 0.147602}, {0.004733, 0.691367, 0.303900}}};

Vec3 simulated(FigureColor c, Vision v) {
    Vec3 l = linear(c);
    if (v != Vision::Normal) {
        l = times(v == Vision::Protanopia ? kProtanopia : v == Vision::Deuteranopia ? kDeuteranopia : kTritanopia, l);
    }
    for (double& x : l) {
        x = std::clamp(x, 0.0, 1.0);
    }
    return l;
}

// Linear sRGB to CIELAB, D65 white (X, Y, Z) = (0.95047, 1, 1.08883).
Vec3 lab(const Vec3& rgb) {
    constexpr Mat3 kToXyz{{{0.4124564, 0.3575761, 0.1804375}, {0.2126729, 0.7151522, 0.0721750}, {0.0193339, 0.1191920, 0.9503041}}};
    const Vec3 xyz = times(kToXyz, rgb);
    auto f = [](double t) { return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0; };
    const double fx = f(xyz[0] / 0.95047), fy = f(xyz[1]), fz = f(xyz[2] / 1.08883);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double deltaE76(FigureColor a, FigureColor b, Vision v) {
    const Vec3 p = lab(simulated(a, v)), q = lab(simulated(b, v));
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// WCAG 2.1: relative luminance and contrast ratio.
double luminance(FigureColor c) {
    const Vec3 l = linear(c);
    return 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
}
double contrast(FigureColor a, FigureColor b) {
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

std::string rgb(FigureColor c) {
    std::ostringstream s;
    s << "(" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ")";
    return s.str();
}

const char* inkName(Ink ink) {
    static const char* const names[] = {"Text",  "Muted", "Grid", "Axis",  "Background", "Diffuse", "Specular", "Total", "Compare",
                                        "Light", "Mirror", "Viewer", "Half", "Probe",      "Warning", "Overlay1", "Overlay2", "Overlay3"};
    static_assert(std::size(names) == static_cast<std::size_t>(Ink::Count));
    return names[static_cast<std::size_t>(ink)];
}

// One colour against a background, at least `least`:1.
void expectContrast(FigureColor fg, const char* fgName, FigureColor bg, const char* bgName, double least, Theme theme) {
    const double c = contrast(fg, bg);
    EXPECT_GE(c, least) << toString(theme) << ": " << fgName << " " << rgb(fg) << " on " << bgName << " " << rgb(bg) << " is "
                        << c << ":1";
}

//----------------------------------------------------------------------------------------
// The colour science itself, against known values
//----------------------------------------------------------------------------------------

TEST(ColourScience, KnownValues) {
    EXPECT_NEAR(contrast({255, 255, 255}, {0, 0, 0}), 21.0, 1e-9);
    EXPECT_NEAR(contrast({118, 118, 118}, {255, 255, 255}), 4.54, 0.01); // #767676, the lightest grey at 4.5:1 on white
    const Vec3 white = lab(linear({255, 255, 255}));
    EXPECT_NEAR(white[0], 100.0, 0.01);
    EXPECT_NEAR(white[1], 0.0, 0.01);
    EXPECT_NEAR(white[2], 0.0, 0.01);
    const Vec3 red = lab(linear({255, 0, 0})); // sRGB red: L* 53.24, a* 80.09, b* 67.20
    EXPECT_NEAR(red[0], 53.24, 0.02);
    EXPECT_NEAR(red[1], 80.09, 0.05);
    EXPECT_NEAR(red[2], 67.20, 0.05);
    // Each simulation keeps the greys (the matrices' rows sum to 1).
    for (Vision v : kVisions) {
        const Vec3 g = simulated({128, 128, 128}, v), n = linear({128, 128, 128});
        EXPECT_NEAR(g[0], n[0], 1e-5) << name(v);
        EXPECT_NEAR(g[2], n[2], 1e-5) << name(v);
    }
}

TEST(ColourScience, ReproducesTheIssuesMeasurement) {
    // Issue 38 measured the old figures' overlay: its red and green curves 9 ΔE76 apart for deuteranopia.
    EXPECT_NEAR(deltaE76({215, 50, 50}, {40, 160, 60}, Vision::Deuteranopia), 9.0, 0.1);
    EXPECT_GT(deltaE76({215, 50, 50}, {40, 160, 60}, Vision::Normal), 100.0);
}

//----------------------------------------------------------------------------------------
// Every theme
//----------------------------------------------------------------------------------------

class EveryTheme : public ::testing::TestWithParam<Theme> {};

TEST_P(EveryTheme, CurvesALegendTellsApartStayApartForEveryVision) {
    const Theme theme = GetParam();
    const Palette& plot = themeColors(theme).plot;
    for (const std::vector<Ink>& set : legendSets()) {
        for (std::size_t i = 0; i < set.size(); ++i) {
            for (std::size_t j = i + 1; j < set.size(); ++j) {
                const FigureColor a = colorOf(plot, set[i]), b = colorOf(plot, set[j]);
                for (Vision v : kVisions) {
                    const double d = deltaE76(a, b, v);
                    EXPECT_GE(d, 20.0) << toString(theme) << ": " << inkName(set[i]) << " " << rgb(a) << " and "
                                       << inkName(set[j]) << " " << rgb(b) << " are " << d << " ΔE76 apart for " << name(v);
                }
            }
        }
    }
}

TEST_P(EveryTheme, TextHasContrastOnEveryBackground) {
    const Theme theme = GetParam();
    const ThemeColors& t = themeColors(theme);
    const FigureColor plotBg = colorOf(t.plot, Ink::Background);
    const std::pair<FigureColor, const char*> backgrounds[] = {
        {plotBg, "the plot"}, {t.ui.window, "the window"}, {t.ui.control, "a control"},
        {t.ui.controlHover, "a hovered control"}, {t.ui.controlActive, "an active control"}};
    for (const auto& [bg, bgName] : backgrounds) {
        expectContrast(colorOf(t.plot, Ink::Text), "text", bg, bgName, 4.5, theme);
    }
    // Everything else the plots write in (values in the curves' colours, arrow names, warnings)
    // stands on the plot or, in the readouts' strips, on the window.
    for (std::size_t i = 0; i < t.plot.size(); ++i) {
        const Ink ink = static_cast<Ink>(i);
        if (ink == Ink::Background || ink == Ink::Grid) {
            continue;
        }
        expectContrast(t.plot[i], inkName(ink), plotBg, "the plot", 4.5, theme);
        expectContrast(t.plot[i], inkName(ink), t.ui.window, "the window", 4.5, theme);
    }
    expectContrast(t.ui.error, "error text", t.ui.window, "the window", 4.5, theme);
    expectContrast(t.ui.success, "success text", t.ui.window, "the window", 4.5, theme);
    // The overlay's angle fields: white text on their curve's colour, shaded.
    for (Ink ink : {Ink::Overlay1, Ink::Overlay2, Ink::Overlay3}) {
        for (float k : kFieldShades) {
            expectContrast({255, 255, 255}, "white text", shaded(colorOf(t.plot, ink), k), inkName(ink), 4.5, theme);
        }
    }
}

TEST_P(EveryTheme, LinesBordersAndTheFocusRingHaveContrast) {
    const Theme theme = GetParam();
    const ThemeColors& t = themeColors(theme);
    const FigureColor plotBg = colorOf(t.plot, Ink::Background);
    expectContrast(colorOf(t.plot, Ink::Grid), "the grid", plotBg, "the plot", 3.0, theme);
    expectContrast(t.ui.controlBorder, "a control's border", t.ui.window, "the window", 3.0, theme);
    const std::pair<FigureColor, const char*> places[] = {
        {t.ui.window, "the window"}, {t.ui.control, "a control"}, {t.ui.controlHover, "a hovered control"},
        {t.ui.controlActive, "an active control"}};
    for (const auto& [bg, bgName] : places) {
        expectContrast(t.ui.focusRing, "the focus ring", bg, bgName, 3.0, theme);
        expectContrast(t.ui.accent, "the accent (grabs, check marks)", bg, bgName, 3.0, theme);
    }
}

INSTANTIATE_TEST_SUITE_P(Themes, EveryTheme, ::testing::ValuesIn(kThemes),
                         [](const ::testing::TestParamInfo<Theme>& p) { return std::string(toString(p.param)); });

TEST(Themes, NamesRoundTripAndUnknownNamesAreRefused) {
    for (Theme t : kThemes) {
        EXPECT_EQ(themeFrom(toString(t)), t);
    }
    EXPECT_FALSE(themeFrom("Dark"));
    EXPECT_FALSE(themeFrom(""));
    EXPECT_EQ(themeNames(), "dark, light");
}

} // namespace
} // namespace lab
