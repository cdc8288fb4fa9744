// preset_fields.h — a preset's fields by their JSON paths: which differ, which an exercise leaves
// open, and a preset written as only what differs from another.
//
// A field is a leaf of the preset's saved JSON (core/scene/preset.h presetToJson): a number, a
// string, a switch or an array of numbers ("material.diffuse", "lights[1].attenuation"). Objects,
// and arrays of objects (the lights), are walked into. An exercise's `open` list and its field
// tolerances name fields, or whole objects above them ("lights[0]", "material").
#pragma once

#include "core/scene/field_path.h" // the path grammar, covers()
#include "core/scene/preset.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

using PresetJson = nlohmann::ordered_json;

// The preset's saved JSON as a value (every key), without "format" and "version".
PresetJson presetValue(const Preset& preset);

// The paths of the fields whose values differ between `a` and `b`, in the order of `a`'s keys. A
// light only one of them has is one path ("lights[2]").
std::vector<std::string> changedFields(const PresetJson& a, const PresetJson& b);

// Fields a student may always change: looking around, naming and describing is never cheating,
// and `check`/`sweep` only tell `lab check` what to compare.
bool alwaysFree(std::string_view path);

// Whether `path` names a field or an object of fields a preset can have (the field table's,
// core/scene/field_table.h, with up to limits::kMaxLights lights), or a value one of `examples` holds.
bool knownFieldPath(std::string_view path, const std::vector<const PresetJson*>& examples);

// The value at `path` in `json`, or nullptr.
const PresetJson* fieldAt(const PresetJson& json, std::string_view path);

// `patch` applied to `base`: a patch with "format" is a whole preset and replaces it; otherwise objects merge key by key
// (a key whose value is null is removed, as in RFC 7386), the lights element by element (a light the
// base lacks is added), anything else is replaced. A model given as "gltf" drops the base's
// built-in and the other way round.
PresetJson mergePreset(PresetJson base, const PresetJson& patch);

// What tells two sets apart, for compare mode's labels and `lab render`'s compare view: each
// field of the scene that differs (what alwaysFree() names aside: the camera, the texts, the plots,
// the check and the lecture's parts) as
// "label: value" — "normal matrix: model-view (wrong)" for `a`, "normal matrix: inverse-transpose
// (correct)" for `b` — at most `most` of them, then "+N more"; both empty when nothing differs.
struct DifferenceLabels {
    std::string a, b;
};
DifferenceLabels differenceLabels(const Preset& a, const Preset& b, std::size_t most = 3);

// What `mergePreset(base, ·)` needs to turn `base` into `full`: only the keys that differ, null for
// a key `full` lacks. Where `full` has fewer lights than `base` (a patch does not remove elements),
// the whole of `full` with "format" and "version".
PresetJson presetPatch(const PresetJson& base, const PresetJson& full);

} // namespace lab
