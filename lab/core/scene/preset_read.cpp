// preset_read.cpp — reading preset JSON: every problem reported with its JSON path.
//
// Owns parsePreset, loadPreset and resolveModelPath. Reading walks the document once with a small
// Reader (preset_reader.h) that knows the JSON path it is at, marks each key it consumes and
// reports every problem instead of stopping at the first. Keys it never consumed are reported as
// unknown, with the closest known key as a suggestion. Which keys there are, where each goes, its
// kind, range and rules come from the field table (field_table.h); the model's source, the lights'
// array, `check` and `sweep` are read by hand here.
//
// It does not write presets (preset.cpp), load the model a preset names (model_loader.h) or
// decide what a number may be (limits.h).
#include "core/scene/preset.h"
#include "core/scene/preset_reader.h"

#include "core/io/file_io.h"
#include "core/io/json_text.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"
#include "core/io/site_files.h"
#include "core/scene/limits.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"
#include "core/scene/file_header.h"
#include "core/scene/sweep.h"
#include "core/scene/view_mode.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <span>
#include <tuple>

namespace lab {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using preset_detail::Keys;
using preset_detail::Reader;

//----------------------------------------------------------------------------------------
// Text to JSON
//----------------------------------------------------------------------------------------

std::optional<Json> preset_detail::parseJsonObject(std::string_view text, const std::string& file, int maxDepth,
                                                  std::string_view kind, Diagnostics& diagnostics) {
    if (std::optional<Diagnostic> problem = jsonTextProblem(text, file, maxDepth)) {
        diagnostics.push_back(std::move(*problem));
        return std::nullopt;
    }
    Json json;
    try {
        json = Json::parse(text);
    } catch (const Json::parse_error& e) {
        diagnostics.push_back({file, lineColumn(text, e.byte == 0 ? 0 : e.byte - 1),
                               "invalid JSON: " + shortened(parseErrorDetail(e.what()), 200)});
        return std::nullopt;
    } catch (const Json::out_of_range& e) {
        // A number too large for a double, e.g. 1e999: "... number overflow parsing '1e999'".
        std::string what = e.what();
        std::size_t open = what.find('\''), close = what.rfind('\'');
        std::string number = open < close ? what.substr(open + 1, close - open - 1) : "";
        std::size_t at = number.empty() ? std::string_view::npos : text.find(number);
        diagnostics.push_back({file, at == std::string_view::npos ? "" : lineColumn(text, at),
                               "number out of range: " + shortened(number.empty() ? what : number, 200)});
        return std::nullopt;
    } catch (const Json::exception& e) {
        diagnostics.push_back({file, "", "invalid JSON: " + shortened(e.what(), 200)});
        return std::nullopt;
    }
    if (!json.is_object()) {
        diagnostics.push_back({file, "", std::string(kind) + " is a JSON object, got " + Reader::describe(json)});
        return std::nullopt;
    }
    return json;
}

namespace {

// Deep nesting would recurse deeply in the JSON parser; no valid preset nests past 4.
constexpr int kMaxJsonDepth = 32;

//----------------------------------------------------------------------------------------
// The preset's sections
//----------------------------------------------------------------------------------------

// The keys of `check` and its views (scene fields' keys come from the field table).
constexpr std::string_view kCheckKeys[] = {"pixel_tolerance", "max_failing", "max_mean", "plot_tolerance", "views"};
constexpr std::string_view kCheckViewKeys[] = {"view", "light"};

void readCheck(Reader& r, CheckSettings& check);
void readSweep(Reader& top, std::vector<std::string>& sweep);

// model.gltf: a .gltf or .glb file in or below the preset's folder.
void readGltfPath(Reader& r, Model& model, const std::optional<fs::path>& folder) {
    std::string path;
    r.readString("gltf", path);
    if (r.has("subdivisions")) {
        r.find("subdivisions");
        r.error("subdivisions", "applies to built-in models only");
    }
    if (path.empty()) {
        if (r.find("gltf")->is_string()) {
            r.error("gltf", "expected a path, got an empty string");
        }
        return;
    }
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    std::string error;
    if (hasNul(path)) {
        r.error("gltf", "the path " + inQuotes(path) + " holds a NUL byte");
    } else if (!lower.ends_with(".gltf") && !lower.ends_with(".glb")) {
        r.error("gltf", "expected a .gltf or .glb file, got " + inQuotes(path));
    } else if (!folder) {
        r.error("gltf", "a glTF model needs the preset to be a file (paths are relative to it)");
    } else if (!resolveModelPath(path, *folder, error)) {
        r.error("gltf", error);
    } else {
        model.gltf = path;
    }
}

// The model's source, read together: a built-in with its subdivisions, or a glTF file (which
// has none).
void readModelSource(Reader& r, Model& model, const std::optional<fs::path>& folder, bool patch) {
    bool hasGltf = r.has("gltf");
    if (patch && !hasGltf && !r.has("builtin")) { // a patch's model keeps the base's source
        if (!model.gltf.empty() && r.has("subdivisions")) {
            r.find("subdivisions");
            r.error("subdivisions", "applies to built-in models only");
        } else if (model.gltf.empty()) {
            bool round = model.builtin == Builtin::Sphere || model.builtin == Builtin::Torus;
            r.readInt2("subdivisions", model.subdivisions, round ? limits::kSubdivisionsRound : limits::kSubdivisions);
        }
        return;
    }
    model.gltf.clear();
    if (r.has("builtin") && hasGltf) {
        r.error("gltf", "a model has either \"builtin\" or \"gltf\", not both");
    }
    int builtin = static_cast<int>(model.builtin);
    r.readChoice("builtin", builtin, kBuiltinChoices);
    model.builtin = static_cast<Builtin>(builtin);
    model.subdivisions = defaultSubdivisions(model.builtin);
    if (hasGltf) {
        readGltfPath(r, model, folder);
    } else {
        bool round = model.builtin == Builtin::Sphere || model.builtin == Builtin::Torus;
        r.readInt2("subdivisions", model.subdivisions, round ? limits::kSubdivisionsRound : limits::kSubdivisions);
        if (model.builtin == Builtin::Sphere && model.subdivisions.y < 2) {
            r.error("subdivisions", "a sphere needs at least 2 stacks");
        }
    }
}

// What a preset reads besides its rows: the model's source, and the lights.
struct Sections {
    Preset& preset;
    const std::optional<fs::path>& folder;
    bool patch = false; // `compare`: the keys given change a copy of the preset, the rest stays
};

void readRows(Reader& r, std::string_view object, Sections& s, LightDesc* light);
void readCompare(Reader& top, Sections& s);

// One row's value, by its kind, then its rule.
void readRow(Reader& r, const FieldRow& row, Preset& p, LightDesc* light) {
    std::string_view key = fieldKey(row);
    switch (row.kind) {
    case FieldKind::Number: r.readNumber(key, fieldValue<float>(row, p, light), *row.range); break;
    case FieldKind::Vec3:
    case FieldKind::Color: r.readVec3(key, fieldValue<glm::vec3>(row, p, light), *row.range); break;
    case FieldKind::Direction: r.readDirection(key, fieldValue<glm::vec3>(row, p, light)); break;
    case FieldKind::Int2: r.readInt2(key, fieldValue<glm::ivec2>(row, p, light), *row.intRange); break;
    case FieldKind::Switch: r.readBool(key, fieldValue<bool>(row, p, light)); break;
    case FieldKind::Text: r.readString(key, fieldValue<std::string>(row, p, light)); break;
    case FieldKind::Choice: {
        int value = choiceValue(row, p, light);
        r.readChoice(key, value, row.choices);
        setChoice(row, p, light, value);
        break;
    }
    }
    if (row.rule) {
        std::vector<FieldProblem> problems;
        row.rule(p, light, problems);
        for (const FieldProblem& problem : problems) {
            r.error(problem.key, problem.message);
        }
    }
}

void readLights(Reader& top, Sections& s) {
    const Json* json = top.find("lights");
    if (!json) {
        return;
    }
    if (!json->is_array()) {
        top.error("lights", "expected an array of lights, got " + Reader::describe(*json));
        return;
    }
    if (json->size() > kMaxLights) {
        top.error("lights", "at most " + std::to_string(kMaxLights) + " lights, got " + std::to_string(json->size()));
        return;
    }
    std::vector<LightDesc>& lights = s.preset.lights;
    if (s.patch) { // element by element; a light the base lacks is added
        lights.resize(std::max(lights.size(), json->size()));
    } else {
        lights.assign(json->size(), LightDesc{});
    }
    for (std::size_t i = 0; i < json->size(); ++i) {
        const Json& light = (*json)[i];
        if (!light.is_object()) {
            top.errorAt(top.elementPath("lights", i), "expected an object, got " + Reader::describe(light));
            continue;
        }
        Reader r = top.child(light, top.elementPath("lights", i));
        readRows(r, "lights[]", s, &lights[i]);
    }
}

// The rows of `object` ("material", "lights[]", "" for the top level) in the table's order, the
// objects below it as they come, then its unknown keys.
void readRows(Reader& r, std::string_view object, Sections& s, LightDesc* light) {
    std::vector<std::string_view> seen;
    for (const FieldRow& row : fieldRows()) {
        const FieldPlace place = fieldPlace(row, object);
        if (place.where == FieldPlace::Member) {
            if (row.custom && place.key == "builtin") {
                readModelSource(r, s.preset.model, s.folder, s.patch);
            } else if (!row.custom) {
                readRow(r, row, s.preset, light);
            }
            seen.push_back(place.key);
        } else if (place.where == FieldPlace::Below && std::find(seen.begin(), seen.end(), place.key) == seen.end()) {
            // An object below this one, read once, where its first row comes.
            seen.push_back(place.key);
            if (place.array) {
                readLights(r, s);
            } else {
                r.readObject(place.key, [&](Reader& c) { readRows(c, place.child, s, light); });
            }
        }
    }
    if (object.empty() && !s.patch) {
        r.readObject("check", kCheckKeys, [&](Reader& c) { readCheck(c, s.preset.check); });
        readSweep(r, s.preset.sweep);
        preset_detail::readDisplay(r, s.preset.display);
        r.readString("notes", s.preset.notes);
        readCompare(r, s);
        seen.insert(seen.begin(), {"format", "version"});
        seen.insert(seen.end(), {"check", "sweep", "display", "notes", "compare"});
    }
    r.finish(seen);
}

// Set B: `patch` (the object `compare` holds, under r) read onto a copy of the preset without
// what only the lecture reads, with the patch's rules (Sections::patch).
Preset patchedCopy(Reader& r, const Preset& preset, const std::optional<fs::path>& folder) {
    Preset b = preset;
    b.display = {};
    b.notes.clear();
    b.compare.clear();
    Sections sb{b, folder, true};
    readRows(r, "", sb, nullptr);
    return b;
}

// `compare`: set B as a patch of the preset's own fields, read onto a copy of it (so every value,
// rule and glTF path is checked as the file's are); kept as its minified text.
void readCompare(Reader& top, Sections& s) {
    const Json* json = top.find("compare");
    if (!json) {
        return;
    }
    if (!json->is_object()) {
        top.error("compare", "expected an object of the fields set B changes, such as {\"shading\": \"gouraud\"}, got " +
                                 Reader::describe(*json));
        return;
    }
    const std::size_t before = top.problems();
    Reader r = top.child(*json, top.pathOf("compare"));
    patchedCopy(r, s.preset, s.folder); // read for its problems; comparedPreset() makes B when it is wanted
    if (top.problems() == before) {
        s.preset.compare = json->dump();
    }
}

// `check.views`: view names ("d"), or {"view": "spot", "light": 2}; each name a view of
// view_mode.h (whether it applies is asked where it is checked).
void readCheckViews(Reader& r, std::vector<CheckView>& views) {
    const Json* json = r.find("views");
    if (!json) {
        return;
    }
    if (!json->is_array() || json->size() > kViewModes.size() * limits::kMaxLights) {
        r.error("views", "expected an array of view names such as \"d\" or objects {\"view\": \"spot\", \"light\": 2}, got " +
                             Reader::describe(*json));
        return;
    }
    for (std::size_t i = 0; i < json->size(); ++i) {
        const Json& item = (*json)[i];
        std::string where = r.elementPath("views", i);
        CheckView v;
        if (item.is_object()) {
            Reader o = r.child(item, where);
            o.readString("view", v.view);
            o.readInt("light", v.light, limits::kLightNumber);
            o.finish(kCheckViewKeys);
            where += ".view";
        } else if (item.is_string()) {
            v.view = item.get<std::string>();
        } else {
            r.errorAt(where, "expected a view name or an object {\"view\": ..., \"light\": N}, got " + Reader::describe(item));
            continue;
        }
        if (!viewFromName(v.view)) {
            r.errorAt(where, "no view " + inQuotes(v.view, 60) + suggestion(v.view, viewNameList()) + "; the views are " +
                                 viewNames());
        } else if (std::find(views.begin(), views.end(), v) != views.end()) { // it would be checked twice, one golden
            r.errorAt(where, inQuotes(v.view, 60) + (v.light == 1 ? "" : " of light " + std::to_string(v.light)) +
                                 " is listed twice");
        } else {
            views.push_back(std::move(v));
        }
    }
}

// `check`: lab check's tolerances for this preset, each optional.
void readCheck(Reader& r, CheckSettings& check) {
    if (r.has("pixel_tolerance")) {
        int v = 0;
        std::size_t before = r.problems();
        r.readInt("pixel_tolerance", v, limits::kPixelTolerance);
        if (r.problems() == before) {
            check.pixelTolerance = v;
        }
    }
    for (auto [key, dst, range] : {std::tuple{"max_failing", &check.maxFailing, &limits::kMaxFailing},
                                   std::tuple{"max_mean", &check.maxMean, &limits::kMaxMean},
                                   std::tuple{"plot_tolerance", &check.plotTolerance, &limits::kPlotTolerance}}) {
        if (r.has(key)) {
            float v = 0.0f;
            std::size_t before = r.problems();
            r.readNumber(key, v, *range);
            if (r.problems() == before) {
                *dst = v;
            }
        }
    }
    readCheckViews(r, check.views);
}

// `sweep`: one or two `lab render --sweep` arguments, each checked for its syntax here. Whether the
// keys and values suit the rest of the preset is asked where the sweep is used (lab check, the
// sweep window: core/scene/sweep.h sweepCells), not here: a preset edited in the lab (a light removed
// that the sweep names) must still save and load as it is, load(save(x)) == x.
void readSweep(Reader& top, std::vector<std::string>& sweep) {
    const Json* json = top.find("sweep");
    if (!json) {
        return;
    }
    if (!json->is_array() || json->empty() || json->size() > kMaxSweepKeys) {
        top.error("sweep", "expected an array of 1 or 2 strings such as \"material.shininess=10,20,50\", got " +
                               Reader::describe(*json));
        return;
    }
    for (std::size_t i = 0; i < json->size(); ++i) {
        const Json& axis = (*json)[i];
        std::string error;
        if (!axis.is_string()) {
            top.errorAt(top.elementPath("sweep", i), "expected a string KEY=V1,V2,..., got " + Reader::describe(axis));
        } else if (!parseSweepAxis(axis.get<std::string>(), error)) {
            top.errorAt(top.elementPath("sweep", i), error);
        } else {
            sweep.push_back(axis.get<std::string>());
        }
    }
}

} // namespace

//----------------------------------------------------------------------------------------
// Entry points
//----------------------------------------------------------------------------------------

std::optional<fs::path> resolveModelPath(const std::string& gltf, const fs::path& folder, std::string& error) {
    fs::path relative(gltf);
    if (relative.is_absolute()) {
        error = inQuotes(gltf) + " is an absolute path; model paths are relative to the preset's folder";
        return std::nullopt;
    }
    fs::path base = canonicalFolder(folder);
    std::error_code ec;
    fs::path full = fs::weakly_canonical(base / relative, ec);
    if (ec) {
        error = inQuotes(gltf) + ": " + ec.message();
        return std::nullopt;
    }
    if (!isInside(base, full)) {
        error = inQuotes(gltf) + " leaves the preset's folder " + base.string();
        return std::nullopt;
    }
    fs::file_status status = fs::status(full, ec);
    if (!fs::exists(status) && onSite(full)) {
        return full; // the page fetches it when the preset opens (core/io/site_files.h)
    }
    if (!fs::exists(status)) {
        error = "model file " + inQuotes(gltf) + " not found (looked for " + inQuotes(full.string(), 400) + ")";
        return std::nullopt;
    }
    if (!fs::is_regular_file(status)) {
        error = inQuotes(gltf) + " is not a regular file";
        return std::nullopt;
    }
    return full;
}

namespace {

// The preset in `text` (one JSON object found at `where`): a file's must say its format and
// version; an inline one (`inlined`) may leave them to the file around it, and is checked when it
// gives them.
std::optional<Preset> readPreset(std::string_view text, const std::string& displayName, const std::string& where,
                                 bool inlined, const std::optional<fs::path>& folder, Diagnostics& diagnostics,
                                 OmittedKeys* omitted) {
    std::optional<Json> json = preset_detail::parseJsonObject(text, displayName, kMaxJsonDepth, "a preset", diagnostics);
    if (!json) {
        return std::nullopt;
    }
    Diagnostics out;
    Reader r(*json, where, displayName, out);
    Preset preset;
    std::optional<HeaderProblem> header;
    if (!(inlined && !r.has("format") && !r.has("version"))) {
        header = fileHeaderProblem(*json, kPresetFile);
    }
    if (header) {
        r.error(header->key, header->message);
    } else {
        r.find("format"); // checked above (or left to the file around an inline preset)
        r.find("version");
        Sections sections{preset, folder};
        readRows(r, "", sections, nullptr);
    }
    if (!out.empty()) {
        diagnostics.insert(diagnostics.end(), out.begin(), out.end());
        return std::nullopt;
    }
    if (omitted) {
        *omitted = {!r.has("camera"), !r.has("lights")};
    }
    return preset;
}

} // namespace

std::optional<Preset> parsePreset(std::string_view text, const std::string& displayName,
                                  const std::optional<fs::path>& folder, Diagnostics& diagnostics,
                                  OmittedKeys* omitted) {
    return readPreset(text, displayName, "", false, folder, diagnostics, omitted);
}

std::optional<Preset> parseInlinePreset(std::string_view objectText, const std::string& displayName,
                                        const std::string& where, const std::optional<fs::path>& folder,
                                        Diagnostics& diagnostics, OmittedKeys* omitted) {
    return readPreset(objectText, displayName, where, true, folder, diagnostics, omitted);
}

namespace preset_detail {

// `display`: how the lab first shows the preset.
void readDisplayKeys(Reader& r, OpeningDisplay& display) {
    r.readString("view", display.view);
    if (!display.view.empty() && !viewFromName(display.view)) {
        r.error("view", "no view " + inQuotes(display.view, 60) + suggestion(display.view, viewNameList()) +
                            "; the views are " + viewNames());
    }
    r.readInt("light", display.light, limits::kLightNumber);
    if (r.has("compare")) {
        bool compare = false;
        r.readBool("compare", compare);
        display.compare = compare;
    }
    r.readBool("wipe", display.wipe);
    r.readBool("wireframe", display.wireframe);
    r.readString("plots", display.plots);
    if (!display.plots.empty() && std::find(std::begin(kPlotTabNames), std::end(kPlotTabNames), display.plots) == std::end(kPlotTabNames)) {
        std::string tabs; // "plane, lobe3d, energy and slice", from the table
        for (std::size_t i = 0; i < std::size(kPlotTabNames); ++i) {
            tabs += (i == 0 ? "" : i + 1 == std::size(kPlotTabNames) ? " and " : ", ") + std::string(kPlotTabNames[i]);
        }
        r.error("plots", "no plots tab " + inQuotes(display.plots, 60) + suggestion(display.plots, kPlotTabNames) + "; the tabs are " + tabs);
    }
}

void readDisplay(Reader& parent, OpeningDisplay& display) {
    static constexpr std::string_view kDisplayKeys[] = {"view", "light", "compare", "wipe", "wireframe", "plots"};
    parent.readObject("display", kDisplayKeys, [&](Reader& r) { readDisplayKeys(r, display); });
}

} // namespace preset_detail

std::optional<Preset> comparedPreset(const Preset& preset, const std::optional<fs::path>& folder,
                                     Diagnostics& diagnostics) {
    std::optional<Json> json = preset_detail::parseJsonObject(preset.compare.empty() ? "{}" : preset.compare, preset.name,
                                                              kMaxJsonDepth, "a preset", diagnostics);
    if (!json) {
        return std::nullopt;
    }
    Diagnostics out;
    Reader r(*json, "compare", preset.name, out);
    Preset b = patchedCopy(r, preset, folder);
    if (!out.empty()) {
        diagnostics.insert(diagnostics.end(), out.begin(), out.end());
        return std::nullopt;
    }
    return b;
}

std::optional<LoadedPreset> loadPreset(const fs::path& file, Diagnostics& diagnostics) {
    std::string error;
    std::optional<std::string> text = readFile(file, kMaxPresetBytes, error);
    if (!text) {
        diagnostics.push_back({file.string(), "", error});
        return std::nullopt;
    }
    fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    OmittedKeys omitted;
    std::optional<Preset> preset = parsePreset(*text, file.string(), folder, diagnostics, &omitted);
    if (!preset) {
        return std::nullopt;
    }
    return LoadedPreset{std::move(*preset), file, omitted};
}

} // namespace lab
