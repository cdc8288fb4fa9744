// preset.cpp — the preset's names, defaults and JSON writing.
//
// Owns toString for every enumeration (the names preset files use, from the field table),
// defaultSubdivisions, presetToJson and savePreset: every key of the field table in its order
// (core/scene/field_table.h: a light's `orbit` only when given), then `check` and `sweep` when
// given, numbers as the shortest decimal that reads back as the same float, written atomically.
//
// It does not read or validate presets (preset_read.cpp).
#include "core/scene/preset.h"

#include "core/io/file_io.h"
#include "core/io/number_format.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

//----------------------------------------------------------------------------------------
// Names and defaults
//----------------------------------------------------------------------------------------

glm::ivec2 defaultSubdivisions(Builtin builtin) {
    switch (builtin) {
    case Builtin::Sphere: return {64, 32};
    case Builtin::Cube: return {1, 1};
    case Builtin::Plane: return {16, 16};
    case Builtin::Torus: return {64, 32};
    }
    return {1, 1};
}

std::string_view toString(Builtin v) { return choiceName(kBuiltinChoices, static_cast<int>(v)); }
std::string_view toString(Shading v) { return choiceName(kShadingChoices, static_cast<int>(v)); }
std::string_view toString(NormalMatrixMode v) { return choiceName(kNormalMatrixChoices, static_cast<int>(v)); }
std::string_view toString(BrdfModel v) { return choiceName(kBrdfChoices, static_cast<int>(v)); }
std::string_view toString(Distribution v) { return choiceName(kDistributionChoices, static_cast<int>(v)); }
std::string_view toString(FresnelMode v) { return choiceName(kFresnelChoices, static_cast<int>(v)); }
std::string_view toString(LightType v) { return choiceName(kLightTypeChoices, static_cast<int>(v)); }

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

// `display`: what differs from the defaults.
Json displayJson(const OpeningDisplay& d) {
    Json display = Json::object();
    if (!d.view.empty()) {
        display["view"] = d.view;
    }
    if (d.light != 1) {
        display["light"] = d.light;
    }
    if (d.compare) {
        display["compare"] = *d.compare;
    }
    if (d.wipe) {
        display["wipe"] = true;
    }
    if (d.wireframe) {
        display["wireframe"] = true;
    }
    if (!d.plots.empty()) {
        display["plots"] = d.plots;
    }
    return display;
}

// A row's value as the file writes it.
Json rowJson(const FieldRow& row, Preset& p, LightDesc* light) {
    switch (row.kind) {
    case FieldKind::Number: return number(fieldValue<float>(row, p, light));
    case FieldKind::Vec3:
    case FieldKind::Color:
    case FieldKind::Direction: return vec3(fieldValue<glm::vec3>(row, p, light));
    case FieldKind::Int2: {
        const glm::ivec2& v = fieldValue<glm::ivec2>(row, p, light);
        return Json::array({v.x, v.y});
    }
    case FieldKind::Switch: return fieldValue<bool>(row, p, light);
    case FieldKind::Text: return fieldValue<std::string>(row, p, light);
    case FieldKind::Choice: return choiceName(row.choices, choiceValue(row, p, light));
    }
    return nullptr;
}

// The rows of `object` ("" for the top level, "lights[]" for one light) and the objects below it,
// in the table's order; an object none of whose rows is written is left out (a light's orbit).
Json rowsJson(std::string_view object, Preset& p, LightDesc* light) {
    Json j = Json::object();
    for (const FieldRow& row : fieldRows()) {
        const FieldPlace place = fieldPlace(row, object);
        const std::string key(place.key);
        if (place.where == FieldPlace::Member) {
            if (!row.written || row.written(p, light)) {
                j[key] = rowJson(row, p, light);
            }
        } else if (place.where == FieldPlace::Below && !j.contains(key)) { // written where its first row comes
            if (place.array) {
                Json lights = Json::array();
                for (LightDesc& l : p.lights) {
                    lights.push_back(rowsJson(place.child, p, &l));
                }
                j[key] = lights;
            } else if (Json sub = rowsJson(place.child, p, light); !sub.empty()) {
                j[key] = sub;
            }
        }
    }
    return j;
}

Json presetJson(const Preset& preset) {
    Preset p = preset; // the rows' addresses are of a Preset to edit; writing changes nothing
    Json j;
    j["format"] = kPresetFormat;
    j["version"] = kPresetVersion;
    Json rows = rowsJson("", p, nullptr);
    for (auto& [key, value] : rows.items()) {
        j[key] = std::move(value);
    }
    // `check` and `sweep` only when given: presets without them are written as before they existed.
    if (!p.check.empty()) {
        j["check"] = checkJson(p.check);
    }
    if (!p.sweep.empty()) {
        j["sweep"] = p.sweep;
    }
    // The lecture's parts likewise (core/scene/preset.h OpeningDisplay, notes, compare).
    if (!p.display.empty()) {
        j["display"] = displayJson(p.display);
    }
    if (!p.notes.empty()) {
        j["notes"] = p.notes;
    }
    if (!p.compare.empty()) {
        j["compare"] = Json::parse(std::string_view(p.compare)); // minified when read: valid JSON (a string_view: one parser instantiation)
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
    // Nor one over the size every reader refuses (a fit of a preset near the limit writes every key).
    const std::string text = jsonText(json);
    if (text.size() > kMaxPresetBytes) {
        diagnostics.push_back({file.string(), "",
                               "refusing to save a preset of " + std::to_string(text.size()) + " bytes, more than the " +
                                   std::to_string(kMaxPresetBytes) + " a preset may have (so no reader would open it)" +
                                   (preset.description.size() > text.size() / 2 ? "; shorten its description" : "")});
        return false;
    }
    std::string error;
    if (!writeFileAtomic(file, text, error)) {
        diagnostics.push_back({file.string(), "", error});
        return false;
    }
    return true;
}

} // namespace lab
