// sweep.cpp — sweep arguments, their validation by the preset reader, the cells and the grid.
#include "core/scene/sweep.h"

#include "core/io/safe_text.h"
#include "core/io/suggest.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace lab {

using Json = nlohmann::ordered_json;

namespace {

//----------------------------------------------------------------------------------------
// Arguments
//----------------------------------------------------------------------------------------

constexpr std::size_t kMaxArgumentBytes = 2000;

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) {
        s.remove_prefix(1);
    }
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) {
        s.remove_suffix(1);
    }
    return s;
}

// A key or value as it goes into a message: escaped, one line, bounded.
std::string shown(std::string_view text) { return printable(shortened(text, 80), true); }

// Every key a sweep could name in `json` (the leaves, and the triplets whole), for suggestions.
void leafKeys(const Json& json, const std::string& path, std::vector<std::string>& out) {
    if (json.is_object()) {
        for (const auto& [key, value] : json.items()) {
            leafKeys(value, path.empty() ? key : path + "." + key, out);
        }
    } else if (json.is_array()) {
        bool numbers = std::all_of(json.begin(), json.end(), [](const Json& e) { return e.is_number(); });
        if (numbers) {
            out.push_back(path);
        }
        for (std::size_t i = 0; i < json.size(); ++i) {
            leafKeys(json[i], path + "[" + std::to_string(i) + "]", out);
        }
    } else {
        out.push_back(path);
    }
}

// ` (did you mean "x"?)` for the closest of the preset's keys within a few edits, else "".
std::string keySuggestion(std::string_view key, const Json& json) {
    std::vector<std::string> keys;
    leafKeys(json, "", keys);
    return suggestion(key, keys);
}

// The value `key` names in `json`, or nullptr with `error`.
Json* findKey(Json& json, const std::string& key, std::string& error) {
    std::optional<std::vector<PathStep>> steps = parseFieldPath(key);
    if (!steps) {
        error = shown(key) + ": not a preset key (a path such as material.shininess or lights[0].attenuation)";
        return nullptr;
    }
    static constexpr std::string_view kFixed[] = {"format", "version", "name", "description", "model", "check", "sweep"};
    if (std::find(std::begin(kFixed), std::end(kFixed), steps->front().name) != std::end(kFixed)) {
        error = shown(key) + ": not a key a sweep varies (it varies the material, the BRDF, the shading, the lights, "
                             "the camera, not the model or the file's name)";
        return nullptr;
    }
    // Keys that no render shows: every cell would be the same picture.
    if (steps->front().name == "plot") {
        error = shown(key) + ": changes no render (it is the plots' incident angle); a sweep varies what the renders show";
        return nullptr;
    }
    if (std::any_of(steps->begin(), steps->end(), [](const PathStep& s) { return s.name == "orbit"; })) {
        error = shown(key) + ": changes no render (a moving light is rendered where the preset puts it); a sweep "
                             "varies what the renders show";
        return nullptr;
    }
    Json* at = &json;
    for (const PathStep& s : *steps) {
        if (!s.isIndex() && at->is_object() && at->contains(s.name)) {
            at = &(*at)[s.name];
        } else if (s.isIndex() && at->is_array() && s.index < at->size()) {
            at = &(*at)[s.index];
        } else {
            error = shown(key) + ": unknown key" + (s.isIndex() && at->is_array()
                                                        ? " (the preset has " + std::to_string(at->size()) + ")"
                                                        : keySuggestion(key, json));
            return nullptr;
        }
    }
    bool numbers = at->is_array() && std::all_of(at->begin(), at->end(), [](const Json& e) { return e.is_number(); });
    if (at->is_structured() && !numbers) {
        error = shown(key) + ": not a single value; name one of its keys" + keySuggestion(key + ".", json);
        return nullptr;
    }
    return at;
}

// The JSON a typed value stands for at `target`: JSON where it parses as such, else a name (so
// `blinn-phong` needs no quotes); a single number for a triplet is all three.
Json valueJson(const std::string& text, const Json& target) {
    Json value;
    try {
        value = Json::parse(std::string_view(text)); // one parser instantiation, as preset_read.cpp's
    } catch (const Json::exception&) {
        value = text;
    }
    if (target.is_array() && value.is_number()) {
        return Json::array_t(target.size(), value);
    }
    return value;
}

} // namespace

std::optional<SweepAxis> parseSweepAxis(std::string_view text, std::string& error) {
    if (text.size() > kMaxArgumentBytes) {
        error = "longer than " + std::to_string(kMaxArgumentBytes) + " bytes";
        return std::nullopt;
    }
    std::size_t equals = text.find('=');
    if (equals == std::string_view::npos) {
        error = inQuotes(text, 80) + ": expected KEY=V1,V2,... such as material.shininess=10,20,30,50";
        return std::nullopt;
    }
    SweepAxis axis;
    axis.key = trimmed(text.substr(0, equals));
    if (axis.key.empty()) {
        error = inQuotes(text, 80) + ": no key before '='";
        return std::nullopt;
    }
    std::string_view values = text.substr(equals + 1);
    int depth = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= values.size(); ++i) {
        char c = i < values.size() ? values[i] : ',';
        depth += c == '[' ? 1 : c == ']' ? -1 : 0;
        // A bracket left open at the end, or closed without being opened, is no value: refused
        // rather than cut off (the last value of "[1,1,1],[0,0,0" was dropped without a word).
        if (depth < 0 || (i == values.size() && depth > 0)) {
            error = shown(axis.key) + ": value " + std::to_string(axis.values.size() + 1) + " " +
                    inQuotes(trimmed(values.substr(start, i - start + (depth < 0 ? 1 : 0))), 80) +
                    (depth < 0 ? " closes a ']' it did not open" : " leaves a '[' open");
            return std::nullopt;
        }
        if (c == ',' && depth == 0) {
            std::string_view v = trimmed(values.substr(start, i - start));
            if (v.empty()) {
                error = shown(axis.key) + ": value " + std::to_string(axis.values.size() + 1) +
                        " is empty (expected KEY=V1,V2,...)";
                return std::nullopt;
            }
            axis.values.emplace_back(v);
            start = i + 1;
        }
    }
    if (axis.values.size() > kMaxSweepValues) {
        error = shown(axis.key) + ": at most " + std::to_string(kMaxSweepValues) + " values, got " +
                std::to_string(axis.values.size());
        return std::nullopt;
    }
    return axis;
}

std::optional<SweepCells> sweepCells(const LoadedPreset& base, const std::vector<SweepAxis>& axes, std::string& error) {
    if (axes.empty() || axes.size() > kMaxSweepKeys) {
        error = "one or two keys (one along the columns, one down the rows), got " + std::to_string(axes.size());
        return std::nullopt;
    }
    if (axes.size() == 2) {
        const std::string first = canonicalPath(axes[0].key), second = canonicalPath(axes[1].key);
        if (overlaps(first, second)) {
            error = first == second ? shown(axes[0].key) + (axes[0].key == axes[1].key ? "" : " and " + shown(axes[1].key)) +
                                          ": the same key twice"
                                    : shown(axes[0].key) + " and " + shown(axes[1].key) + " overlap";
            return std::nullopt;
        }
    }
    for (const SweepAxis& axis : axes) {
        if (axis.values.empty() || axis.values.size() > kMaxSweepValues) {
            error = shown(axis.key) + ": from 1 to " + std::to_string(kMaxSweepValues) + " values, got " +
                    std::to_string(axis.values.size());
            return std::nullopt;
        }
    }
    // The preset as its file would hold it, without the model: a sweep never varies the model,
    // and left out it needs no folder to resolve against (the base's model is put back after).
    const std::string saved = presetToJson(base.preset);
    Json json = Json::parse(std::string_view(saved));
    json.erase("model");
    json.erase("check"); // how lab check compares the base, and the base's own sweep: not the cells'
    json.erase("sweep");
    // Each value is checked on its own (so the message is about it), then each cell made.
    std::vector<std::vector<Json>> values(axes.size());
    for (std::size_t a = 0; a < axes.size(); ++a) {
        Json probe = json;
        Json* target = findKey(probe, axes[a].key, error);
        if (!target) {
            return std::nullopt;
        }
        const Json original = *target; // the shape a value takes (a number for a triplet is all three)
        for (const std::string& text : axes[a].values) {
            *target = valueJson(text, original);
            values[a].push_back(*target);
            Diagnostics diagnostics;
            if (!parsePreset(probe.dump(), "", std::nullopt, diagnostics) && !diagnostics.empty()) {
                const Diagnostic& d = diagnostics.front();
                error = shown(axes[a].key) + "=" + shown(text) + ": " +
                        (d.where == axes[a].key || d.where.empty() ? "" : d.where + ": ") + d.message;
                return std::nullopt;
            }
        }
    }
    SweepCells cells;
    cells.columns = static_cast<int>(axes[0].values.size());
    cells.rows = axes.size() > 1 ? static_cast<int>(axes[1].values.size()) : 1;
    OmittedKeys omitted = base.omitted;
    for (const SweepAxis& axis : axes) { // a swept camera or light is the user's, not framed for the model
        std::string section = axis.key.substr(0, axis.key.find_first_of(".["));
        omitted.camera = omitted.camera && section != "camera";
        omitted.lights = omitted.lights && section != "lights";
    }
    for (int row = 0; row < cells.rows; ++row) {
        for (int column = 0; column < cells.columns; ++column) {
            Json cell = json;
            *findKey(cell, axes[0].key, error) = values[0][static_cast<std::size_t>(column)];
            if (axes.size() > 1) {
                *findKey(cell, axes[1].key, error) = values[1][static_cast<std::size_t>(row)];
            }
            Diagnostics diagnostics;
            std::optional<Preset> preset = parsePreset(cell.dump(), "", std::nullopt, diagnostics);
            if (!preset) { // each value passed alone; together they may still break a rule (far > near)
                error = shown(axes[0].key) + "=" + shown(axes[0].values[static_cast<std::size_t>(column)]) +
                        (axes.size() > 1 ? " with " + shown(axes[1].key) + "=" + shown(axes[1].values[static_cast<std::size_t>(row)]) : "") +
                        ": " + (diagnostics.empty() ? "refused" : diagnostics.front().str());
                return std::nullopt;
            }
            preset->model = base.preset.model;
            cells.presets.push_back(LoadedPreset{std::move(*preset), base.file, omitted});
        }
    }
    error.clear();
    return cells;
}

//----------------------------------------------------------------------------------------
// Keys for the GUI
//----------------------------------------------------------------------------------------

namespace {

// Where a row's suggestions come in the list, or -1 for none: the BRDF's own lobe and numbers
// (shininess n; or roughness m and ior), the material's colours, the other BRDF's lobe parameter
// (for a grid across BRDFs: brdf along the other axis), the choices and the ambient light, the
// lights, the camera. A row that does not apply (a spot's cut-off on a point light) is none.
int suggestionRank(const FieldRow& row, bool applying) {
    const bool surface = row.group == FieldGroup::Brdf || row.group == FieldGroup::Material;
    if (!applying) {
        return (row.style & kStyleLobe) ? 2 : -1;
    }
    if (surface && row.kind == FieldKind::Number) {
        return 0;
    }
    if (row.group == FieldGroup::Material) {
        return 1;
    }
    return row.group == FieldGroup::Lights ? 4 : row.group == FieldGroup::Camera ? 5 : 3;
}

// A row's suggestions for `path`: its `sweep` text, alternatives split at ';', each optionally
// "[i]=..." for one part of the field.
void addSuggestions(const FieldRow& row, const std::string& path, std::vector<SweepKeySuggestion>& keys) {
    std::string_view text = row.sweep;
    while (!text.empty()) {
        std::string_view one = text.substr(0, text.find(';'));
        text.remove_prefix(std::min(text.size(), one.size() + 1));
        std::size_t equals = one.starts_with('[') ? one.find('=') : std::string_view::npos;
        keys.push_back(equals == std::string_view::npos
                           ? SweepKeySuggestion{path, std::string(one)}
                           : SweepKeySuggestion{path + std::string(one.substr(0, equals)), std::string(one.substr(equals + 1))});
    }
}

} // namespace

std::vector<SweepKeySuggestion> sweepKeySuggestions(const Preset& preset) {
    // The rows with suggested values, by rank (suggestionRank) and then in the table's order.
    std::vector<std::pair<int, SweepKeySuggestion>> ranked;
    for (const FieldRow& row : fieldRows()) {
        if (row.sweep.empty()) {
            continue;
        }
        std::vector<SweepKeySuggestion> keys;
        int rank = -1;
        if (!isLightRow(row)) {
            rank = suggestionRank(row, applies(row, preset, nullptr));
            addSuggestions(row, std::string(row.path), keys);
        }
        for (std::size_t i = 0; isLightRow(row) && i < preset.lights.size(); ++i) {
            if (applies(row, preset, &preset.lights[i])) {
                rank = suggestionRank(row, true);
                addSuggestions(row, fieldPath(row, static_cast<int>(i)), keys);
            }
        }
        for (SweepKeySuggestion& k : keys) {
            if (rank >= 0) {
                ranked.emplace_back(rank, std::move(k));
            }
        }
    }
    std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<SweepKeySuggestion> keys;
    for (auto& [rank, key] : ranked) {
        keys.push_back(std::move(key));
    }
    return keys;
}

} // namespace lab
