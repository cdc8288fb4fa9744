// field_widget.h — a preset field's widget, drawn from its row of the field table.
//
// The label, range, step, format, help and kind come from core/scene/field_table.h, so the panel
// never spells a field's range or label itself. Every widget is named for the GUI tests by its
// field's path ("material.shininess", "lights[1].cutoff_deg"). A value the field's rules refuse
// (c0, c1, c2 all 0; a direction shorter than limits::kMinDirectionLength) is not taken: the field
// keeps its last accepted value. ImGui only.
#pragma once

#include "core/scene/field_table.h"

#include <string>

namespace lab::ui {

// Draws the field `row` of `preset` (of `light`, for a light's row) under the name `path`. True
// when the value changed.
bool fieldWidget(const FieldRow& row, Preset& preset, LightDesc* light, const std::string& path);

} // namespace lab::ui
