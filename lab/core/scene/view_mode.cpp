// view_mode.cpp — the views' names, where each applies, and the per-term copy of a preset.
#include "core/scene/view_mode.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lab {

namespace {

struct ViewRow {
    ViewMode mode;
    const char* name;  // the command line's
    const char* label; // the GUI's
};

constexpr std::array<ViewRow, kViewModes.size()> kRows{{
    {ViewMode::Lit, "lit", "Lit (all terms)"},
    {ViewMode::Emissive, "emissive", "Emissive only"},
    {ViewMode::Ambient, "ambient", "Ambient only"},
    {ViewMode::Diffuse, "diffuse", "Diffuse only"},
    {ViewMode::Specular, "specular", "Specular only"},
    {ViewMode::Normals, "normals", "Normals as colours"},
    {ViewMode::NdotL, "n-dot-l", "N.L: cosine of incidence"},
    {ViewMode::NdotV, "n-dot-v", "N.V: cosine of the view angle"},
    {ViewMode::RdotV, "r-dot-v", "R.V: Phong's mirror factor"},
    {ViewMode::NdotH, "n-dot-h", "N.H: the half vector's cosine"},
    {ViewMode::D, "d", "D: microfacet distribution"},
    {ViewMode::F, "f", "F: Fresnel reflectance"},
    {ViewMode::G, "g", "G: masking and shadowing"},
    {ViewMode::Denominator, "denominator", "4 max(N.V, 1e-4): the denominator"},
    {ViewMode::Attenuation, "attenuation", "Att(d): distance attenuation"},
    {ViewMode::Spot, "spot", "Spot factor"},
    {ViewMode::Distance, "distance", "d: distance to the light"},
    {ViewMode::GouraudError, "gouraud-error", "Gouraud error: |per pixel - per vertex|"},
}};

const ViewRow& row(ViewMode mode) { return kRows[static_cast<std::size_t>(mode)]; }

} // namespace

const char* toString(ViewMode mode) { return row(mode).label; }
const char* viewName(ViewMode mode) { return row(mode).name; }

std::optional<ViewMode> viewFromName(std::string_view name) {
    for (const ViewRow& r : kRows) {
        if (name == r.name) {
            return r.mode;
        }
    }
    return std::nullopt;
}

std::string viewNames() {
    std::string s;
    for (const ViewRow& r : kRows) {
        s += (s.empty() ? "" : ", ") + std::string(r.name);
    }
    return s;
}

std::vector<std::string_view> viewNameList() {
    std::vector<std::string_view> names;
    for (const ViewRow& r : kRows) {
        names.push_back(r.name);
    }
    return names;
}

bool showsValue(ViewMode mode) { return mode >= ViewMode::NdotL; }
bool isFactor(ViewMode mode) { return mode >= ViewMode::NdotL && mode <= ViewMode::Distance; }

std::string notApplicable(ViewMode mode, const Preset& p, int light) {
    if (!isFactor(mode)) {
        return {};
    }
    const std::string which = "light " + std::to_string(light + 1);
    if (light < 0 || light >= static_cast<int>(p.lights.size())) {
        return "there is no " + which + " (the preset has " + std::to_string(p.lights.size()) +
               (p.lights.size() == 1 ? " light)" : " lights)");
    }
    const LightDesc& l = p.lights[static_cast<std::size_t>(light)];
    if (!l.enabled) {
        return which + " is switched off";
    }
    const std::string brdf = "this preset's BRDF is " + std::string(toString(p.brdf));
    switch (mode) {
    case ViewMode::RdotV:
        return p.brdf == BrdfModel::Phong ? "" : "R.V is the Phong BRDF's factor; " + brdf;
    case ViewMode::NdotH:
        return p.brdf != BrdfModel::Phong ? "" : "N.H is a factor of Blinn-Phong and Cook-Torrance; " + brdf;
    case ViewMode::D:
    case ViewMode::F:
    case ViewMode::G:
    case ViewMode::Denominator:
        return p.brdf == BrdfModel::CookTorrance
                   ? ""
                   : std::string(viewName(mode)) + " is a Cook-Torrance factor; " + brdf;
    case ViewMode::Distance:
        return l.type != LightType::Directional ? "" : which + " is directional: it has no distance";
    case ViewMode::Spot: // 1 everywhere but for a spot light: nothing to see
        return l.type == LightType::Spot ? "" : which + " is a " + std::string(toString(l.type)) + " light: only a spot light has a spot factor";
    default: return {};
    }
}

Preset viewed(const Preset& p, ViewMode mode) {
    Preset v = p;
    const TermSwitches& t = p.terms;
    switch (mode) {
    case ViewMode::Emissive: v.terms = {t.emissive, false, false, false}; break;
    case ViewMode::Ambient: v.terms = {false, t.ambient, false, false}; break;
    case ViewMode::Diffuse: v.terms = {false, false, t.diffuse, false}; break;
    case ViewMode::Specular: v.terms = {false, false, false, t.specular}; break;
    default: break;
    }
    return v;
}

ValueRange autoRange(float smallest, float largest) {
    const float size = std::max(std::abs(smallest), std::abs(largest));
    if (!(largest - smallest > 1e-6f) || !(largest - smallest >= 0.01f * size)) {
        const bool finite = std::isfinite(smallest) && std::isfinite(largest);
        const float v = finite ? 0.5f * (smallest + largest) : 0.0f;
        ValueRange r{std::min(0.0f, v), std::max(1.0f, v)};
        r.constant = v;
        r.spread = finite ? std::max(0.0f, 0.5f * (largest - smallest)) : 0.0f;
        return r;
    }
    return {smallest, largest};
}

float rangePosition(float v, const ValueRange& r) { return std::clamp((v - r.lo) / (r.hi - r.lo), 0.0f, 1.0f); }

} // namespace lab
