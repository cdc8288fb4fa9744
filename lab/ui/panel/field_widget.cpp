// field_widget.cpp — a field's widget from its row (field_widget.h).
#include "ui/panel/field_widget.h"

#include "ui/widgets.h"

#include <glm/geometric.hpp>

#include <cstring>
#include <vector>

namespace lab::ui {

namespace {

const char* choiceLabel(std::span<const FieldChoice> choices, int value) {
    for (const FieldChoice& c : choices) {
        if (c.value == value) {
            return c.label;
        }
    }
    return "?";
}

bool choiceWidget(const FieldRow& row, Preset& preset, LightDesc* light, const std::string& id, const std::string& path) {
    int value = choiceValue(row, preset, light);
    bool changed = false;
    if (row.style & kStyleRadios) {
        ImGui::PushID(path.c_str());
        for (std::size_t i = 0; i < row.choices.size(); ++i) {
            const FieldChoice& c = row.choices[i];
            if (i > 0) {
                sameLineIfFitsRadio(c.label);
            }
            if (ImGui::RadioButton(c.label, value == c.value) && value != c.value) {
                value = c.value;
                changed = true;
            }
            mark(path + "." + c.label);
        }
        ImGui::PopID();
    } else if (ImGui::BeginCombo(id.c_str(), choiceLabel(row.choices, value))) {
        for (const FieldChoice& c : row.choices) {
            if (ImGui::Selectable(c.label, value == c.value) && value != c.value) {
                value = c.value;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    if (changed) {
        setChoice(row, preset, light, value);
    }
    return changed;
}

bool numbersWidget(const FieldRow& row, Preset& preset, LightDesc* light, const std::string& id) {
    const limits::Range& r = *row.range;
    if (row.kind == FieldKind::Number) {
        float& value = fieldValue<float>(row, preset, light);
        ImGuiSliderFlags flags = (row.style & kStyleLogarithmic) ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
        bool changed = ImGui::SliderFloat(id.c_str(), &value, r.sliderMin, r.sliderMax, row.format, flags);
        changed = sliderPageKeys(value, r.sliderMin, r.sliderMax, row.style & kStyleLogarithmic) || changed;
        value = limits::clamp(r, value); // typed values too (Ctrl+click)
        return changed;
    }
    glm::vec3& value = fieldValue<glm::vec3>(row, preset, light);
    if (row.kind == FieldKind::Color) {
        return limitedColorEdit(id.c_str(), value, r);
    }
    return dragVec3(id.c_str(), value, row.step, r.min, r.max, row.format);
}

} // namespace

bool fieldWidget(const FieldRow& row, Preset& preset, LightDesc* light, const std::string& path) {
    const std::string id = fieldLabel(row) + "##" + path; // one ImGui id per field, whatever its label
    // The field's value before the widget, to put back when its rules refuse the new one (the
    // numbers' kinds are the ones with rules, or with a length to keep).
    const bool numbers = row.kind == FieldKind::Number || row.kind == FieldKind::Vec3 || row.kind == FieldKind::Color ||
                         row.kind == FieldKind::Direction;
    const std::size_t size = row.kind == FieldKind::Number ? sizeof(float) : sizeof(glm::vec3);
    unsigned char before[sizeof(glm::vec3)] = {};
    if (numbers) {
        std::memcpy(before, row.at(preset, light), size);
    }
    bool changed = false;
    switch (row.kind) {
    case FieldKind::Number:
    case FieldKind::Vec3:
    case FieldKind::Color:
    case FieldKind::Direction: changed = numbersWidget(row, preset, light, id); break;
    case FieldKind::Switch: changed = ImGui::Checkbox(id.c_str(), &fieldValue<bool>(row, preset, light)); break;
    case FieldKind::Choice: changed = choiceWidget(row, preset, light, id, path); break;
    case FieldKind::Int2:
    case FieldKind::Text: break; // the model's subdivisions and the file's texts have widgets of their own
    }
    if (row.kind != FieldKind::Choice || !(row.style & kStyleRadios)) {
        mark(path);
    }
    // The field's rules: a value they refuse is not taken.
    bool refused = row.kind == FieldKind::Direction &&
                   glm::length(fieldValue<glm::vec3>(row, preset, light)) < limits::kMinDirectionLength;
    if (changed && !refused) {
        std::vector<FieldProblem> problems;
        objectRules(row, preset, light, problems);
        refused = !problems.empty();
    }
    if (changed && refused && numbers) {
        std::memcpy(row.at(preset, light), before, size);
        changed = false;
    }
    if (row.style & kStyleHelpMarker) {
        helpMarker(std::string(row.help).c_str());
    }
    return changed;
}

} // namespace lab::ui
