// exercise.cpp — the exercise file: reading with JSON paths, writing, locked fields, the score.
#include "core/exercise/exercise.h"

#include "core/exercise/preset_fields.h"
#include "core/io/file_io.h"
#include "core/io/json_text.h"
#include "core/io/safe_text.h"
#include "core/io/suggest.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

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

std::optional<PresetJson> parseJson(std::string_view text, const std::string& file, Diagnostics& diagnostics) {
    if (!jsonNestingWithin(text, kMaxJsonDepth)) {
        diagnostics.push_back({file, "", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels"});
        return std::nullopt;
    }
    try {
        PresetJson json = PresetJson::parse(text);
        if (!json.is_object()) {
            diagnostics.push_back({file, "", "an exercise is a JSON object, got " + describe(json)});
            return std::nullopt;
        }
        return json;
    } catch (const PresetJson::parse_error& e) {
        std::string what = e.what();
        std::size_t colon = what.rfind(": ");
        diagnostics.push_back({file, lineColumn(text, e.byte == 0 ? 0 : e.byte - 1),
                               "invalid JSON: " + shortened(colon == std::string::npos ? what : what.substr(colon + 2), 200)});
    } catch (const PresetJson::exception& e) {
        diagnostics.push_back({file, "", "invalid JSON: " + shortened(e.what(), 200)});
    }
    return std::nullopt;
}

bool readHeader(const PresetJson& json, Reading& r) {
    const std::string expected = "\"" + std::string(kExerciseFormat) + "\"";
    auto format = json.find("format");
    if (format == json.end()) {
        r.error("format", "missing; expected " + expected);
        return false;
    }
    if (!format->is_string() || format->get<std::string>() != kExerciseFormat) {
        std::string got = shortened(format->dump(), 80);
        r.error("format", "expected " + expected + ", got " + got +
                              (got == "\"" + std::string(kPresetFormat) + "\"" ? " (this is a preset, not an exercise)" : ""));
        return false;
    }
    auto version = json.find("version");
    if (version == json.end()) {
        r.error("version", "missing; expected " + std::to_string(kExerciseVersion));
    } else if (!version->is_number_integer() && !version->is_number_unsigned()) {
        r.error("version", "expected an integer, got " + shortened(version->dump(), 40));
    } else if (version->get<double>() > kExerciseVersion) {
        r.error("version", "version " + version->dump() + " is newer than this program reads (" +
                               std::to_string(kExerciseVersion) + "); update Lighting Lab");
    } else if (version->get<double>() < 1) {
        r.error("version", "expected " + std::to_string(kExerciseVersion) + ", got " + version->dump());
    } else {
        return true;
    }
    return false;
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
            for (const auto& [field, within] : value.items()) {
                std::string at = where + "." + printable(field, true);
                const PresetJson* v = fieldAt(target, field);
                if (!knownFieldPath(field, examples)) {
                    r.error(at, "no such field in a preset");
                } else if (!fieldIsOpen(e, field) || alwaysFree(field)) {
                    r.error(at, "is not an open field; a tolerance applies only to a field in \"open\"");
                } else if (!v || !(v->is_number() || (v->is_array() && !v->empty() &&
                                                      std::all_of(v->begin(), v->end(), [](auto& x) { return x.is_number(); })))) {
                    r.error(at, "a field tolerance needs a number or numbers; this field is " + (v ? describe(*v) : "absent"));
                } else if (!within.is_number() || !std::isfinite(within.get<double>()) || within.get<double>() < 0) {
                    r.error(at, "expected a number >= 0, got " + shortened(within.dump(), 40));
                } else {
                    e.tolerance.fields.push_back({field, within.get<float>()});
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

std::optional<fs::path> modelFile(const PresetJson& value, const fs::path& folder) {
    const PresetJson* gltf = fieldAt(value, "model.gltf");
    if (!gltf || !gltf->is_string()) {
        return std::nullopt;
    }
    std::string error;
    std::optional<fs::path> file = resolveModelPath(gltf->get<std::string>(), folder.empty() ? fs::path(".") : folder, error);
    if (!file) {
        return std::nullopt;
    }
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(*file, ec);
    return ec ? *file : canonical;
}

} // namespace

Tolerance ExerciseTolerance::image() const {
    Tolerance t = kExerciseTolerance;
    if (pixelTolerance) t.pixelTolerance = *pixelTolerance;
    if (maxFailing) t.maxFailingShare = *maxFailing;
    if (maxMean) t.maxMeanDifference = *maxMean;
    return t;
}

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

std::optional<Exercise> parseExercise(std::string_view text, const std::string& displayName,
                                      const std::optional<fs::path>& folder, Diagnostics& diagnostics) {
    std::optional<PresetJson> json = parseJson(text, displayName, diagnostics);
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

    // start: a preset object; target: a patch over it, or a whole preset.
    bool scenes = false;
    PresetJson startValue, targetValue;
    auto start = json->find("start");
    auto target = json->find("target");
    if (start == json->end()) {
        r.error("start", "missing; expected a preset object (the scene the student starts from)");
    } else if (!start->is_object()) {
        r.error("start", "expected a preset object, got " + describe(*start));
    } else if (std::optional<Preset> p = parseInlinePreset(start->dump(), displayName, "start", folder, out)) {
        e.start = *p;
        startValue = presetValue(e.start);
        if (target == json->end()) {
            r.error("target", "missing; expected a preset object, or the fields that differ from start");
        } else if (!target->is_object()) {
            r.error("target", "expected a preset object, or an object of the fields that differ from start, got " +
                                  describe(*target));
        } else {
            PresetJson merged = mergePreset(startValue, *target);
            if (std::optional<Preset> t = parseInlinePreset(merged.dump(), displayName, "target", folder, out)) {
                e.target = *t;
                targetValue = presetValue(e.target);
                scenes = true;
            }
        }
    }

    const std::vector<const PresetJson*> examples = {&startValue, &targetValue};
    auto open = json->find("open");
    if (open == json->end()) {
        r.error("open", "missing; expected the JSON paths of the fields the student may change, e.g. [\"material.shininess\"]");
    } else if (!open->is_array() || open->empty()) {
        r.error("open", "expected a non-empty array of field paths, got " + (open->is_array() ? "[]" : describe(*open)));
    } else {
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
            } else if (std::find(e.open.begin(), e.open.end(), path.get<std::string>()) != e.open.end()) {
                r.error(where, inQuotes(path.get<std::string>()) + " is listed twice");
            } else {
                e.open.push_back(path.get<std::string>());
            }
        }
    }
    if (scenes && out.empty()) {
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
    if (auto t = json->find("tolerance"); t != json->end()) {
        readTolerance(*t, e, examples, targetValue, r);
    }
    if (auto hints = json->find("hints"); hints != json->end()) {
        if (!hints->is_array()) {
            r.error("hints", "expected an array of strings, got " + describe(*hints));
        } else if (hints->size() > kMaxExerciseHints) {
            r.error("hints", "at most " + std::to_string(kMaxExerciseHints) + " hints, got " + std::to_string(hints->size()));
        } else {
            for (std::size_t i = 0; i < hints->size(); ++i) {
                const PresetJson& h = (*hints)[i];
                if (!h.is_string() || h.get<std::string>().empty() || hasNul(h.get<std::string>())) {
                    r.error("hints[" + std::to_string(i) + "]", "expected a non-empty string, got " + describe(h));
                } else {
                    e.hints.push_back(h.get<std::string>());
                }
            }
        }
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

std::string exerciseToJson(const Exercise& e) {
    PresetJson j;
    j["format"] = kExerciseFormat;
    j["version"] = kExerciseVersion;
    j["title"] = e.title;
    j["instructions"] = e.instructions;
    PresetJson start = presetValue(e.start);
    j["start"] = start;
    j["target"] = presetPatch(start, presetValue(e.target));
    j["open"] = e.open;
    if (!e.tolerance.empty()) {
        PresetJson t = PresetJson::object();
        if (e.tolerance.pixelTolerance) t["pixel_tolerance"] = *e.tolerance.pixelTolerance;
        if (e.tolerance.maxFailing) t["max_failing"] = *e.tolerance.maxFailing;
        if (e.tolerance.maxMean) t["max_mean"] = *e.tolerance.maxMean;
        if (!e.tolerance.fields.empty()) {
            PresetJson fields = PresetJson::object();
            for (const FieldTolerance& f : e.tolerance.fields) {
                fields[f.field] = f.within;
            }
            t["fields"] = fields;
        }
        j["tolerance"] = t;
    }
    if (!e.hints.empty()) {
        j["hints"] = e.hints;
    }
    return j.dump(2) + "\n";
}

bool saveExercise(const Exercise& exercise, const fs::path& file, Diagnostics& diagnostics) {
    std::string error;
    if (!writeFileAtomic(file, exerciseToJson(exercise), error)) {
        diagnostics.push_back({file.string(), "", error});
        return false;
    }
    return true;
}

bool fieldIsOpen(const Exercise& exercise, std::string_view path) {
    return alwaysFree(path) ||
           std::any_of(exercise.open.begin(), exercise.open.end(), [&](const std::string& o) { return covers(o, path); });
}

std::vector<std::string> lockedChanges(const Exercise& exercise, const Preset& attempt, const fs::path& exerciseFolder,
                                       const fs::path& attemptFolder) {
    PresetJson start = presetValue(exercise.start), tried = presetValue(attempt);
    // The same model file named from two folders is the same model.
    std::optional<fs::path> a = modelFile(start, exerciseFolder), b = modelFile(tried, attemptFolder);
    if (a && b && *a == *b) {
        tried["model"]["gltf"] = start["model"]["gltf"];
    }
    std::vector<std::string> locked;
    for (std::string& field : changedFields(start, tried)) {
        if (!fieldIsOpen(exercise, field)) {
            locked.push_back(std::move(field));
        }
    }
    return locked;
}

namespace {

// "lights[1].attenuation" as a JSON pointer ("/lights/1/attenuation"), for a path fieldAt found.
PresetJson::json_pointer pointerOf(const std::string& path) {
    PresetJson::json_pointer pointer;
    std::size_t i = 0;
    while (i < path.size()) {
        std::size_t end = path.find_first_of(".[", i);
        if (end != i) {
            pointer /= path.substr(i, end == std::string::npos ? std::string::npos : end - i);
        }
        if (end == std::string::npos) {
            break;
        }
        if (path[end] == '[') {
            std::size_t close = path.find(']', end);
            pointer /= static_cast<std::size_t>(std::stoul(path.substr(end + 1, close - end - 1)));
            i = close + 1;
            i += i < path.size() && path[i] == '.' ? 1 : 0;
        } else {
            i = end + 1;
        }
    }
    return pointer;
}

// `value` at `pointer` in `json` (an array grows by one at its end), or the key or element there
// removed when `value` is null.
void putAt(PresetJson& json, const PresetJson::json_pointer& pointer, const PresetJson* value) {
    PresetJson& parent = json[pointer.parent_pointer()];
    const std::string& last = pointer.back();
    if (parent.is_array()) {
        std::size_t index = std::stoul(last);
        if (!value) {
            if (index < parent.size()) {
                parent.erase(index);
            }
        } else if (index < parent.size()) {
            parent[index] = *value;
        } else {
            parent.push_back(*value);
        }
    } else if (!value) {
        parent.erase(last);
    } else {
        parent[last] = *value;
    }
}

} // namespace

Preset withLockedFieldsOfStart(const Exercise& exercise, const Preset& attempt) {
    PresetJson start = presetValue(exercise.start), kept = presetValue(attempt);
    std::vector<std::string> locked;
    for (const std::string& field : changedFields(start, kept)) {
        if (!fieldIsOpen(exercise, field)) {
            locked.push_back(field);
        }
    }
    if (locked.empty()) {
        return attempt;
    }
    // The attempt, each locked field back at the start's value (or gone where the start has none);
    // from the last path to the first, so that removing lights[2] comes before lights[1].
    for (auto it = locked.rbegin(); it != locked.rend(); ++it) {
        putAt(kept, pointerOf(*it), fieldAt(start, *it));
    }
    // Read back as a preset without a folder: a glTF model (valid where it came from) is set
    // aside for the reading and put back after.
    std::optional<std::string> gltf;
    if (const PresetJson* g = fieldAt(kept, "model.gltf"); g && g->is_string()) {
        gltf = g->get<std::string>();
        kept["model"].erase("gltf");
    }
    Diagnostics ignored;
    std::optional<Preset> p = parseInlinePreset(kept.dump(), "attempt", "", std::nullopt, ignored);
    if (!p) {
        return exercise.start; // (cannot happen: every value came from a preset that read)
    }
    if (gltf) {
        p->model.gltf = *gltf;
        p->model.builtin = attempt.model.builtin;
        p->model.subdivisions = attempt.model.subdivisions;
    }
    return *p;
}

Preset attemptAsScored(const Exercise& exercise, const Preset& attempt) {
    Preset p = attempt;
    p.camera = exercise.target.camera;
    return p;
}

Preset targetAsScored(const Exercise& exercise) { return exercise.target; }

std::string ExerciseScore::summary() const {
    char line[256];
    if (solved) {
        std::snprintf(line, sizeof line, "Solved: %.0f%% of the model's pixels match", std::floor(closeness * 100.0));
        return line;
    }
    std::snprintf(line, sizeof line, "%.0f%% of the model's pixels match", std::floor(closeness * 100.0));
    std::string s = line;
    if (!image.sameSize) {
        return s + "; the renders differ in size";
    }
    if (image.failingShare > tolerance.maxFailingShare) {
        std::snprintf(line, sizeof line, "; %.1f%% of the image differs by more than %d levels (at most %.1f%%)",
                      image.failingShare * 100.0, tolerance.pixelTolerance, tolerance.maxFailingShare * 100.0);
        s += line;
    }
    if (image.meanDifference > tolerance.maxMeanDifference) {
        std::snprintf(line, sizeof line, "; the mean difference is %.2f levels (at most %.2f)", image.meanDifference,
                      tolerance.maxMeanDifference);
        s += line;
    }
    for (const FieldMiss& m : misses) {
        char miss[200];
        std::snprintf(miss, sizeof miss, "; %s is %.3g away (at most %.3g)", m.field.c_str(), double(m.difference),
                      double(m.within));
        s += miss;
    }
    return s;
}

ExerciseScore scoreExercise(const Exercise& exercise, const Preset& attempt, const Image& attemptImage,
                            const Image& targetImage) {
    ExerciseScore score;
    const Tolerance tolerance = exercise.tolerance.image();
    score.tolerance = tolerance;
    score.image = compareImages(attemptImage, targetImage, tolerance);
    if (score.image.sameSize) {
        auto background = [](const glm::vec3& c) {
            glm::vec3 v = glm::round(glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f)) * 255.0f);
            return glm::ivec3(v);
        };
        glm::ivec3 ba = background(attempt.background), bt = background(exercise.target.background);
        std::size_t model = 0, matching = 0;
        const std::size_t n = attemptImage.rgb.size() / 3;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint8_t* a = &attemptImage.rgb[i * 3];
            const std::uint8_t* t = &targetImage.rgb[i * 3];
            bool aBack = true, tBack = true;
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                aBack = aBack && std::abs(int(a[c]) - ba[c]) <= 1;
                tBack = tBack && std::abs(int(t[c]) - bt[c]) <= 1;
                worst = std::max(worst, std::abs(int(a[c]) - int(t[c])));
            }
            if (aBack && tBack) {
                continue;
            }
            ++model;
            matching += worst <= tolerance.pixelTolerance ? 1 : 0;
        }
        score.closeness = model == 0 ? 1.0 : double(matching) / double(model);
    }
    PresetJson tried = presetValue(attempt), target = presetValue(exercise.target);
    for (const FieldTolerance& f : exercise.tolerance.fields) {
        const PresetJson* a = fieldAt(tried, f.field);
        const PresetJson* t = fieldAt(target, f.field);
        float worst = 0.0f;
        if (!a || !t || a->is_number() != t->is_number() || (a->is_array() && a->size() != t->size())) {
            worst = INFINITY;
        } else if (a->is_number()) {
            worst = std::abs(a->get<float>() - t->get<float>());
        } else {
            for (std::size_t i = 0; i < a->size(); ++i) {
                worst = std::max(worst, std::abs((*a)[i].get<float>() - (*t)[i].get<float>()));
            }
        }
        // Within float rounding of the edge counts (0.95 against 1 within 0.05 is 0.0500001 in float).
        if (!(worst <= f.within + 1e-5f * std::max(1.0f, f.within))) {
            score.misses.push_back({f.field, worst, f.within});
        }
    }
    score.solved = score.image.passes(tolerance) && score.misses.empty();
    return score;
}

} // namespace lab
