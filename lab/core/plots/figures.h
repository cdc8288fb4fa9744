// figures.h — the plots as figures for slides and homework: the lobe, the incident angles
// overlaid, the attenuation of a light, the albedo against the incident angle and the (θh, θd)
// slice (core/plots/slice.h; A, B and A − B in compare mode), each a Figure
// (core/plots/figure.h: one description, written as SVG and as PNG) with its axes, rings, tick and
// angle labels, legend and a title naming the preset, the BRDF and the angle, plus the CSV of the
// numbers its curves are drawn from.
//
// The numbers are those of the on-screen plots and `lab plot` (core/plots/plot_data.h reflectedIntensity,
// lobePoints, attenuationCurve; core/plots/energy.h albedoCurve; core/plots/plot_layout.h ticks), every sample
// drawn (no thinning), so a curve's points are the CSV's rows mapped by `placement`. Colours are
// a theme's (theme.h): the light one by default, dark ink on white for paper and slides; the lab
// exports in its own theme. No ImGui, no GL, no files.
#pragma once

#include "core/plots/figure.h"
#include "core/plots/plot_data.h"
#include "core/plots/theme.h"
#include "core/scene/preset.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace lab {

enum class FigureKind { Lobe, Overlay, Attenuation, Albedo, Slice };
inline constexpr std::array kFigureKinds{FigureKind::Lobe, FigureKind::Overlay, FigureKind::Attenuation, FigureKind::Albedo,
                                         FigureKind::Slice};
std::string_view toString(FigureKind kind); // "lobe", "overlay", "attenuation", "albedo", "slice"
std::optional<FigureKind> figureKindFrom(std::string_view name);

struct FigureRequest {
    FigureKind kind = FigureKind::Lobe;
    float incidentDeg = 45.0f;                  // the lobe's, and the albedo's marker
    RadialScale scale = RadialScale::Linear;    // the polar figures' radial scale
    glm::vec3 overlayDeg{60.0f, 25.0f, 10.0f};  // the overlay's three incident angles
    int light = 0;                              // the attenuation's light, 0-based
    Theme theme = Theme::Light;                 // the colours: dark on white unless asked
    PlotComponent component = PlotComponent::Specular; // the slice's image (its CSV has all three)
    ValuePalette palette = ValuePalette::Viridis;       // the slice's palette (the lab's view palette)
};

struct FigureResult {
    Figure figure;
    std::string csv; // the samples the curves are drawn from (README "Figures" lists the columns)
    // Where a curve's unit point goes in the figure: offset + scale × unit. Unit points are
    // lobePoints' r·(sin θo, cos θo) for lobe and overlay, (d / maxDistance, Att) for the
    // attenuation and (θi / 90°, ρ / yMax) for the albedo.
    glm::vec2 offset{0.0f}, scale{1.0f};
    float outer = 1.0f; // the polar figures' outer ring (lobePoints' maxIntensity); the albedo's yMax
    float maxDistance = 0.0f; // the attenuation's
};

// The figure `request` asks for, of preset `a` (and compare set `b`, drawn in the lobe and the
// albedo when given), or nullopt with `error` (one line) when it cannot be drawn: the light asked
// for does not exist.
std::optional<FigureResult> makeFigure(const Preset& a, const Preset* b, const FigureRequest& request, std::string& error);

// Where a figure goes: each file given is written (atomically, durable: the user made it).
struct FigureFiles {
    std::optional<std::filesystem::path> svg, png, csv;
    float pngScale = 1.0f; // in [kMinFigureScale, kMaxFigureScale]
};

// Writes the files `files` names; false with `error` ("FILE: why") at the first that fails.
bool writeFigure(const FigureResult& figure, const FigureFiles& files, std::string& error);

} // namespace lab
