// field_edit.cpp — a field set from text, checked as the reader checks it (field_edit.h).
#include "core/scene/field_edit.h"

#include "core/io/safe_text.h"
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"
#include "core/scene/preset_reader.h"

#include <glm/glm.hpp>

#include <optional>

namespace lab {

namespace {

using preset_detail::Json;

// A number as the page typed it, written as JSON: spaces around it dropped, and the two forms people
// type and the panel's own fields take, ".5" and "5.", as 0.5 and 5. Nothing else changes, so that the
// parser below refuses what a preset file may not hold (hex floats, "inf", '+', text after a NUL).
std::string asJsonNumber(std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
    std::string s(first == std::string_view::npos ? std::string_view{} : text.substr(first, last - first + 1));
    const std::size_t sign = s.starts_with('-') ? 1 : 0;
    if (s.size() > sign + 1 && s[sign] == '.') {
        s.insert(sign, "0");
    }
    const std::size_t dot = s.find('.');
    if (dot != std::string::npos && dot > sign && (dot + 1 == s.size() || s[dot + 1] == 'e' || s[dot + 1] == 'E')) {
        s.insert(dot + 1, "0");
    }
    return s;
}

enum class Parsed { Number, NotANumber, OutOfRange };

// Whether `s` is written as a JSON number: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?. Only to tell,
// when the parser finds a number too large for a double, "1e999" from "7777…x": it throws for the
// number before it reads what follows.
bool jsonNumberSyntax(std::string_view s) {
    std::size_t i = 0;
    auto digits = [&] {
        const std::size_t from = i;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
            ++i;
        }
        return i > from;
    };
    i += s.starts_with('-') ? 1 : 0;
    if (i < s.size() && s[i] == '0') {
        ++i;
    } else if (!digits()) {
        return false;
    }
    if (i < s.size() && s[i] == '.' && (++i, !digits())) {
        return false;
    }
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        i += i < s.size() && (s[i] == '+' || s[i] == '-') ? 1 : 0;
        if (!digits()) {
            return false;
        }
    }
    return i == s.size();
}

// `text` read by the preset reader's own JSON parser (one parser instantiation, as sweep.cpp's).
Parsed parseNumber(std::string_view text, Json& number) {
    if (hasNul(text)) { // nlohmann's parser takes a NUL for the end of its input: "5\0junk" would be 5
        return Parsed::NotANumber;
    }
    const std::string json = asJsonNumber(text);
    try {
        number = Json::parse(std::string_view(json)); // (a string_view, as the reader's: one instantiation)
        return number.is_number() ? Parsed::Number : Parsed::NotANumber;
    } catch (const Json::out_of_range&) { // beyond a double: 1e309
        return jsonNumberSyntax(json) ? Parsed::OutOfRange : Parsed::NotANumber;
    } catch (const Json::exception&) {
        return Parsed::NotANumber;
    }
}

// A number as typed, for a message: itself when short, else quoted and cut (safe_text.h's rule).
std::string typed(std::string_view text) {
    const std::string s = asJsonNumber(text);
    return s.size() <= 120 && printable(s, true) == s ? s : inQuotes(text);
}

constexpr const char* kExpectedNumber = "expected a number such as 0.5, -2 or 1e-3, got ";

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
        Json number;
        const Parsed parsed = parseNumber(text, number);
        if (parsed != Parsed::Number) {
            return parsed == Parsed::OutOfRange ? "number out of range: " + typed(text) : kExpectedNumber + inQuotes(text);
        }
        if (std::string why = preset_detail::numberProblem(number.get<double>(), *row.range, typed(text)); !why.empty()) {
            return why;
        }
        const float v = static_cast<float>(number.get<double>());
        if (row.kind == FieldKind::Number) {
            fieldValue<float>(row, p, light) = v;
            return {};
        }
        glm::vec3& value = fieldValue<glm::vec3>(row, p, light);
        glm::vec3 changed = value;
        changed[static_cast<int>(*element)] = v;
        if (row.kind == FieldKind::Direction && glm::length(changed) < limits::kMinDirectionLength) {
            return "a direction must not be (0, 0, 0)";
        }
        value = changed;
        return {};
    }
    case FieldKind::Int2: {
        Json number;
        const bool whole = parseNumber(text, number) == Parsed::Number && number.is_number_integer() &&
                           number.get<double>() >= row.intRange->min && number.get<double>() <= row.intRange->max;
        if (!whole) {
            return "expected a whole number in [" + std::to_string(row.intRange->min) + ", " +
                   std::to_string(row.intRange->max) + "], got " + inQuotes(text);
        }
        fieldValue<glm::ivec2>(row, p, light)[static_cast<int>(*element)] = number.get<int>();
        return {};
    }
    case FieldKind::Switch:
        if (text != "true" && text != "false") {
            return "expected true or false, got " + inQuotes(text);
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
        return "not one of its choices: " + inQuotes(text);
    case FieldKind::Text: fieldValue<std::string>(row, p, light) = std::string(text); return {};
    }
    return "cannot be set";
}

} // namespace

std::string setFieldFromText(Preset& preset, std::string_view path, std::string_view text) {
    const std::optional<std::vector<PathStep>> steps = parseFieldPath(path); // (a NUL breaks the grammar)
    const std::string where = pathInMessage(path);
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
    // The rules of its object (the camera's ties eye, target and up): one another field names is named.
    std::vector<FieldProblem> problems;
    objectRules(*row, preset, light, problems);
    if (!problems.empty()) {
        preset = std::move(before);
        const FieldProblem& first = problems.front();
        const std::string other = first.key == fieldKey(*row) ? "" : std::string(fieldObject(*row)) + "." + first.key + " ";
        return where + ": " + (other.starts_with("lights[].") ? "" : other) + first.message;
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
