// preset.cpp — preset JSON: validation with paths, and saving every key.
//
// Reading walks the document once with a small Reader that knows the JSON path it is at, marks
// each key it consumes and reports every problem instead of stopping at the first. Keys it never
// consumed are reported as unknown, with the closest known key as a suggestion.
#include "core/preset.h"

#include "core/file_io.h"
#include "core/number_format.h"
#include "core/paths.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace lab {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

//----------------------------------------------------------------------------------------
// Names
//----------------------------------------------------------------------------------------

namespace {

template <typename E, std::size_t N>
using NameTable = std::array<std::pair<E, std::string_view>, N>;

constexpr NameTable<Builtin, 4> kBuiltinNames{
    {{Builtin::Sphere, "sphere"}, {Builtin::Cube, "cube"}, {Builtin::Plane, "plane"}, {Builtin::Torus, "torus"}}};
constexpr NameTable<Shading, 3> kShadingNames{
    {{Shading::Flat, "flat"}, {Shading::Gouraud, "gouraud"}, {Shading::Phong, "phong"}}};
constexpr NameTable<NormalMatrixMode, 2> kNormalMatrixNames{
    {{NormalMatrixMode::InverseTranspose, "inverse-transpose"}, {NormalMatrixMode::ModelView, "model-view"}}};
constexpr NameTable<BrdfModel, 3> kBrdfNames{
    {{BrdfModel::Phong, "phong"}, {BrdfModel::BlinnPhong, "blinn-phong"}, {BrdfModel::CookTorrance, "cook-torrance"}}};
constexpr NameTable<Distribution, 3> kDistributionNames{
    {{Distribution::Beckmann, "beckmann"}, {Distribution::Gaussian, "gaussian"}, {Distribution::Ggx, "ggx"}}};
constexpr NameTable<FresnelMode, 2> kFresnelNames{{{FresnelMode::Schlick, "schlick"}, {FresnelMode::Full, "full"}}};
constexpr NameTable<LightType, 3> kLightTypeNames{
    {{LightType::Point, "point"}, {LightType::Directional, "directional"}, {LightType::Spot, "spot"}}};

template <typename E, std::size_t N>
std::string_view nameOf(const NameTable<E, N>& table, E value) {
    for (const auto& [v, name] : table) {
        if (v == value) {
            return name;
        }
    }
    return "?";
}

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

// ` (did you mean "x"?)` for the closest candidate within a couple of edits, else "".
template <typename Names>
std::string suggestion(std::string_view word, const Names& candidates) {
    std::string_view best;
    std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (std::string_view c : candidates) {
        std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best.empty() ? std::string{} : " (did you mean \"" + std::string(best) + "\"?)";
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

std::string_view toString(Builtin v) { return nameOf(kBuiltinNames, v); }
std::string_view toString(Shading v) { return nameOf(kShadingNames, v); }
std::string_view toString(NormalMatrixMode v) { return nameOf(kNormalMatrixNames, v); }
std::string_view toString(BrdfModel v) { return nameOf(kBrdfNames, v); }
std::string_view toString(Distribution v) { return nameOf(kDistributionNames, v); }
std::string_view toString(FresnelMode v) { return nameOf(kFresnelNames, v); }
std::string_view toString(LightType v) { return nameOf(kLightTypeNames, v); }

//----------------------------------------------------------------------------------------
// Reading
//----------------------------------------------------------------------------------------

namespace {

// One JSON object being read: remembers its path and which keys were consumed.
class Reader {
public:
    Reader(const Json& object, std::string path, const std::string& file, Diagnostics& out)
        : object_(object), path_(std::move(path)), file_(file), out_(out) {}

    // Reports keys nobody asked for; call after every read of this object.
    void finish(std::initializer_list<std::string_view> known) {
        for (const auto& [key, value] : object_.items()) {
            if (!consumed_.contains(key)) {
                error(key, "unknown key" + suggestion(key, known));
            }
        }
    }

    std::string pathOf(std::string_view key) const {
        return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
    }

    void error(std::string_view key, std::string message) {
        out_.push_back({file_, pathOf(key), std::move(message)});
    }

    // The value under `key`, or nullptr when absent. Marks the key as known.
    const Json* find(std::string_view key) {
        consumed_.insert(std::string(key));
        auto it = object_.find(key);
        return it == object_.end() ? nullptr : &*it;
    }

    bool has(std::string_view key) const { return object_.contains(key); }

    // A finite number within `range` (any finite number when null).
    void readNumber(std::string_view key, float& dst, const limits::Range* range = nullptr) {
        if (const Json* v = find(key)) {
            readNumberAt(*v, pathOf(key), dst, range);
        }
    }
    void readNumber(std::string_view key, float& dst, const limits::Range& range) { readNumber(key, dst, &range); }

    void readVec3(std::string_view key, glm::vec3& dst, const limits::Range* range = nullptr) {
        const Json* v = find(key);
        if (!v) {
            return;
        }
        if (!v->is_array() || v->size() != 3) {
            error(key, "expected an array of 3 numbers, got " + describe(*v));
            return;
        }
        for (int i = 0; i < 3; ++i) {
            readNumberAt((*v)[static_cast<std::size_t>(i)], pathOf(key) + "[" + std::to_string(i) + "]", dst[i],
                         range);
        }
    }

    void readVec3(std::string_view key, glm::vec3& dst, const limits::Range& range) { readVec3(key, dst, &range); }

    void readInt2(std::string_view key, glm::ivec2& dst, const limits::IntRange& range) {
        const Json* v = find(key);
        if (!v) {
            return;
        }
        if (!v->is_array() || v->size() != 2) {
            error(key, "expected an array of 2 integers, got " + describe(*v));
            return;
        }
        for (int i = 0; i < 2; ++i) {
            const Json& e = (*v)[static_cast<std::size_t>(i)];
            std::string where = pathOf(key) + "[" + std::to_string(i) + "]";
            if (!e.is_number_integer() && !e.is_number_unsigned()) {
                out_.push_back({file_, where, "expected an integer, got " + describe(e)});
            } else if (e.get<double>() < range.min || e.get<double>() > range.max) {
                out_.push_back({file_, where,
                                "must be from " + std::to_string(range.min) + " to " + std::to_string(range.max) +
                                    ", got " + e.dump()});
            } else {
                dst[i] = e.get<int>();
            }
        }
    }

    void readBool(std::string_view key, bool& dst) {
        if (const Json* v = find(key)) {
            if (v->is_boolean()) {
                dst = v->get<bool>();
            } else {
                error(key, "expected true or false, got " + describe(*v));
            }
        }
    }

    void readString(std::string_view key, std::string& dst) {
        if (const Json* v = find(key)) {
            if (v->is_string()) {
                dst = v->get<std::string>();
            } else {
                error(key, "expected a string, got " + describe(*v));
            }
        }
    }

    template <typename E, std::size_t N>
    void readEnum(std::string_view key, E& dst, const NameTable<E, N>& table) {
        const Json* v = find(key);
        if (!v) {
            return;
        }
        std::string choices;
        std::vector<std::string_view> names;
        for (const auto& [value, name] : table) {
            choices += (choices.empty() ? "\"" : ", \"") + std::string(name) + "\"";
            names.push_back(name);
            if (v->is_string() && v->get<std::string>() == name) {
                dst = value;
                return;
            }
        }
        std::string got = v->is_string() ? "\"" + v->get<std::string>() + "\"" : describe(*v);
        error(key, "expected one of " + choices + ", got " + got +
                       (v->is_string() ? suggestion(v->get<std::string>(), names) : ""));
    }

    // Descends into an object under `key`; returns false (after reporting) if it is not one.
    const Json* object(std::string_view key) {
        const Json* v = find(key);
        if (v && !v->is_object()) {
            error(key, "expected an object, got " + describe(*v));
            return nullptr;
        }
        return v;
    }

    static std::string describe(const Json& v) {
        switch (v.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::boolean: return v.get<bool>() ? "true" : "false";
        case Json::value_t::string: return "a string";
        case Json::value_t::array: return "an array of " + std::to_string(v.size());
        case Json::value_t::object: return "an object";
        default: return v.dump();
        }
    }

private:
    void readNumberAt(const Json& v, const std::string& where, float& dst, const limits::Range* range) {
        if (!v.is_number()) {
            out_.push_back({file_, where, "expected a number, got " + describe(v)});
            return;
        }
        double d = v.get<double>();
        float f = static_cast<float>(d);
        if (!std::isfinite(d) || !std::isfinite(f)) {
            out_.push_back({file_, where, "number out of range: " + v.dump()});
            return;
        }
        if (range && !limits::contains(*range, f)) {
            out_.push_back({file_, where, std::string("must be ") + range->text + ", got " + v.dump()});
            return;
        }
        dst = f;
    }

    const Json& object_;
    std::string path_;
    const std::string& file_;
    Diagnostics& out_;
    std::set<std::string, std::less<>> consumed_;
};

// Deep nesting would recurse deeply in the JSON parser; no valid preset nests past 4.
constexpr int kMaxJsonDepth = 32;

bool nestingWithin(std::string_view text, int maxDepth) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                inString = false;
            }
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth) {
                return false;
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return true;
}

// "line L, column C" of a byte offset, for parse errors.
std::string lineColumn(std::string_view text, std::size_t offset) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

void readModel(Reader& top, Model& model, const std::string& file, const std::optional<fs::path>& folder,
               Diagnostics& out) {
    const Json* json = top.object("model");
    if (!json) {
        return;
    }
    Reader r(*json, "model", file, out);
    bool hasBuiltin = r.has("builtin");
    bool hasGltf = r.has("gltf");
    if (hasBuiltin && hasGltf) {
        r.error("gltf", "a model has either \"builtin\" or \"gltf\", not both");
    }
    r.readEnum("builtin", model.builtin, kBuiltinNames);
    model.subdivisions = defaultSubdivisions(model.builtin);
    if (hasGltf) {
        std::string path;
        r.readString("gltf", path);
        if (r.has("subdivisions")) {
            r.find("subdivisions");
            r.error("subdivisions", "applies to built-in models only");
        }
        if (!path.empty()) {
            std::string lower = path;
            std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
            std::string error;
            if (!lower.ends_with(".gltf") && !lower.ends_with(".glb")) {
                r.error("gltf", "expected a .gltf or .glb file, got \"" + path + "\"");
            } else if (!folder) {
                r.error("gltf", "a glTF model needs the preset to be a file (paths are relative to it)");
            } else if (!resolveModelPath(path, *folder, error)) {
                r.error("gltf", error);
            } else {
                model.gltf = path;
            }
        } else if (r.has("gltf") && json->at("gltf").is_string()) {
            r.error("gltf", "expected a path, got an empty string");
        }
    } else {
        bool round = model.builtin == Builtin::Sphere || model.builtin == Builtin::Torus;
        r.readInt2("subdivisions", model.subdivisions, round ? limits::kSubdivisionsRound : limits::kSubdivisions);
        if (model.builtin == Builtin::Sphere && model.subdivisions.y < 2) {
            r.error("subdivisions", "a sphere needs at least 2 stacks");
        }
    }
    r.readVec3("scale", model.scale);
    for (int i = 0; i < 3; ++i) {
        if (model.scale[i] == 0.0f) {
            r.error("scale", "scale factors must not be 0 (the normal matrix would not exist)");
            break;
        }
    }
    r.readVec3("rotate_deg", model.rotateDeg);
    r.readVec3("translate", model.translate);
    r.finish({"builtin", "gltf", "subdivisions", "scale", "rotate_deg", "translate"});
}

void readCamera(Reader& top, Camera& camera, const std::string& file, Diagnostics& out) {
    const Json* json = top.object("camera");
    if (!json) {
        return;
    }
    Reader r(*json, "camera", file, out);
    r.readVec3("eye", camera.eye);
    r.readVec3("target", camera.target);
    r.readVec3("up", camera.up);
    r.readNumber("fovy_deg", camera.fovyDeg, limits::kFovyDeg);
    r.readNumber("near", camera.near, limits::kNear);
    r.readNumber("far", camera.far, limits::kFar);
    if (camera.far <= camera.near) {
        r.error("far", "must be greater than near");
    }
    glm::vec3 forward = camera.target - camera.eye;
    if (glm::dot(forward, forward) == 0.0f) {
        r.error("target", "must differ from eye");
    } else {
        glm::vec3 side = glm::cross(forward, camera.up);
        if (glm::dot(side, side) <= 1e-12f * glm::dot(forward, forward) * glm::dot(camera.up, camera.up)) {
            r.error("up", "must not be parallel to the viewing direction (or zero)");
        }
    }
    r.finish({"eye", "target", "up", "fovy_deg", "near", "far"});
}

void readLight(const Json& json, const std::string& path, LightDesc& light, const std::string& file,
               Diagnostics& out) {
    Reader r(json, path, file, out);
    r.readEnum("type", light.type, kLightTypeNames);
    r.readVec3("position", light.position);
    r.readVec3("direction", light.direction);
    if (light.direction == glm::vec3(0.0f)) {
        r.error("direction", "must not be the zero vector");
    }
    r.readVec3("ambient", light.ambient, limits::kLightColor);
    r.readVec3("diffuse", light.diffuse, limits::kLightColor);
    r.readVec3("specular", light.specular, limits::kLightColor);
    r.readVec3("attenuation", light.attenuation, limits::kAttenuation);
    if (light.attenuation == glm::vec3(0.0f)) {
        r.error("attenuation", "c0, c1 and c2 must not all be 0");
    }
    r.readNumber("cutoff_deg", light.cutoffDeg, limits::kCutoffDeg);
    r.readNumber("exponent", light.exponent, limits::kSpotExponent);
    r.readBool("enabled", light.enabled);
    r.finish({"type", "position", "direction", "ambient", "diffuse", "specular", "attenuation", "cutoff_deg",
              "exponent", "enabled"});
}

} // namespace

std::optional<fs::path> resolveModelPath(const std::string& gltf, const fs::path& folder, std::string& error) {
    fs::path relative(gltf);
    if (relative.is_absolute()) {
        error = "\"" + gltf + "\" is an absolute path; model paths are relative to the preset's folder";
        return std::nullopt;
    }
    fs::path base = canonicalFolder(folder);
    std::error_code ec;
    fs::path full = fs::weakly_canonical(base / relative, ec);
    if (ec) {
        error = "\"" + gltf + "\": " + ec.message();
        return std::nullopt;
    }
    if (!isInside(base, full)) {
        error = "\"" + gltf + "\" leaves the preset's folder " + base.string();
        return std::nullopt;
    }
    fs::file_status status = fs::status(full, ec);
    if (!fs::exists(status)) {
        error = "model file \"" + gltf + "\" not found (looked for " + full.string() + ")";
        return std::nullopt;
    }
    if (!fs::is_regular_file(status)) {
        error = "\"" + gltf + "\" is not a regular file";
        return std::nullopt;
    }
    return full;
}

std::optional<Preset> parsePreset(std::string_view text, const std::string& displayName,
                                  const std::optional<fs::path>& folder, Diagnostics& diagnostics) {
    Diagnostics out;
    const std::string& file = displayName;
    if (!nestingWithin(text, kMaxJsonDepth)) {
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
        diagnostics.push_back({file, lineColumn(text, e.byte == 0 ? 0 : e.byte - 1), "invalid JSON: " + detail});
        return std::nullopt;
    } catch (const Json::out_of_range& e) {
        // A number too large for a double, e.g. 1e999: "... number overflow parsing '1e999'".
        std::string what = e.what();
        std::size_t open = what.find('\''), close = what.rfind('\'');
        std::string number = open < close ? what.substr(open + 1, close - open - 1) : "";
        std::size_t at = number.empty() ? std::string_view::npos : text.find(number);
        diagnostics.push_back({file, at == std::string_view::npos ? "" : lineColumn(text, at),
                               "number out of range: " + (number.empty() ? what : number)});
        return std::nullopt;
    } catch (const Json::exception& e) {
        diagnostics.push_back({file, "", std::string("invalid JSON: ") + e.what()});
        return std::nullopt;
    }
    if (!json.is_object()) {
        diagnostics.push_back({file, "", "a preset is a JSON object, got " + Reader::describe(json)});
        return std::nullopt;
    }

    Preset preset;
    Reader r(json, "", file, out);

    // Format and version first: a file that is not a preset gets one clear message, not fifty.
    const Json* format = r.find("format");
    if (!format) {
        diagnostics.push_back({file, "format", "missing; expected \"" + std::string(kPresetFormat) + "\""});
        return std::nullopt;
    }
    if (!format->is_string() || format->get<std::string>() != kPresetFormat) {
        diagnostics.push_back(
            {file, "format", "expected \"" + std::string(kPresetFormat) + "\", got " + format->dump()});
        return std::nullopt;
    }
    const Json* version = r.find("version");
    if (!version) {
        diagnostics.push_back({file, "version", "missing; expected " + std::to_string(kPresetVersion)});
        return std::nullopt;
    }
    if (!version->is_number_integer() && !version->is_number_unsigned()) {
        diagnostics.push_back({file, "version", "expected an integer, got " + version->dump()});
        return std::nullopt;
    }
    if (version->get<double>() > kPresetVersion) {
        diagnostics.push_back({file, "version",
                               "version " + version->dump() + " is newer than this program reads (" +
                                   std::to_string(kPresetVersion) + "); update Lighting Lab"});
        return std::nullopt;
    }
    if (version->get<double>() < 1) {
        diagnostics.push_back({file, "version", "expected " + std::to_string(kPresetVersion) + ", got " + version->dump()});
        return std::nullopt;
    }

    r.readString("name", preset.name);
    r.readString("description", preset.description);
    readModel(r, preset.model, file, folder, out);
    readCamera(r, preset.camera, file, out);
    r.readEnum("shading", preset.shading, kShadingNames);
    r.readEnum("normal_matrix", preset.normalMatrix, kNormalMatrixNames);
    r.readEnum("brdf", preset.brdf, kBrdfNames);
    if (const Json* ct = r.object("cook_torrance")) {
        Reader c(*ct, "cook_torrance", file, out);
        c.readEnum("distribution", preset.cookTorrance.distribution, kDistributionNames);
        c.readNumber("roughness", preset.cookTorrance.roughness, limits::kRoughness);
        c.readEnum("fresnel", preset.cookTorrance.fresnel, kFresnelNames);
        c.readNumber("ior", preset.cookTorrance.ior, limits::kIor);
        c.readBool("geometry", preset.cookTorrance.geometry);
        c.finish({"distribution", "roughness", "fresnel", "ior", "geometry"});
    }
    if (const Json* m = r.object("material")) {
        Reader c(*m, "material", file, out);
        c.readVec3("emissive", preset.material.emissive, limits::kMaterialColor);
        c.readVec3("ambient", preset.material.ambient, limits::kMaterialColor);
        c.readVec3("diffuse", preset.material.diffuse, limits::kMaterialColor);
        c.readVec3("specular", preset.material.specular, limits::kMaterialColor);
        c.readNumber("shininess", preset.material.shininess, limits::kShininess);
        c.finish({"emissive", "ambient", "diffuse", "specular", "shininess"});
    }
    r.readVec3("ambient_light", preset.ambientLight, limits::kAmbientLight);
    if (const Json* lights = r.find("lights")) {
        if (!lights->is_array()) {
            r.error("lights", "expected an array of lights, got " + Reader::describe(*lights));
        } else if (lights->size() > kMaxLights) {
            r.error("lights", "at most " + std::to_string(kMaxLights) + " lights, got " + std::to_string(lights->size()));
        } else {
            preset.lights.assign(lights->size(), LightDesc{});
            for (std::size_t i = 0; i < lights->size(); ++i) {
                std::string path = "lights[" + std::to_string(i) + "]";
                const Json& l = (*lights)[i];
                if (!l.is_object()) {
                    out.push_back({file, path, "expected an object, got " + Reader::describe(l)});
                } else {
                    readLight(l, path, preset.lights[i], file, out);
                }
            }
        }
    }
    if (const Json* t = r.object("terms")) {
        Reader c(*t, "terms", file, out);
        c.readBool("emissive", preset.terms.emissive);
        c.readBool("ambient", preset.terms.ambient);
        c.readBool("diffuse", preset.terms.diffuse);
        c.readBool("specular", preset.terms.specular);
        c.finish({"emissive", "ambient", "diffuse", "specular"});
    }
    r.readVec3("background", preset.background, limits::kBackground);
    if (const Json* p = r.object("plot")) {
        Reader c(*p, "plot", file, out);
        c.readNumber("incident_deg", preset.plotIncidentDeg, limits::kPlotIncidentDeg);
        c.finish({"incident_deg"});
    }
    r.finish({"format", "version", "name", "description", "model", "camera", "shading", "normal_matrix", "brdf",
              "cook_torrance", "material", "ambient_light", "lights", "terms", "background", "plot"});

    if (!out.empty()) {
        diagnostics.insert(diagnostics.end(), out.begin(), out.end());
        return std::nullopt;
    }
    return preset;
}

std::optional<LoadedPreset> loadPreset(const fs::path& file, Diagnostics& diagnostics) {
    std::string error;
    std::optional<std::string> text = readFile(file, kMaxPresetBytes, error);
    if (!text) {
        diagnostics.push_back({file.string(), "", error});
        return std::nullopt;
    }
    fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    std::optional<Preset> preset = parsePreset(*text, file.string(), folder, diagnostics);
    if (!preset) {
        return std::nullopt;
    }
    return LoadedPreset{std::move(*preset), file};
}

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

} // namespace

namespace {

bool hasNonFinite(const Json& j) {
    if (j.is_number_float()) {
        return !std::isfinite(j.get<double>());
    }
    if (j.is_structured()) {
        return std::any_of(j.begin(), j.end(), hasNonFinite);
    }
    return false;
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
    }
    j["lights"] = lights;
    j["terms"] = {{"emissive", p.terms.emissive},
                  {"ambient", p.terms.ambient},
                  {"diffuse", p.terms.diffuse},
                  {"specular", p.terms.specular}};
    j["background"] = vec3(p.background);
    j["plot"] = {{"incident_deg", number(p.plotIncidentDeg)}};
    return j;
}

} // namespace

std::string presetToJson(const Preset& preset) {
    std::string out;
    emit(presetJson(preset), out, 0);
    out += '\n';
    return out;
}

bool savePreset(const Preset& preset, const fs::path& file, Diagnostics& diagnostics) {
    // A preset in memory can hold non-finite values only through a bug elsewhere (JSON has no
    // NaN, so they would come out as null); refuse to write a file that would not load.
    Json json = presetJson(preset);
    if (hasNonFinite(json)) {
        diagnostics.push_back({file.string(), "", "refusing to save a preset with non-finite numbers"});
        return false;
    }
    std::string text;
    emit(json, text, 0);
    text += '\n';
    std::string error;
    if (!writeFileAtomic(file, text, error)) {
        diagnostics.push_back({file.string(), "", error});
        return false;
    }
    return true;
}

} // namespace lab
