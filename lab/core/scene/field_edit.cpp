// field_edit.cpp — a field set from text, checked as the reader checks it (field_edit.h).
#include "core/scene/field_edit.h"

#include "core/scene/field_path.h"
#include "core/scene/field_table.h"

#include <glm/glm.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace lab {

namespace {

std::optional<float> number(std::string_view text) {
    std::string s(text);
    char* end = nullptr;
    float v = std::strtof(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) {
        return std::nullopt;
    }
    return v;
}

std::optional<int> integer(std::string_view text) {
    int v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return v;
}

std::string shown(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(v));
    return buffer;
}

// The value set on `p` by kind; "" or what is wrong with `text` (completing "<path>: ").
std::string setByKind(const FieldRow& row, Preset& p, LightDesc* light, std::optional<std::size_t> element,
                      std::string_view text) {
    const bool triplet = row.kind == FieldKind::Vec3 || row.kind == FieldKind::Color || row.kind == FieldKind::Direction;
    if ((triplet || row.kind == FieldKind::Int2) != element.has_value() || (element && *element > (triplet ? 2u : 1u))) {
        return element ? "has no element " + std::to_string(*element) : "is set one element at a time ([0], [1], ...)";
    }
    switch (row.kind) {
    case FieldKind::Number:
    case FieldKind::Vec3:
    case FieldKind::Color:
    case FieldKind::Direction: {
        std::optional<float> v = number(text);
        if (!v) {
            return "expected a number, got \"" + std::string(text) + "\"";
        }
        if (!limits::contains(*row.range, *v)) {
            return std::string("must be ") + row.range->text + ", got " + shown(*v);
        }
        if (row.kind == FieldKind::Number) {
            fieldValue<float>(row, p, light) = *v;
            return {};
        }
        glm::vec3& value = fieldValue<glm::vec3>(row, p, light);
        glm::vec3 changed = value;
        changed[static_cast<int>(*element)] = *v;
        if (row.kind == FieldKind::Direction && glm::length(changed) < limits::kMinDirectionLength) {
            return "a direction must not be (0, 0, 0)";
        }
        value = changed;
        return {};
    }
    case FieldKind::Int2: {
        std::optional<int> v = integer(text);
        if (!v || !limits::contains(*row.intRange, *v)) {
            return "expected a whole number in [" + std::to_string(row.intRange->min) + ", " +
                   std::to_string(row.intRange->max) + "], got \"" + std::string(text) + "\"";
        }
        fieldValue<glm::ivec2>(row, p, light)[static_cast<int>(*element)] = *v;
        return {};
    }
    case FieldKind::Switch:
        if (text != "true" && text != "false") {
            return "expected true or false, got \"" + std::string(text) + "\"";
        }
        fieldValue<bool>(row, p, light) = text == "true";
        return {};
    case FieldKind::Choice:
        for (const FieldChoice& c : row.choices) {
            if (c.name == text) {
                setChoice(row, p, light, c.value);
                return {};
            }
        }
        return "not one of its choices: \"" + std::string(text) + "\"";
    case FieldKind::Text: fieldValue<std::string>(row, p, light) = std::string(text); return {};
    }
    return "cannot be set";
}

} // namespace

std::string setFieldFromText(Preset& preset, std::string_view path, std::string_view text) {
    const std::string where(path);
    std::optional<std::vector<PathStep>> steps = parseFieldPath(path);
    const FieldRow* row = steps ? fieldRow(path) : nullptr;
    if (!row || (row->custom && row->kind != FieldKind::Choice && row->kind != FieldKind::Int2) ||
        (row->style & kStyleHidden)) {
        return where + ": not a field the page can set";
    }
    LightDesc* light = nullptr;
    if (isLightRow(*row)) {
        std::size_t index = (*steps)[1].index;
        if (index >= preset.lights.size()) {
            return where + ": there is no light " + std::to_string(index) + " (the scene has " +
                   std::to_string(preset.lights.size()) + ")";
        }
        light = &preset.lights[index];
    }
    std::optional<std::size_t> element;
    if (steps->back().isIndex()) {
        element = steps->back().index;
    }
    if (row->custom && !applies(*row, preset, light)) {
        return where + ": does not apply to this model";
    }
    Preset before = preset;
    if (std::string problem = setByKind(*row, preset, light, element, text); !problem.empty()) {
        return where + ": " + problem;
    }
    if (row->rule) {
        std::vector<FieldProblem> problems;
        row->rule(preset, light, problems);
        if (!problems.empty()) {
            preset = std::move(before);
            return where + ": " + problems.front().message;
        }
    }
    // The model's source is read by hand, not by the table (preset_read.cpp): its rules here, as there.
    const Model& m = preset.model;
    if (fieldKey(*row) == "builtin") {
        preset.model.subdivisions = defaultSubdivisions(m.builtin);
    } else if (fieldKey(*row) == "subdivisions" && (m.builtin == Builtin::Sphere || m.builtin == Builtin::Torus) &&
               (!limits::contains(limits::kSubdivisionsRound, m.subdivisions.x) ||
                !limits::contains(limits::kSubdivisionsRound, m.subdivisions.y))) {
        preset = std::move(before);
        return where + ": a sphere or a torus needs at least " + std::to_string(limits::kSubdivisionsRound.min);
    }
    return {};
}

} // namespace lab
