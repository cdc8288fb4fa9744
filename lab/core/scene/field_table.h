// field_table.h — every field of a preset, described once.
//
// One row per field of the scene: its JSON path, where it lives in Preset, its kind, range and
// step, unit, label, one-line help, group, and the rules that tie it to other fields. The preset
// reader and writer (preset_read.cpp, preset.cpp; a sweep's values are checked by both), the
// panel's widgets (ui/panel), the sweep's suggestions (sweep.h), an exercise's open paths and field tolerances
// (core/exercise/preset_fields.h) and, through the writer, the share link's "only what differs"
// all read this table, so they cannot disagree. Adding a material parameter is one row here and
// its Preset member; the reader, writer, panel, sweep and exercise paths follow.
//
// The rows are in the order a preset file writes its keys. A light's rows are written once, as
// "lights[].type", and stand for every light. `check` and `sweep` are not scene fields (they tell
// `lab check` what to compare, with structured values): preset_read.cpp and preset.cpp read and
// write them by hand, after the table's keys.
//
// This file owns the rows and the questions asked of them. It does not read or write JSON, or
// draw anything.
#pragma once

#include "core/scene/limits.h"
#include "core/scene/preset.h"

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lab {

enum class FieldKind {
    Number,    // float within `range`
    Vec3,      // three floats, each within `range` (a position, a scale, angles)
    Color,     // three floats within `range`, edited as a colour (reflectances, intensities)
    Direction, // three floats within `range`, at least limits::kMinDirectionLength long
    Int2,      // two integers within `intRange`
    Switch,    // true or false
    Choice,    // one of `choices`, by name
    Text,      // a string
};

// The panel's sections (ui/panel) a field belongs to; the sweep's suggestions are ordered by them.
enum class FieldGroup { File, Model, Camera, Shading, Brdf, Material, Lights, Plot };

// How a field's widget looks, beyond its kind.
enum FieldStyle : unsigned {
    kStylePlain = 0,
    kStyleLogarithmic = 1u << 0, // a number's slider is logarithmic
    kStyleRadios = 1u << 1,      // a choice is a row of radio buttons (else a combo)
    kStyleHelpMarker = 1u << 2,  // the panel shows the help beside the widget as "(?)"
    kStyleHidden = 1u << 3,      // no widget of its own (the camera's up, near and far; the file's name)
    kStyleLobe = 1u << 4,        // the number that shapes its BRDF's specular lobe (shininess n, roughness m)
};

// One value of an enumeration: its integer, the name preset files use, and the panel's label.
struct FieldChoice {
    int value;
    std::string_view name;
    const char* label;
};

// A problem a rule finds: the key it names, relative to the row's object ("far", "up"), and the
// message completing "<path>: ".
struct FieldProblem {
    std::string key;
    std::string message;
};

struct FieldRow {
    std::string_view path; // "material.shininess"; "lights[].exponent" for every light's
    FieldKind kind;
    FieldGroup group;
    const limits::Range* range = nullptr;       // Number, Vec3, Color, Direction
    const limits::IntRange* intRange = nullptr; // Int2 (the model's subdivisions: the reader asks limits.h's
                                                // kSubdivisionsRound of a sphere or a torus)
    std::span<const FieldChoice> choices = {};  // Choice
    float step = 0.0f;                          // a drag's step (Vec3, Direction)
    const char* format = "%.3f";                // a number's format on screen
    unsigned style = kStylePlain;
    std::string_view unit = {};  // "deg", "deg/s"; empty when none
    std::string_view label = {}; // the panel's label, without the unit
    std::string_view help = {};  // one line: what the field does
    std::string_view sweep = {}; // suggested sweep values "V1,V2,..."; alternatives for parts of
                                 // the field as "[1]=V1,V2;[2]=V1,V2"; empty: none suggested
    // Where the field lives: the address of its value (float, glm::vec3, glm::ivec2, bool, an enum
    // with int values, std::string by kind) in `preset`, or in `light` for a light's row.
    void* (*at)(Preset& preset, LightDesc* light) = nullptr;
    // Whether the field matters for this preset (its BRDF, its light's type); nullptr: always.
    bool (*applies)(const Preset& preset, const LightDesc* light) = nullptr;
    // Whether the writer writes it (a glTF model has no subdivisions; a light's orbit only when it
    // moves or differs from the default); nullptr: always.
    bool (*written)(const Preset& preset, const LightDesc* light) = nullptr;
    // What must hold once the field is read, beyond its own range (c0, c1, c2 not all 0); nullptr: none.
    void (*rule)(const Preset& preset, const LightDesc* light, std::vector<FieldProblem>& problems) = nullptr;
    // The reader reads it with a rule of its own, not by kind (the model's built-in, glTF and subdivisions).
    bool custom = false;
};

// Every row, in the order a preset file writes its keys.
std::span<const FieldRow> fieldRows();

// The row of `path` ("material.shininess", "lights[2].exponent", "lights[].exponent"), or nullptr.
// An element of a triplet ("material.diffuse[1]") is its triplet's row; an object is no row.
const FieldRow* fieldRow(std::string_view path);

// Whether `path` names a field, or an object or element of fields ("lights[0]", "material",
// "material.diffuse[1]") a preset can have, with at most limits::kMaxLights lights.
bool isFieldPath(std::string_view path);

// The row's path for light `light` ("lights[2].exponent"); the path itself for a row not of a light.
std::string fieldPath(const FieldRow& row, int light);

// The row's key in its object ("exponent") and its object's path ("lights[]", "lights[].orbit",
// "" at the top).
std::string_view fieldKey(const FieldRow& row);
std::string_view fieldObject(const FieldRow& row);

// What an edit of `row` must keep: the rule of every row in its object (the camera's, on its row
// "far", ties eye, target and up), each for `light`. The reader runs a rule once its row is read,
// after the rest of its object; an edit of one field (the panel's, the page's) runs them all.
void objectRules(const FieldRow& row, const Preset& preset, const LightDesc* light, std::vector<FieldProblem>& problems);
bool isLightRow(const FieldRow& row);

// Where `row` lies from the object at `object` ("" the top level, "material", "lights[]" one light),
// for the reader and the writer, which walk the rows object by object: a member of it (`key` is its
// key), in an object below it (`key` is that object's key in `object`, `child` its path, `array` when
// it is the lights' array), or outside it.
struct FieldPlace {
    enum Where { Outside, Member, Below } where = Outside;
    std::string_view key;
    std::string_view child;
    bool array = false;
};
FieldPlace fieldPlace(const FieldRow& row, std::string_view object);

// The row's label with its unit: "cut-off (deg)".
std::string fieldLabel(const FieldRow& row);

// The value of a row, typed by its kind (null `light` for a row not of a light).
template <typename T>
T& fieldValue(const FieldRow& row, Preset& preset, LightDesc* light) {
    return *static_cast<T*>(row.at(preset, light));
}
int choiceValue(const FieldRow& row, const Preset& preset, const LightDesc* light);
void setChoice(const FieldRow& row, Preset& preset, LightDesc* light, int value);
bool applies(const FieldRow& row, const Preset& preset, const LightDesc* light);

// The name preset files use for a choice's value, "?" when it has none.
std::string_view choiceName(std::span<const FieldChoice> choices, int value);

// The choices of each enumeration (the names preset files use, the panel's labels).
extern const std::span<const FieldChoice> kBuiltinChoices, kShadingChoices, kNormalMatrixChoices, kBrdfChoices,
    kDistributionChoices, kFresnelChoices, kLightTypeChoices;

} // namespace lab
