// view_mode.cpp — labels and the per-term copy of a preset.
#include "core/scene/view_mode.h"

namespace lab {

const char* toString(ViewMode mode) {
    switch (mode) {
    case ViewMode::Lit: return "Lit (all terms)";
    case ViewMode::Emissive: return "Emissive only";
    case ViewMode::Ambient: return "Ambient only";
    case ViewMode::Diffuse: return "Diffuse only";
    case ViewMode::Specular: return "Specular only";
    case ViewMode::Normals: return "Normals as colours";
    }
    return "";
}

Preset viewed(const Preset& p, ViewMode mode) {
    Preset v = p;
    const TermSwitches& t = p.terms;
    switch (mode) {
    case ViewMode::Emissive: v.terms = {t.emissive, false, false, false}; break;
    case ViewMode::Ambient: v.terms = {false, t.ambient, false, false}; break;
    case ViewMode::Diffuse: v.terms = {false, false, t.diffuse, false}; break;
    case ViewMode::Specular: v.terms = {false, false, false, t.specular}; break;
    case ViewMode::Lit:
    case ViewMode::Normals: break;
    }
    return v;
}

} // namespace lab
