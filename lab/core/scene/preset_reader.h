// preset_reader.h — the preset reader's cursor (preset_read.cpp): one JSON object, the JSON path
// it was found at, and the keys consumed. Each read checks a value's type and range and reports a
// problem with its path instead of stopping; finish() reports every key left unconsumed as unknown,
// with the closest known key as a suggestion.
#pragma once

#include "core/io/diagnostics.h"
#include "core/io/json_text.h"
#include "core/io/safe_text.h"
#include "core/io/suggest.h"
#include "core/scene/limits.h"
#include "core/scene/field_table.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <span>
#include <string>
#include <string_view>

namespace lab::preset_detail {

using Json = nlohmann::ordered_json;

// The JSON object `text` holds, as `file`'s, or nullopt after one diagnostic: nested deeper than
// `maxDepth` or holding a NUL (jsonTextProblem), not JSON (with its line and column), a number
// beyond a double ("number out of range: 1e999"), or not an object ("<kind> is a JSON object, got
// an array of 2"; `kind` is "a preset", "an exercise", "a deck"). The one way every file of the
// lab's own formats becomes JSON (preset_read.cpp).
std::optional<Json> parseJsonObject(std::string_view text, const std::string& file, int maxDepth, std::string_view kind,
                                    Diagnostics& diagnostics);

// What is wrong with `value`, read as `written`, for a float field within `range`; "" when nothing
// is. The preset reader's check, which the page's field edits make too (field_edit.cpp), so that
// both say the same of the same number: "number out of range: 1e39" (finite as a double, not as
// a float), "must be in [0.001, 1000000], got 1000001".
inline std::string numberProblem(double value, const limits::Range& range, const std::string& written) {
    const float f = static_cast<float>(value);
    if (!std::isfinite(value) || !std::isfinite(f)) {
        return "number out of range: " + written;
    }
    if (!limits::contains(range, f)) {
        return std::string("must be ") + range.text + ", got " + written;
    }
    return {};
}
using Keys = std::span<const std::string_view>;

class Reader {
public:
    Reader(const Json& object, std::string path, const std::string& file, Diagnostics& out)
        : object_(object), path_(std::move(path)), file_(file), out_(out) {}

    // A Reader for `object`, found at `path`, reporting to the same place.
    Reader child(const Json& object, std::string path) const { return Reader(object, std::move(path), file_, out_); }

    // Reports the keys not in `known`, with the closest known one as a suggestion. A key that is
    // not a plain name (control characters, a NUL, great length) is quoted in the path.
    void finish(Keys known) {
        for (const auto& [key, value] : object_.items()) {
            if (!consumed_.contains(key)) {
                error(keyInPath(key),
                      "unknown key" + std::string(hasNul(key) ? " (it holds a NUL byte)" : "") + suggestion(key, known));
            }
        }
    }

    std::string pathOf(std::string_view key) const {
        return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
    }
    std::string elementPath(std::string_view key, std::size_t i) const {
        return pathOf(key) + "[" + std::to_string(i) + "]";
    }

    std::size_t problems() const { return out_.size(); }
    const std::string& path() const { return path_; }

    void errorAt(std::string where, std::string message) {
        out_.push_back({file_, std::move(where), std::move(message)});
    }
    void error(std::string_view key, std::string message) { errorAt(pathOf(key), std::move(message)); }

    // The value under `key`, or nullptr when absent. Marks the key as known.
    const Json* find(std::string_view key) {
        consumed_.insert(std::string(key));
        auto it = object_.find(key);
        return it == object_.end() ? nullptr : &*it;
    }

    bool has(std::string_view key) const { return object_.contains(key); }

    // Reads the object under `key` with `read(Reader&)`, then reports its keys not in `known`.
    // Nothing happens when the key is absent; anything but an object is reported.
    template <typename Read>
    void readObject(std::string_view key, Keys known, Read read) {
        readObject(key, [&](Reader& r) {
            read(r);
            r.finish(known);
        });
    }

    // Reads the object under `key` with `read(Reader&)`, which reports its unknown keys itself.
    template <typename Read>
    void readObject(std::string_view key, Read read) {
        const Json* v = find(key);
        if (v && !v->is_object()) {
            error(key, "expected an object, got " + describe(*v));
        } else if (v) {
            Reader r = child(*v, pathOf(key));
            read(r);
        }
    }

    // A finite number within `range`.
    void readNumber(std::string_view key, float& dst, const limits::Range& range = limits::kFinite) {
        if (const Json* v = find(key)) {
            readNumberAt(*v, pathOf(key), dst, range);
        }
    }

    // Three finite numbers, each within `range`.
    void readVec3(std::string_view key, glm::vec3& dst, const limits::Range& range = limits::kFinite) {
        if (const Json* v = array(key, 3, "numbers")) {
            for (std::size_t i = 0; i < 3; ++i) {
                readNumberAt((*v)[i], elementPath(key, i), dst[static_cast<int>(i)], range);
            }
        }
    }

    // A direction (normalized where it is used): readVec3, then at least kMinDirectionLength long.
    void readDirection(std::string_view key, glm::vec3& dst) {
        readVec3(key, dst, limits::kCoordinate);
        if (glm::length(dst) < limits::kMinDirectionLength) {
            error(key, "must be at least 0.001 long (it is normalized)");
        }
    }

    // Two integers, each within `range`.
    void readInt2(std::string_view key, glm::ivec2& dst, const limits::IntRange& range) {
        if (const Json* v = array(key, 2, "integers")) {
            for (std::size_t i = 0; i < 2; ++i) {
                readIntAt((*v)[i], elementPath(key, i), dst[static_cast<int>(i)], range);
            }
        }
    }

    // An integer within `range`.
    void readInt(std::string_view key, int& dst, const limits::IntRange& range) {
        if (const Json* v = find(key)) {
            readIntAt(*v, pathOf(key), dst, range);
        }
    }

    void readBool(std::string_view key, bool& dst) { readScalar(key, dst, &Json::is_boolean, "true or false"); }
    void readString(std::string_view key, std::string& dst) { readScalar(key, dst, &Json::is_string, "a string"); }

    // One of `choices`, by name (core/scene/field_table.h): its value into `dst`.
    void readChoice(std::string_view key, int& dst, std::span<const FieldChoice> choices) {
        const Json* v = find(key);
        if (!v) {
            return;
        }
        std::string names;
        std::vector<std::string_view> list;
        for (const FieldChoice& c : choices) {
            names += (names.empty() ? "" : ", ") + inQuotes(c.name);
            list.push_back(c.name);
            if (v->is_string() && v->get<std::string>() == c.name) {
                dst = c.value;
                return;
            }
        }
        std::string got = v->is_string() ? inQuotes(v->get<std::string>()) : describe(*v);
        error(key, "expected one of " + names + ", got " + got + (v->is_string() ? suggestion(v->get<std::string>(), list) : ""));
    }

    static std::string describe(const Json& v) {
        switch (v.type()) {
        case Json::value_t::null:
            return "null";
        case Json::value_t::boolean:
            return v.get<bool>() ? "true" : "false";
        case Json::value_t::string:
            return "a string";
        case Json::value_t::array:
            return "an array of " + std::to_string(v.size());
        case Json::value_t::object:
            return "an object";
        default:
            return v.dump();
        }
    }

private:
    // The array under `key` when it has exactly `n` elements; otherwise reports it and returns null.
    const Json* array(std::string_view key, std::size_t n, const char* elements) {
        const Json* v = find(key);
        if (v && (!v->is_array() || v->size() != n)) {
            error(key, "expected an array of " + std::to_string(n) + " " + elements + ", got " + describe(*v));
            return nullptr;
        }
        return v;
    }

    // A bool or a string: `is` says whether the value has the type, `expected` names it.
    template <typename T>
    void readScalar(std::string_view key, T& dst, bool (Json::*is)() const noexcept, const char* expected) {
        if (const Json* v = find(key)) {
            if ((v->*is)()) {
                dst = v->get<T>();
            } else {
                error(key, std::string("expected ") + expected + ", got " + describe(*v));
            }
        }
    }

    void readNumberAt(const Json& v, std::string where, float& dst, const limits::Range& range) {
        if (!v.is_number()) {
            errorAt(std::move(where), "expected a number, got " + describe(v));
            return;
        }
        const double d = v.get<double>();
        if (std::string why = numberProblem(d, range, v.dump()); !why.empty()) {
            errorAt(std::move(where), std::move(why));
        } else {
            dst = static_cast<float>(d);
        }
    }

    void readIntAt(const Json& v, std::string where, int& dst, const limits::IntRange& range) {
        if (!v.is_number_integer() && !v.is_number_unsigned()) {
            errorAt(std::move(where), "expected an integer, got " + describe(v));
        } else if (v.get<double>() < range.min || v.get<double>() > range.max) {
            errorAt(std::move(where), "must be from " + std::to_string(range.min) + " to " + std::to_string(range.max) +
                                          ", got " + v.dump());
        } else {
            dst = v.get<int>();
        }
    }

    const Json& object_;
    std::string path_;
    const std::string& file_;
    Diagnostics& out_;
    std::set<std::string, std::less<>> consumed_;
};

// A preset's `display` object under `parent` (preset_read.cpp), read by a deck's slide the same way.
void readDisplay(Reader& parent, OpeningDisplay& display);

} // namespace lab::preset_detail
