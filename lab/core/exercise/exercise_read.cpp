// exercise_read.cpp — reading an exercise file: every problem with its JSON path.
#include "core/exercise/exercise.h"

#include "core/exercise/preset_fields.h"
#include "core/io/file_io.h"
#include "core/io/json_text.h"
#include "core/io/safe_text.h"
#include "core/io/suggest.h"
#include "core/scene/file_header.h"
#include "core/scene/limits.h"
#include "core/scene/preset_reader.h"

#include <algorithm>
#include <cmath>

namespace lab {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxJsonDepth = 32;
constexpr std::string_view kExerciseKeys[] = {"format", "version", "title",     "instructions",
                                              "start",  "target",  "open",      "tolerance", "hints"};
constexpr std::string_view kToleranceKeys[] = {"pixel_tolerance", "max_failing", "max_mean", "fields"};

std::string describe(const PresetJson& v) {
    switch (v.type()) {
    case PresetJson::value_t::object: return "an object";
    case PresetJson::value_t::array: return "an array";
    case PresetJson::value_t::string: return "a string";
    case PresetJson::value_t::boolean: return "a boolean";
    case PresetJson::value_t::null: return "null";
    default: return "a number";
    }
}

struct Reading {
    const std::string& file;
    Diagnostics& out;
    void error(std::string where, std::string message) { out.push_back({file, std::move(where), std::move(message)}); }
};

bool readHeader(const PresetJson& json, Reading& r) {
    if (std::optional<HeaderProblem> problem = fileHeaderProblem(json, kExerciseFile)) {
        r.error(problem->key, problem->message);
        return false;
    }
    return true;
}

std::optional<std::string> readText(const PresetJson& json, std::string_view key, bool required, Reading& r) {
    auto it = json.find(key);
    if (it == json.end()) {
        if (required) {
            r.error(std::string(key), "missing; expected a string");
        }
        return std::nullopt;
    }
    if (!it->is_string()) {
        r.error(std::string(key), "expected a string, got " + describe(*it));
        return std::nullopt;
    }
    std::string text = it->get<std::string>();
    if (hasNul(text)) {
        r.error(std::string(key), "holds a NUL byte");
        return std::nullopt;
    }
    return text;
}

void readTolerance(const PresetJson& t, Exercise& e, const std::vector<const PresetJson*>& examples,
                   const PresetJson& target, Reading& r) {
    if (!t.is_object()) {
        r.error("tolerance", "expected an object, got " + describe(t));
        return;
    }
    for (const auto& [key, value] : t.items()) {
        std::string where = "tolerance." + key;
        if (std::find(std::begin(kToleranceKeys), std::end(kToleranceKeys), key) == std::end(kToleranceKeys)) {
            r.error("tolerance." + printable(key, true), "unknown key" + suggestion(key, kToleranceKeys));
            continue;
        }
        if (key == "fields") {
            if (!value.is_object()) {
                r.error(where, "expected an object of field paths and numbers, got " + describe(value));
                continue;
            }
            for (const auto& [typed, within] : value.items()) {
                std::string at = where + "." + printable(typed, true);
                const std::string field = canonicalPath(typed);
                const PresetJson* v = fieldAt(target, field);
                if (!knownFieldPath(field, examples)) {
                    r.error(at, "no such field in a preset");
                } else if (!fieldIsOpen(e, field) || alwaysFree(field)) {
                    r.error(at, "is not an open field; a tolerance applies only to a field in \"open\"");
                } else if (std::any_of(e.tolerance.fields.begin(), e.tolerance.fields.end(),
                                       [&](const auto& f) { return f.field == field; })) {
                    r.error(at, "is listed twice (" + inQuotes(field) + ")"); // "lights[00]" is "lights[0]"
                } else if (!v || !(v->is_number() || (v->is_array() && !v->empty() &&
                                                      std::all_of(v->begin(), v->end(), [](auto& x) { return x.is_number(); })))) {
                    r.error(at, "a field tolerance needs a number or numbers; this field is " + (v ? describe(*v) : "absent"));
                } else if (!within.is_number()) {
                    r.error(at, "expected a number >= 0, got " + shortened(within.dump(), 40));
                } else if (double d = within.get<double>(); !(d >= limits::kFieldTolerance.min && d <= limits::kFieldTolerance.max)) {
                    // (compared as read: 1e308 becomes an infinite float, which would pass anything)
                    r.error(at, std::string("must be ") + limits::kFieldTolerance.text + ", got " + shortened(within.dump(), 40));
                } else {
                    e.tolerance.fields.push_back({field, static_cast<float>(d)});
                }
            }
            continue;
        }
        if (!value.is_number() || !std::isfinite(value.get<double>())) {
            r.error(where, "expected a number, got " + shortened(value.dump(), 40));
            continue;
        }
        double v = value.get<double>();
        if (key == "pixel_tolerance") {
            if (!value.is_number_integer() && !value.is_number_unsigned() ? v != std::floor(v) : false) {
                r.error(where, "expected a whole number of levels, got " + value.dump());
            } else if (v < 0 || v > 255) {
                r.error(where, "expected 0 to 255 levels, got " + value.dump());
            } else {
                e.tolerance.pixelTolerance = static_cast<int>(v);
            }
        } else if (key == "max_failing") {
            if (v < 0 || v > 1) {
                r.error(where, "expected a share from 0 to 1 (0.01 is 1%), got " + value.dump());
            } else {
                e.tolerance.maxFailing = static_cast<float>(v);
            }
        } else if (v < 0 || v > 255) {
            r.error(where, "expected 0 to 255 levels, got " + value.dump());
        } else {
            e.tolerance.maxMean = static_cast<float>(v);
        }
    }
}

// Every field path of a full preset value, for the suggestions of an unknown `open` path.
void leafPaths(const PresetJson& v, const std::string& path, std::vector<std::string>& out) {
    if (v.is_object()) {
        for (const auto& [key, value] : v.items()) {
            std::string p = path.empty() ? key : path + "." + key;
            out.push_back(p);
            leafPaths(value, p, out);
        }
    } else if (v.is_array() && !v.empty() && v[0].is_object()) {
        for (std::size_t i = 0; i < v.size(); ++i) {
            leafPaths(v[i], path + "[" + std::to_string(i) + "]", out);
        }
    }
}

} // namespace

bool isExerciseText(std::string_view text) {
    if (!jsonNestingWithin(text, kMaxJsonDepth)) {
        return false;
    }
    PresetJson json = PresetJson::parse(text, nullptr, false);
    if (json.is_discarded() || !json.is_object()) {
        return false;
    }
    auto format = json.find("format");
    return format != json.end() && format->is_string() && format->get<std::string>() == kExerciseFormat;
}

namespace {

// `start` (a preset object) and `target` (a patch over it, or a whole preset): true when both read.
bool readScenes(const PresetJson& json, Exercise& e, const std::string& displayName,
                const std::optional<fs::path>& folder, PresetJson& startValue, PresetJson& targetValue, Reading& r) {
    auto start = json.find("start");
    auto target = json.find("target");
    if (start == json.end()) {
        r.error("start", "missing; expected a preset object (the scene the student starts from)");
        return false;
    }
    if (!start->is_object()) {
        r.error("start", "expected a preset object, got " + describe(*start));
        return false;
    }
    std::optional<Preset> p = parseInlinePreset(start->dump(), displayName, "start", folder, r.out);
    if (!p) {
        return false;
    }
    e.start = *p;
    startValue = presetValue(e.start);
    if (target == json.end()) {
        r.error("target", "missing; expected a preset object, or the fields that differ from start");
        return false;
    }
    if (!target->is_object()) {
        r.error("target", "expected a preset object, or an object of the fields that differ from start, got " +
                              describe(*target));
        return false;
    }
    PresetJson merged = mergePreset(startValue, *target);
    std::optional<Preset> t = parseInlinePreset(merged.dump(), displayName, "target", folder, r.out);
    if (!t) {
        return false;
    }
    e.target = *t;
    targetValue = presetValue(e.target);
    return true;
}

// `open`: the field paths a student may change, each known, none twice.
void readOpen(const PresetJson& json, Exercise& e, const std::vector<const PresetJson*>& examples, Reading& r) {
    auto open = json.find("open");
    if (open == json.end()) {
        r.error("open", "missing; expected the JSON paths of the fields the student may change, e.g. [\"material.shininess\"]");
        return;
    }
    if (!open->is_array() || open->empty()) {
        r.error("open", "expected a non-empty array of field paths, got " + (open->is_array() ? "[]" : describe(*open)));
        return;
    }
    std::vector<std::string> known;
    leafPaths(presetValue(Preset{}), "", known);
    for (std::size_t i = 0; i < open->size(); ++i) {
        const PresetJson& path = (*open)[i];
        std::string where = "open[" + std::to_string(i) + "]";
        if (!path.is_string()) {
            r.error(where, "expected a field path, got " + describe(path));
        } else if (!knownFieldPath(path.get<std::string>(), examples)) {
            r.error(where, "no field " + inQuotes(path.get<std::string>()) + " in a preset" +
                               suggestion(path.get<std::string>(), known));
        } else if (std::find(e.open.begin(), e.open.end(), canonicalPath(path.get<std::string>())) != e.open.end()) {
            r.error(where, inQuotes(path.get<std::string>()) + " is listed twice");
        } else {
            e.open.push_back(canonicalPath(path.get<std::string>())); // "lights[00]" is "lights[0]"
        }
    }
}

// The target differs from the start only in open (or free) fields, and in at least one open one.
void checkTarget(const Exercise& e, const PresetJson& startValue, const PresetJson& targetValue, Reading& r) {
    bool differs = false;
    for (const std::string& field : changedFields(startValue, targetValue)) {
        if (alwaysFree(field)) {
            continue;
        }
        if (!fieldIsOpen(e, field)) {
            r.error("target." + field, "differs from start, but the field is not open: a student could not reach "
                                       "it (add it to \"open\" or give the target start's value)");
        } else {
            differs = true;
        }
    }
    if (!differs) {
        r.error("target", "equals start in every open field: the exercise would be solved before it begins");
    }
}

void readHints(const PresetJson& hints, Exercise& e, Reading& r) {
    if (!hints.is_array()) {
        r.error("hints", "expected an array of strings, got " + describe(hints));
        return;
    }
    if (hints.size() > kMaxExerciseHints) {
        r.error("hints", "at most " + std::to_string(kMaxExerciseHints) + " hints, got " + std::to_string(hints.size()));
        return;
    }
    for (std::size_t i = 0; i < hints.size(); ++i) {
        const PresetJson& h = hints[i];
        if (!h.is_string() || h.get<std::string>().empty() || hasNul(h.get<std::string>())) {
            r.error("hints[" + std::to_string(i) + "]",
                    "expected a non-empty string, got " + (h.is_string() ? std::string("an empty string") : describe(h)));
        } else {
            e.hints.push_back(h.get<std::string>());
        }
    }
}

} // namespace

std::optional<Exercise> parseExercise(std::string_view text, const std::string& displayName,
                                      const std::optional<fs::path>& folder, Diagnostics& diagnostics) {
    std::optional<PresetJson> json = preset_detail::parseJsonObject(text, displayName, kMaxJsonDepth, "an exercise", diagnostics);
    if (!json) {
        return std::nullopt;
    }
    Diagnostics out;
    Reading r{displayName, out};
    if (!readHeader(*json, r)) {
        diagnostics.insert(diagnostics.end(), out.begin(), out.end());
        return std::nullopt;
    }
    Exercise e;
    for (const auto& [key, value] : json->items()) {
        if (std::find(std::begin(kExerciseKeys), std::end(kExerciseKeys), key) == std::end(kExerciseKeys)) {
            r.error(printable(key, true), "unknown key" + suggestion(key, kExerciseKeys));
        }
    }
    if (auto title = readText(*json, "title", true, r)) {
        if (title->empty()) {
            r.error("title", "is empty; an exercise needs a title");
        }
        e.title = *title;
    }
    e.instructions = readText(*json, "instructions", true, r).value_or("");
    PresetJson startValue, targetValue;
    bool scenes = readScenes(*json, e, displayName, folder, startValue, targetValue, r);
    const std::vector<const PresetJson*> examples = {&startValue, &targetValue};
    readOpen(*json, e, examples, r);
    if (scenes && out.empty()) {
        checkTarget(e, startValue, targetValue, r);
    }
    if (auto t = json->find("tolerance"); t != json->end()) {
        readTolerance(*t, e, examples, targetValue, r);
    }
    if (auto hints = json->find("hints"); hints != json->end()) {
        readHints(*hints, e, r);
    }
    if (!out.empty()) {
        diagnostics.insert(diagnostics.end(), out.begin(), out.end());
        return std::nullopt;
    }
    return e;
}

std::optional<LoadedExercise> loadExercise(const fs::path& file, Diagnostics& diagnostics) {
    std::string error;
    std::optional<std::string> text = readFile(file, kMaxExerciseBytes, error);
    if (!text) {
        diagnostics.push_back({file.string(), "", error});
        return std::nullopt;
    }
    fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    std::optional<Exercise> e = parseExercise(*text, file.string(), folder, diagnostics);
    if (!e) {
        return std::nullopt;
    }
    return LoadedExercise{std::move(*e), file};
}

} // namespace lab
