// preset_fields.cpp — preset fields by JSON path: differences, open paths, patches.
#include "core/exercise/preset_fields.h"

#include "core/scene/limits.h"

#include <algorithm>

namespace lab {

namespace {

bool isObjectArray(const PresetJson& v) {
    return v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), [](const PresetJson& e) { return e.is_object(); });
}

std::string join(const std::string& prefix, std::string_view key) {
    return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

void collectChanges(const PresetJson& a, const PresetJson& b, const std::string& path, std::vector<std::string>& out) {
    if (a.is_object() && b.is_object()) {
        for (const auto& [key, value] : a.items()) {
            auto other = b.find(key);
            if (other == b.end()) {
                out.push_back(join(path, key));
            } else {
                collectChanges(value, *other, join(path, key), out);
            }
        }
        for (const auto& [key, value] : b.items()) {
            if (!a.contains(key)) {
                out.push_back(join(path, key));
            }
        }
        return;
    }
    if ((isObjectArray(a) || isObjectArray(b)) && a.is_array() && b.is_array()) {
        std::size_t n = std::max(a.size(), b.size());
        for (std::size_t i = 0; i < n; ++i) {
            std::string element = path + "[" + std::to_string(i) + "]";
            if (i < a.size() && i < b.size()) {
                collectChanges(a[i], b[i], element, out);
            } else {
                out.push_back(element);
            }
        }
        return;
    }
    if (a != b) {
        out.push_back(path);
    }
}

// The path's parts: "lights[1].attenuation" is {"lights", 1, "attenuation"}; nullopt if malformed.
struct Part {
    std::string key;
    std::optional<std::size_t> index;
};

std::optional<std::vector<Part>> splitPath(std::string_view path) {
    std::vector<Part> parts;
    std::size_t i = 0;
    bool needKey = true; // at the start and after a '.'
    while (i < path.size()) {
        if (path[i] == '[') {
            std::size_t close = path.find(']', i);
            if (parts.empty() || needKey || close == std::string_view::npos || close == i + 1 || close - i > 4 ||
                (path[i + 1] == '0' && close > i + 2)) { // no leading zeros: "lights[00]" names nothing
                return std::nullopt;
            }
            std::size_t index = 0;
            for (std::size_t k = i + 1; k < close; ++k) {
                if (path[k] < '0' || path[k] > '9') {
                    return std::nullopt;
                }
                index = index * 10 + std::size_t(path[k] - '0');
            }
            parts.push_back({"", index});
            i = close + 1;
        } else if (path[i] == '.') {
            if (needKey) {
                return std::nullopt;
            }
            needKey = true;
            ++i;
            continue;
        } else {
            if (!needKey) {
                return std::nullopt;
            }
            std::size_t end = path.find_first_of(".[", i);
            end = end == std::string_view::npos ? path.size() : end;
            parts.push_back({std::string(path.substr(i, end - i)), std::nullopt});
            i = end;
        }
        needKey = false;
    }
    if (parts.empty() || needKey) {
        return std::nullopt;
    }
    return parts;
}

// `full` marked as a whole preset (mergePreset takes it as it is).
PresetJson whole(const PresetJson& full) {
    PresetJson j = {{"format", kPresetFormat}, {"version", kPresetVersion}};
    for (const auto& [key, value] : full.items()) {
        j[key] = value;
    }
    return j;
}

} // namespace

PresetJson presetValue(const Preset& preset) {
    PresetJson j = PresetJson::parse(presetToJson(preset));
    j.erase("format");
    j.erase("version");
    return j;
}

std::vector<std::string> changedFields(const PresetJson& a, const PresetJson& b) {
    std::vector<std::string> out;
    collectChanges(a, b, "", out);
    return out;
}

bool covers(std::string_view prefix, std::string_view path) {
    if (!path.starts_with(prefix)) {
        return false;
    }
    return path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[';
}

bool alwaysFree(std::string_view path) {
    for (std::string_view free : {"name", "description", "camera", "plot", "check", "sweep"}) {
        if (covers(free, path)) {
            return true;
        }
    }
    return false;
}

const PresetJson* fieldAt(const PresetJson& json, std::string_view path) {
    std::optional<std::vector<Part>> parts = splitPath(path);
    if (!parts) {
        return nullptr;
    }
    const PresetJson* at = &json;
    for (const Part& part : *parts) {
        if (part.index) {
            if (!at->is_array() || *part.index >= at->size()) {
                return nullptr;
            }
            at = &(*at)[*part.index];
        } else {
            if (!at->is_object()) {
                return nullptr;
            }
            auto it = at->find(part.key);
            if (it == at->end()) {
                return nullptr;
            }
            at = &*it;
        }
    }
    return at;
}

bool knownFieldPath(std::string_view path, const std::vector<const PresetJson*>& examples) {
    // Every field a preset can have: the defaults (a built-in model, one light), a glTF model,
    // a light with an orbit, as many lights as a preset may hold.
    static const PresetJson all = [] {
        Preset p;
        p.lights.assign(static_cast<std::size_t>(limits::kMaxLights), LightDesc{});
        p.lights.front().orbit.on = true;
        PresetJson j = presetValue(p);
        j["model"]["gltf"] = "model.glb";
        for (PresetJson& light : j["lights"]) {
            light["orbit"] = j["lights"][0]["orbit"];
        }
        return j;
    }();
    if (fieldAt(all, path)) {
        return true;
    }
    return std::any_of(examples.begin(), examples.end(), [&](const PresetJson* e) { return e && fieldAt(*e, path); });
}

PresetJson mergePreset(PresetJson base, const PresetJson& patch) {
    if (!base.is_object() || !patch.is_object() || patch.contains("format")) {
        return patch; // a whole preset replaces the base
    }
    for (const auto& [key, value] : patch.items()) {
        auto at = base.find(key);
        if (value.is_null()) {
            base.erase(key); // a key the patch removes (RFC 7386)
        } else if (at == base.end()) {
            base[key] = value;
        } else if (key == "model" && value.is_object() && at->is_object()) {
            if (value.contains("gltf")) {
                at->erase("builtin");
                at->erase("subdivisions");
            } else if (value.contains("builtin")) {
                at->erase("gltf");
            }
            *at = mergePreset(*at, value);
        } else if (value.is_object() && at->is_object()) {
            *at = mergePreset(*at, value);
        } else if (key == "lights" && value.is_array() && at->is_array()) {
            for (std::size_t i = 0; i < value.size(); ++i) {
                if (i < at->size() && value[i].is_object() && (*at)[i].is_object()) {
                    (*at)[i] = mergePreset((*at)[i], value[i]);
                } else if (i < at->size()) {
                    (*at)[i] = value[i];
                } else {
                    at->push_back(value[i]);
                }
            }
        } else {
            *at = value;
        }
    }
    return base;
}

PresetJson presetPatch(const PresetJson& base, const PresetJson& full) {
    if (!base.is_object() || !full.is_object()) {
        return full;
    }
    PresetJson patch = PresetJson::object();
    for (const auto& [key, value] : full.items()) {
        auto at = base.find(key);
        if (at == base.end()) {
            patch[key] = value;
        } else if (*at == value) {
            continue;
        } else if (key == "model" && value.is_object() && at->is_object() &&
                   value.contains("gltf") != at->contains("gltf")) {
            patch[key] = value; // a model of the other kind: all of it
        } else if (value.is_object() && at->is_object()) {
            patch[key] = presetPatch(*at, value);
        } else if (key == "lights" && value.is_array() && at->is_array()) {
            if (value.size() < at->size()) {
                return whole(full); // a patch cannot remove a light
            }
            PresetJson lights = PresetJson::array();
            for (std::size_t i = 0; i < value.size(); ++i) {
                // A light the base lacks: what differs from a default light (a light read with
                // keys left out has their defaults).
                static const PresetJson defaultLight = presetValue(Preset{})["lights"][0];
                lights.push_back(presetPatch(i < at->size() ? (*at)[i] : defaultLight, value[i]));
            }
            patch[key] = lights;
        } else {
            patch[key] = value;
        }
    }
    for (const auto& [key, value] : base.items()) {
        if (!full.contains(key)) {
            patch[key] = nullptr; // removed (a light's orbit switched off, a check block's tolerance)
        }
    }
    return patch;
}

} // namespace lab
