// preset_read.cpp — reading preset JSON: every problem reported with its JSON path.
//
// Owns parsePreset, loadPreset and resolveModelPath. Reading walks the document once with a small
// Reader (preset_reader.h) that knows the JSON path it is at, marks each key it consumes and
// reports every problem instead of stopping at the first. Keys it never consumed are reported as
// unknown, with the closest known key as a suggestion. The ranges come from core/scene/limits.h; the names from
// preset_names.h.
//
// It does not write presets (preset.cpp), load the model a preset names (model_loader.h) or
// decide what a number may be (limits.h).
#include "core/scene/preset.h"
#include "core/scene/preset_reader.h"

#include "core/io/file_io.h"
#include "core/io/json_text.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"
#include "core/scene/limits.h"
#include "core/scene/preset_names.h"
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

namespace {

//----------------------------------------------------------------------------------------
// Text to JSON
//----------------------------------------------------------------------------------------

// Deep nesting would recurse deeply in the JSON parser; no valid preset nests past 4.
constexpr int kMaxJsonDepth = 32;

// The JSON object `text` holds, or nullopt after one diagnostic: nested too deep, not JSON, a
// number beyond a double, or not an object.
std::optional<Json> parseObject(std::string_view text, const std::string& file, Diagnostics& diagnostics) {
    if (!jsonNestingWithin(text, kMaxJsonDepth)) {
        diagnostics.push_back({file, "", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels"});
        return std::nullopt;
    }
    Json json;
    try {
        json = Json::parse(text);
    } catch (const Json::parse_error& e) {
        // e.what() repeats the position in its own words; keep the part after the last ": ".
        std::string what = e.what();
        std::size_t colon = what.rfind(": ");
        std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
        diagnostics.push_back({file, lineColumn(text, e.byte == 0 ? 0 : e.byte - 1), "invalid JSON: " + shortened(detail, 200)});
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
        diagnostics.push_back({file, "", "a preset is a JSON object, got " + Reader::describe(json)});
        return std::nullopt;
    }
    return json;
}

//----------------------------------------------------------------------------------------
// The preset's sections
//----------------------------------------------------------------------------------------

// Format and version first: a file that is not a preset gets one clear message, not fifty.
bool readFormatAndVersion(Reader& r) {
    const std::string expectedFormat = "\"" + std::string(kPresetFormat) + "\"";
    const Json* format = r.find("format");
    if (!format) {
        r.error("format", "missing; expected " + expectedFormat);
        return false;
    }
    if (!format->is_string() || format->get<std::string>() != kPresetFormat) {
        r.error("format", "expected " + expectedFormat + ", got " + format->dump());
        return false;
    }
    const Json* version = r.find("version");
    if (!version) {
        r.error("version", "missing; expected " + std::to_string(kPresetVersion));
    } else if (!version->is_number_integer() && !version->is_number_unsigned()) {
        r.error("version", "expected an integer, got " + version->dump());
    } else if (version->get<double>() > kPresetVersion) {
        r.error("version", "version " + version->dump() + " is newer than this program reads (" +
                               std::to_string(kPresetVersion) + "); update Lighting Lab");
    } else if (version->get<double>() < 1) {
        r.error("version", "expected " + std::to_string(kPresetVersion) + ", got " + version->dump());
    } else {
        return true;
    }
    return false;
}

// The keys of each object, for finish(): anything else is reported as unknown.
constexpr std::string_view kPresetKeys[] = {
    "format", "version",       "name",     "description",   "model",  "camera", "shading",    "normal_matrix",
    "brdf",   "cook_torrance", "material", "ambient_light", "lights", "terms",  "background", "plot",
    "check",  "sweep"};
constexpr std::string_view kModelKeys[] = {"builtin", "gltf", "subdivisions", "scale", "rotate_deg", "translate"};
constexpr std::string_view kCameraKeys[] = {"eye", "target", "up", "fovy_deg", "near", "far"};
constexpr std::string_view kCookTorranceKeys[] = {"distribution", "roughness", "fresnel", "ior", "geometry"};
constexpr std::string_view kMaterialKeys[] = {"emissive", "ambient", "diffuse", "specular", "shininess"};
constexpr std::string_view kLightKeys[] = {"type",     "position",    "direction",  "ambient",  "diffuse",
                                           "specular", "attenuation", "cutoff_deg", "exponent", "enabled",
                                           "orbit"};
constexpr std::string_view kOrbitKeys[] = {"on", "axis", "degrees_per_second"};
constexpr std::string_view kTermsKeys[] = {"emissive", "ambient", "diffuse", "specular"};
constexpr std::string_view kPlotKeys[] = {"incident_deg"};
constexpr std::string_view kCheckKeys[] = {"pixel_tolerance", "max_failing", "max_mean", "plot_tolerance", "views"};
constexpr std::string_view kCheckViewKeys[] = {"view", "light"};

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

void readModel(Reader& r, Model& model, const std::optional<fs::path>& folder) {
    bool hasGltf = r.has("gltf");
    if (r.has("builtin") && hasGltf) {
        r.error("gltf", "a model has either \"builtin\" or \"gltf\", not both");
    }
    r.readEnum("builtin", model.builtin, preset_names::kBuiltin);
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
    r.readVec3("scale", model.scale, limits::kCoordinate);
    if (std::abs(model.scale.x) < limits::kMinScale || std::abs(model.scale.y) < limits::kMinScale ||
        std::abs(model.scale.z) < limits::kMinScale) {
        r.error("scale", "scale factors must be at least 0.0001 in magnitude (at 0 the normal matrix would not exist)");
    }
    r.readVec3("rotate_deg", model.rotateDeg, limits::kRotationDeg);
    r.readVec3("translate", model.translate, limits::kCoordinate);
}

void readCamera(Reader& r, Camera& camera) {
    r.readVec3("eye", camera.eye, limits::kCoordinate);
    r.readVec3("target", camera.target, limits::kCoordinate);
    r.readVec3("up", camera.up, limits::kCoordinate);
    r.readNumber("fovy_deg", camera.fovyDeg, limits::kFovyDeg);
    r.readNumber("near", camera.near, limits::kNear);
    r.readNumber("far", camera.far, limits::kFar);
    if (camera.far <= camera.near) {
        r.error("far", "must be greater than near");
    }
    glm::vec3 forward = camera.target - camera.eye;
    if (glm::length(camera.up) < limits::kMinDirectionLength) {
        r.error("up", "must be at least 0.001 long (it is normalized)");
    } else if (glm::length(forward) < limits::kMinDirectionLength) {
        r.error("target", "must be at least 0.001 from eye");
    } else {
        glm::vec3 side = glm::cross(forward, camera.up);
        if (glm::dot(side, side) <= 1e-12f * glm::dot(forward, forward) * glm::dot(camera.up, camera.up)) {
            r.error("up", "must not be parallel to the viewing direction (or zero)");
        }
    }
}

void readCookTorrance(Reader& r, CookTorrance& ct) {
    r.readEnum("distribution", ct.distribution, preset_names::kDistribution);
    r.readNumber("roughness", ct.roughness, limits::kRoughness);
    r.readEnum("fresnel", ct.fresnel, preset_names::kFresnel);
    r.readNumber("ior", ct.ior, limits::kIor);
    r.readBool("geometry", ct.geometry);
}

void readMaterial(Reader& r, MaterialDesc& material) {
    for (auto [key, color] : {std::pair{"emissive", &material.emissive}, std::pair{"ambient", &material.ambient},
                              std::pair{"diffuse", &material.diffuse}, std::pair{"specular", &material.specular}}) {
        r.readVec3(key, *color, limits::kMaterialColor);
    }
    r.readNumber("shininess", material.shininess, limits::kShininess);
}

void readLight(Reader& r, LightDesc& light) {
    r.readEnum("type", light.type, preset_names::kLightType);
    r.readVec3("position", light.position, limits::kCoordinate);
    r.readDirection("direction", light.direction);
    for (auto [key, color] : {std::pair{"ambient", &light.ambient}, std::pair{"diffuse", &light.diffuse},
                              std::pair{"specular", &light.specular}}) {
        r.readVec3(key, *color, limits::kLightColor);
    }
    r.readVec3("attenuation", light.attenuation, limits::kAttenuation);
    if (light.attenuation == glm::vec3(0.0f)) {
        r.error("attenuation", "c0, c1 and c2 must not all be 0");
    }
    r.readNumber("cutoff_deg", light.cutoffDeg, limits::kCutoffDeg);
    r.readNumber("exponent", light.exponent, limits::kSpotExponent);
    r.readBool("enabled", light.enabled);
    r.readObject("orbit", kOrbitKeys, [&](Reader& o) {
        o.readBool("on", light.orbit.on);
        o.readDirection("axis", light.orbit.axis);
        o.readNumber("degrees_per_second", light.orbit.degreesPerSecond, limits::kOrbitSpeed);
    });
}

void readLights(Reader& top, std::vector<LightDesc>& lights) {
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
    lights.assign(json->size(), LightDesc{});
    for (std::size_t i = 0; i < json->size(); ++i) {
        const Json& light = (*json)[i];
        if (!light.is_object()) {
            top.errorAt(top.elementPath("lights", i), "expected an object, got " + Reader::describe(light));
            continue;
        }
        Reader r = top.child(light, top.elementPath("lights", i));
        readLight(r, lights[i]);
        r.finish(kLightKeys);
    }
}

void readTerms(Reader& r, TermSwitches& terms) {
    for (auto [key, on] : {std::pair{"emissive", &terms.emissive}, std::pair{"ambient", &terms.ambient},
                           std::pair{"diffuse", &terms.diffuse}, std::pair{"specular", &terms.specular}}) {
        r.readBool(key, *on);
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

// Every key after format and version, in the documented order.
void readPresetKeys(Reader& r, Preset& p, const std::optional<fs::path>& folder) {
    r.readString("name", p.name);
    r.readString("description", p.description);
    r.readObject("model", kModelKeys, [&](Reader& m) { readModel(m, p.model, folder); });
    r.readObject("camera", kCameraKeys, [&](Reader& c) { readCamera(c, p.camera); });
    r.readEnum("shading", p.shading, preset_names::kShading);
    r.readEnum("normal_matrix", p.normalMatrix, preset_names::kNormalMatrix);
    r.readEnum("brdf", p.brdf, preset_names::kBrdf);
    r.readObject("cook_torrance", kCookTorranceKeys, [&](Reader& c) { readCookTorrance(c, p.cookTorrance); });
    r.readObject("material", kMaterialKeys, [&](Reader& m) { readMaterial(m, p.material); });
    r.readVec3("ambient_light", p.ambientLight, limits::kAmbientLight);
    readLights(r, p.lights);
    r.readObject("terms", kTermsKeys, [&](Reader& t) { readTerms(t, p.terms); });
    r.readVec3("background", p.background, limits::kBackground);
    r.readObject("plot", kPlotKeys,
                 [&](Reader& pl) { pl.readNumber("incident_deg", p.plotIncidentDeg, limits::kPlotIncidentDeg); });
    r.readObject("check", kCheckKeys, [&](Reader& c) { readCheck(c, p.check); });
    readSweep(r, p.sweep);
    r.finish(kPresetKeys);
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
    std::optional<Json> json = parseObject(text, displayName, diagnostics);
    if (!json) {
        return std::nullopt;
    }
    Diagnostics out;
    Reader r(*json, where, displayName, out);
    Preset preset;
    if ((inlined && !r.has("format") && !r.has("version")) || readFormatAndVersion(r)) {
        r.find("format");
        r.find("version");
        readPresetKeys(r, preset, folder);
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
