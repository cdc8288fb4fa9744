// preset.cpp — the preset's names, defaults and JSON writing.
//
// Owns toString for every enumeration (the names preset files use, from preset_names.h),
// defaultSubdivisions, presetToJson and savePreset: every key in the documented order (a
// light's `orbit`, `check` and `sweep` only when given), numbers
// as the shortest decimal that reads back as the same float, written atomically.
//
// It does not read or validate presets (preset_read.cpp).
#include "core/scene/preset.h"

#include "core/io/file_io.h"
#include "core/io/number_format.h"
#include "core/scene/preset_names.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

//----------------------------------------------------------------------------------------
// Names and defaults
//----------------------------------------------------------------------------------------

namespace {

template <typename E, std::size_t N>
std::string_view nameOf(const preset_names::NameTable<E, N>& table, E value) {
    for (const auto& [v, name] : table) {
        if (v == value) {
            return name;
        }
    }
    return "?";
}

} // namespace

glm::ivec2 defaultSubdivisions(Builtin builtin) {
    switch (builtin) {
    case Builtin::Sphere: return {64, 32};
    case Builtin::Cube: return {1, 1};
    case Builtin::Plane: return {16, 16};
    case Builtin::Torus: return {64, 32};
    }
    return {1, 1};
}

std::string_view toString(Builtin v) { return nameOf(preset_names::kBuiltin, v); }
std::string_view toString(Shading v) { return nameOf(preset_names::kShading, v); }
std::string_view toString(NormalMatrixMode v) { return nameOf(preset_names::kNormalMatrix, v); }
std::string_view toString(BrdfModel v) { return nameOf(preset_names::kBrdf, v); }
std::string_view toString(Distribution v) { return nameOf(preset_names::kDistribution, v); }
std::string_view toString(FresnelMode v) { return nameOf(preset_names::kFresnel, v); }
std::string_view toString(LightType v) { return nameOf(preset_names::kLightType, v); }

//----------------------------------------------------------------------------------------
// Writing
//----------------------------------------------------------------------------------------

namespace {

// The shortest decimal that reads back as the same float: 0.8f is written "0.8", not
// "0.800000011920929", and parses back to exactly 0.8f.
Json number(float f) {
    double d = std::strtod(shortestFloat(f).c_str(), nullptr);
    if (d == std::floor(d) && std::abs(d) < 1e15) {
        return Json(static_cast<std::int64_t>(d));
    }
    return Json(d);
}

Json vec3(const glm::vec3& v) { return Json::array({number(v.x), number(v.y), number(v.z)}); }

// Objects one key a line, arrays of scalars on one line: readable and diff-friendly.
void emit(const Json& j, std::string& out, int indent) {
    auto pad = [&](int n) { out.append(static_cast<std::size_t>(n), ' '); };
    if (j.is_object()) {
        if (j.empty()) {
            out += "{}";
            return;
        }
        out += "{\n";
        std::size_t i = 0;
        for (const auto& [key, value] : j.items()) {
            pad(indent + 2);
            out += Json(key).dump() + ": ";
            emit(value, out, indent + 2);
            out += ++i < j.size() ? ",\n" : "\n";
        }
        pad(indent);
        out += "}";
    } else if (j.is_array()) {
        bool flat = std::none_of(j.begin(), j.end(), [](const Json& e) { return e.is_structured(); });
        if (flat) {
            out += "[";
            for (std::size_t k = 0; k < j.size(); ++k) {
                out += (k ? ", " : "") + j[k].dump();
            }
            out += "]";
            return;
        }
        out += "[\n";
        for (std::size_t k = 0; k < j.size(); ++k) {
            pad(indent + 2);
            emit(j[k], out, indent + 2);
            out += k + 1 < j.size() ? ",\n" : "\n";
        }
        pad(indent);
        out += "]";
    } else {
        out += j.dump();
    }
}

bool hasNonFinite(const Json& j) {
    if (j.is_number_float()) {
        return !std::isfinite(j.get<double>());
    }
    if (j.is_structured()) {
        return std::any_of(j.begin(), j.end(), hasNonFinite);
    }
    return false;
}

// `check`: each tolerance given, and the views (a name, or {"view", "light"} for a light but the first).
Json checkJson(const CheckSettings& c) {
    Json check = Json::object();
    if (c.pixelTolerance) {
        check["pixel_tolerance"] = *c.pixelTolerance;
    }
    for (auto [key, value] : {std::pair{"max_failing", c.maxFailing}, std::pair{"max_mean", c.maxMean},
                              std::pair{"plot_tolerance", c.plotTolerance}}) {
        if (value) {
            check[key] = number(*value);
        }
    }
    if (!c.views.empty()) {
        Json views = Json::array();
        for (const CheckView& v : c.views) {
            views.push_back(v.light == 1 ? Json(v.view) : Json{{"view", v.view}, {"light", v.light}});
        }
        check["views"] = views;
    }
    return check;
}

Json presetJson(const Preset& p) {
    Json j;
    j["format"] = kPresetFormat;
    j["version"] = kPresetVersion;
    j["name"] = p.name;
    j["description"] = p.description;
    Json model;
    if (p.model.gltf.empty()) {
        model["builtin"] = toString(p.model.builtin);
        model["subdivisions"] = Json::array({p.model.subdivisions.x, p.model.subdivisions.y});
    } else {
        model["gltf"] = p.model.gltf;
    }
    model["scale"] = vec3(p.model.scale);
    model["rotate_deg"] = vec3(p.model.rotateDeg);
    model["translate"] = vec3(p.model.translate);
    j["model"] = model;
    j["camera"] = {{"eye", vec3(p.camera.eye)},       {"target", vec3(p.camera.target)},
                   {"up", vec3(p.camera.up)},         {"fovy_deg", number(p.camera.fovyDeg)},
                   {"near", number(p.camera.near)},   {"far", number(p.camera.far)}};
    j["shading"] = toString(p.shading);
    j["normal_matrix"] = toString(p.normalMatrix);
    j["brdf"] = toString(p.brdf);
    j["cook_torrance"] = {{"distribution", toString(p.cookTorrance.distribution)},
                          {"roughness", number(p.cookTorrance.roughness)},
                          {"fresnel", toString(p.cookTorrance.fresnel)},
                          {"ior", number(p.cookTorrance.ior)},
                          {"geometry", p.cookTorrance.geometry}};
    j["material"] = {{"emissive", vec3(p.material.emissive)}, {"ambient", vec3(p.material.ambient)},
                     {"diffuse", vec3(p.material.diffuse)},   {"specular", vec3(p.material.specular)},
                     {"shininess", number(p.material.shininess)}};
    j["ambient_light"] = vec3(p.ambientLight);
    Json lights = Json::array();
    for (const LightDesc& l : p.lights) {
        lights.push_back({{"type", toString(l.type)},
                          {"position", vec3(l.position)},
                          {"direction", vec3(l.direction)},
                          {"ambient", vec3(l.ambient)},
                          {"diffuse", vec3(l.diffuse)},
                          {"specular", vec3(l.specular)},
                          {"attenuation", vec3(l.attenuation)},
                          {"cutoff_deg", number(l.cutoffDeg)},
                          {"exponent", number(l.exponent)},
                          {"enabled", l.enabled}});
        if (l.orbit != LightOrbit{}) { // presets without motion are written as they were before it existed
            lights.back()["orbit"] = {{"on", l.orbit.on},
                                      {"axis", vec3(l.orbit.axis)},
                                      {"degrees_per_second", number(l.orbit.degreesPerSecond)}};
        }
    }
    j["lights"] = lights;
    j["terms"] = {{"emissive", p.terms.emissive},
                  {"ambient", p.terms.ambient},
                  {"diffuse", p.terms.diffuse},
                  {"specular", p.terms.specular}};
    j["background"] = vec3(p.background);
    j["plot"] = {{"incident_deg", number(p.plotIncidentDeg)}};
    // `check` and `sweep` only when given: presets without them are written as before they existed.
    if (!p.check.empty()) {
        j["check"] = checkJson(p.check);
    }
    if (!p.sweep.empty()) {
        j["sweep"] = p.sweep;
    }
    return j;
}

std::string jsonText(const Json& json) {
    std::string out;
    emit(json, out, 0);
    out += '\n';
    return out;
}

} // namespace

std::string presetToJson(const Preset& preset) { return jsonText(presetJson(preset)); }

bool savePreset(const Preset& preset, const fs::path& file, Diagnostics& diagnostics) {
    // A preset in memory can hold non-finite values only through a bug elsewhere (JSON has no
    // NaN, so they would come out as null); refuse to write a file that would not load.
    Json json = presetJson(preset);
    if (hasNonFinite(json)) {
        diagnostics.push_back({file.string(), "", "refusing to save a preset with non-finite numbers"});
        return false;
    }
    std::string error;
    if (!writeFileAtomic(file, jsonText(json), error)) {
        diagnostics.push_back({file.string(), "", error});
        return false;
    }
    return true;
}

} // namespace lab
