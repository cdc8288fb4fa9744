// preset_fields.cpp — preset fields by JSON path: differences, open paths, patches.
#include "core/exercise/preset_fields.h"

#include "core/scene/field_table.h"

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
    PresetJson j = PresetJson::parse(std::string_view(presetToJson(preset)));
    j.erase("format");
    j.erase("version");
    return j;
}

std::vector<std::string> changedFields(const PresetJson& a, const PresetJson& b) {
    std::vector<std::string> out;
    collectChanges(a, b, "", out);
    return out;
}

bool alwaysFree(std::string_view path) {
    for (std::string_view free : {"name", "description", "camera", "plot", "check", "sweep", "display", "notes", "compare"}) {
        if (covers(free, path)) {
            return true;
        }
    }
    return false;
}

const PresetJson* fieldAt(const PresetJson& json, std::string_view path) {
    std::optional<std::vector<PathStep>> steps = parseFieldPath(path);
    if (!steps) {
        return nullptr;
    }
    const PresetJson* at = &json;
    for (const PathStep& part : *steps) {
        if (part.isIndex()) {
            if (!at->is_array() || part.index >= at->size()) {
                return nullptr;
            }
            at = &(*at)[part.index];
        } else {
            if (!at->is_object()) {
                return nullptr;
            }
            auto it = at->find(part.name);
            if (it == at->end()) {
                return nullptr;
            }
            at = &*it;
        }
    }
    return at;
}

bool knownFieldPath(std::string_view path, const std::vector<const PresetJson*>& examples) {
    if (isFieldPath(path)) {
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

namespace {

// A field's value as the label says it: a choice's label, a number as the file has it, a triplet
// "(0.8, 0.8, 0.8)", a switch "on"/"off"; a light only one set has is "none" in the other.
std::string valueText(const PresetJson* value, const FieldRow* row) {
    if (!value) {
        return "none";
    }
    if (row && row->kind == FieldKind::Choice && value->is_string()) {
        for (const FieldChoice& c : row->choices) {
            if (c.name == value->get<std::string>()) {
                return c.label;
            }
        }
    }
    if (value->is_boolean()) {
        return value->get<bool>() ? "on" : "off";
    }
    if (value->is_object()) { // a light only one set has
        auto type = value->find("type");
        return type != value->end() && type->is_string() ? type->get<std::string>() + " light" : "present";
    }
    if (value->is_array() && std::all_of(value->begin(), value->end(), [](const PresetJson& v) { return v.is_number(); })) {
        std::string text;
        for (const PresetJson& v : *value) {
            text += (text.empty() ? "(" : ", ") + v.dump();
        }
        return text + ")";
    }
    return value->is_string() ? value->get<std::string>() : value->dump();
}

// "normal matrix", "light 2 position", "light 3".
std::string fieldName(std::string_view path, const FieldRow* row) {
    std::string name;
    if (path.starts_with("lights[")) {
        const std::size_t close = path.find(']');
        int index = 0;
        for (char c : path.substr(7, close - 7)) {
            index = index * 10 + (c - '0'); // a path of changedFields: digits only
        }
        name = "light " + std::to_string(index + 1);
        if (!row) {
            return name;
        }
        name += " ";
    }
    return name + std::string(row && !row->label.empty() ? row->label : path);
}

} // namespace

DifferenceLabels differenceLabels(const Preset& a, const Preset& b, std::size_t most) {
    const PresetJson ja = presetValue(a), jb = presetValue(b);
    std::vector<std::string> changed = changedFields(ja, jb);
    std::erase_if(changed, [](const std::string& path) { return alwaysFree(path); }); // not the picture's
    DifferenceLabels labels;
    for (std::size_t i = 0; i < changed.size() && i < most; ++i) {
        const FieldRow* row = fieldRow(changed[i]);
        const std::string name = fieldName(changed[i], row);
        const std::string sep = i == 0 ? "" : "; ";
        labels.a += sep + name + ": " + valueText(fieldAt(ja, changed[i]), row);
        labels.b += sep + name + ": " + valueText(fieldAt(jb, changed[i]), row);
    }
    if (changed.size() > most) {
        const std::string more = " (+" + std::to_string(changed.size() - most) + " more)";
        labels.a += more;
        labels.b += more;
    }
    return labels;
}

} // namespace lab
