// field_edit.h — one field of a preset set from text, as the page's own controls send it.
//
// The browser page (web/access.js) offers every field of the table as a native HTML control; a
// change there arrives as a path and the control's text ("material.shininess" "32",
// "lights[1].type" "spot", "material.diffuse[2]" "0.5"). This checks it as a preset file's value
// is checked (the row's range, a direction's length, the row's rules) and sets it, or leaves the
// preset exactly as it was and says why. No JSON, no UI.
#pragma once

#include "core/scene/preset.h"

#include <string>
#include <string_view>

namespace lab {

// Sets the field at `path` (a row's path for an existing light, or one element of a triplet or a
// pair) from `text`: a number (read by the preset reader's JSON parser and checked by its
// numberProblem, so exactly what a preset file may hold there, and ".5" and "5."), "true"/"false",
// a choice's file name, or a text; then every rule of the field's object holds (field_table.h
// objectRules). Returns "" when set, else the problem ("material.shininess: must be in [0.001,
// 1000000], got 1000001": the value as typed; values and paths quoted at 120 bytes, safe_text.h)
// with `preset` untouched.
std::string setFieldFromText(Preset& preset, std::string_view path, std::string_view text);

} // namespace lab
