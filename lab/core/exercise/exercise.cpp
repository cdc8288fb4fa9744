// exercise.cpp — the exercise written out, its locked fields, what is rendered to score an attempt
// (reading: exercise_read.cpp; the score: score.cpp).
#include "core/exercise/exercise.h"

#include "core/exercise/preset_fields.h"
#include "core/io/file_io.h"
#include "core/io/json_text.h"
#include "core/io/number_format.h"
#include "core/io/safe_text.h"
#include "core/io/suggest.h"

#include <algorithm>
#include <cctype>

namespace lab {

namespace fs = std::filesystem;

namespace {

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
        // Floats as they were typed (0.01, not 0.009999999776482582), as presets write them.
        auto number = [](float v) { return PresetJson::parse(std::string_view(shortestFloat(v))); };
        if (e.tolerance.maxFailing) t["max_failing"] = number(*e.tolerance.maxFailing);
        if (e.tolerance.maxMean) t["max_mean"] = number(*e.tolerance.maxMean);
        if (!e.tolerance.fields.empty()) {
            PresetJson fields = PresetJson::object();
            for (const FieldTolerance& f : e.tolerance.fields) {
                fields[f.field] = number(f.within);
            }
            t["fields"] = fields;
        }
        j["tolerance"] = t;
    }
    if (!e.hints.empty()) {
        j["hints"] = e.hints;
    }
    // Indented, with each array of plain values (a colour, a position) on one line as in a preset file.
    // Strings are copied as they are: a '[' in the instructions is text (fuzz_exercise found "dis[tri,
    // bution ... ]" saved with its spaces taken out).
    const std::string text = j.dump(2);
    std::string out;
    bool inString = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (inString || text[k] == '"') {
            out += text[k];
            if (inString && text[k] == '\\' && k + 1 < text.size()) {
                out += text[++k];
            } else if (text[k] == '"') {
                inString = !inString;
            }
            continue;
        }
        std::size_t close = text[k] == '[' ? text.find_first_of("[]{\"", k + 1) : std::string::npos;
        if (close == std::string::npos || text[close] != ']') {
            out += text[k];
            continue;
        }
        out += '[';
        for (std::size_t m = k + 1; m < close; ++m) {
            if (text[m] == ',') {
                out += ", ";
            } else if (!std::isspace(static_cast<unsigned char>(text[m]))) {
                out += text[m];
            }
        }
        out += ']';
        k = close;
    }
    return out + "\n";
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

Preset startAsScored(const Exercise& exercise) { return attemptAsScored(exercise, exercise.start); }

} // namespace lab
