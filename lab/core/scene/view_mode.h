// view_mode.h — views of the model that show one part of the lighting.
//
// A view changes what is drawn, never the preset. Three kinds:
//   * the term views (lit, emissive, ambient, diffuse, specular): viewed() returns a copy of the
//     preset with the other terms switched off, drawn as usual;
//   * normals as colours;
//   * the value views: one number per pixel, drawn through a palette with a legend — a factor of
//     the lighting equation for one light (N·L, N·V, R·V, N·H, D, F, G, the Cook-Torrance
//     denominator, the attenuation, the spot factor, the distance to the light), computed by
//     lighting.glsl's equationFactor(), or gouraud-error, the largest channel difference between
//     the per-pixel and the per-vertex lit colours.
// Shared by the workspace (which holds the settings), the UI (which picks them), the command line
// (`lab render --view`, a preset's `check.views`) and the renderer.
#pragma once

#include "core/scene/preset.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

// The factor views keep lighting_api.glsl's FACTOR_* order, from NdotL (lighting.cpp checks it).
enum class ViewMode {
    Lit, Emissive, Ambient, Diffuse, Specular, Normals,
    NdotL, NdotV, RdotV, NdotH, D, F, G, Denominator, Attenuation, Spot, Distance,
    GouraudError
};

inline constexpr std::array kViewModes{
    ViewMode::Lit,   ViewMode::Emissive, ViewMode::Ambient,     ViewMode::Diffuse,     ViewMode::Specular,
    ViewMode::Normals, ViewMode::NdotL,  ViewMode::NdotV,       ViewMode::RdotV,       ViewMode::NdotH,
    ViewMode::D,     ViewMode::F,        ViewMode::G,           ViewMode::Denominator, ViewMode::Attenuation,
    ViewMode::Spot,  ViewMode::Distance, ViewMode::GouraudError};

// How a value view maps its numbers to colours.
enum class ValuePalette { Viridis, Grey };

// The values a value view spreads over its palette: lo is the palette's first colour, hi its last.
struct ValueRange {
    ValueRange() = default;
    ValueRange(float low, float high) : lo(low), hi(high) {}
    float lo = 0.0f, hi = 1.0f;
    // Set by autoRange when the model's values span less than 1% of their size: spread over a
    // palette they would show a gradient that is not there, so the range is [min(0, v), max(1, v)]
    // and the legend says "F = 0.0400 on the whole model, ± 0.00001".
    std::optional<float> constant; // the middle of the values found
    float spread = 0.0f;           // half their span
    bool operator==(const ValueRange&) const = default;
};

// How the scene is shown: the view and its options, and compare mode (set B beside set A).
struct DisplaySettings {
    ViewMode mode = ViewMode::Lit;
    int light = 0;                      // the factor views' light: an index into preset.lights
    ValuePalette palette = ValuePalette::Viridis;
    std::optional<ValueRange> range;    // a fixed range; none: automatic (autoRange)
    bool wipe = false;                  // a divider across the model: the lit model left of it, `mode` right
    float wipeAt = 0.5f;                // where the divider is, a share of the model's viewport width
    bool wireframe = false;             // the triangles' edges over the shaded model
    bool vertexNormals = false;         // each vertex's normal as a short line
    bool plotsAtProbe = false;          // the plots use the probed point's N, L and V
    bool compare = false;
    bool editingB = false; // the panel edits B
    bool operator==(const DisplaySettings&) const = default;
};

// "Lit (all terms)", "D: microfacet distribution", ...
const char* toString(ViewMode mode);
// "lit", "n-dot-l", "gouraud-error", ...: the command line's and the check block's names.
const char* viewName(ViewMode mode);
std::optional<ViewMode> viewFromName(std::string_view name);
// Every name, comma separated, for messages; and as a list (for suggest.h).
std::string viewNames();
std::vector<std::string_view> viewNameList();

// A factor view or gouraud-error: a number per pixel, drawn through a palette.
bool showsValue(ViewMode mode);
// A factor of one light's term (needs a light).
bool isFactor(ViewMode mode);

// Why `mode` cannot show `preset` with light `light` (an index into preset.lights), in one
// sentence: "D is a Cook-Torrance factor; this preset's BRDF is Phong". Empty when it can.
std::string notApplicable(ViewMode mode, const Preset& preset, int light);

// The preset as `mode` shows it: for a term view, only that term switched on (if the preset has
// it on); otherwise the preset itself.
Preset viewed(const Preset& preset, ViewMode mode);

// The automatic range of a value view from the smallest and largest value on the model: those
// two, or when they span less than 1% of their size, [min(0, v), max(1, v)] with `constant`
// and `spread` set, so a (nearly) constant shows as what it is.
ValueRange autoRange(float smallest, float largest);

// v's place in `range`, clamped to [0, 1]: what the palettes colour.
float rangePosition(float v, const ValueRange& range);

} // namespace lab
