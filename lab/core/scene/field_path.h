// field_path.h — the grammar of a path to a preset field, read by one parser.
//
// A path names a value in a preset's JSON as a preset file writes it: names joined by '.', each
// optionally followed by indices in brackets: `material.shininess`, `lights[1].attenuation[2]`,
// `cook_torrance`. A name is [a-z0-9_]+ (a preset's keys); an index is 1 to 3 decimal digits,
// leading zeros allowed (`lights[00]` is `lights[0]`, as the README says). Sweep keys
// (core/scene/sweep.h), an exercise's open fields and tolerances (core/exercise/preset_fields.h)
// and the field table (core/scene/field_table.h) all use it.
//
// This file owns the grammar, the canonical spelling and "covers". It does not know which paths
// a preset has (field_table.h does) or walk any JSON.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

// One step of a path: an object's member (`name`), or an array's element (`name` empty).
struct PathStep {
    std::string name;
    std::size_t index = 0;
    bool isIndex() const { return name.empty(); }
    bool operator==(const PathStep&) const = default;
};

// The steps of `path`, or nullopt when it breaks the grammar.
std::optional<std::vector<PathStep>> parseFieldPath(std::string_view path);

// `path` spelt one way (`lights[00]` is `lights[0]`); a path that breaks the grammar is returned
// as it is.
std::string canonicalPath(std::string_view path);

// `path` as a message names it: itself when it is a path of the grammar of at most 120 bytes, else
// quoted and cut as any typed value is (core/io/safe_text.h inQuotes: a megabyte, a NUL, escapes).
std::string pathInMessage(std::string_view path);

// True when `path` is `prefix` or lies below it ("lights[0]" covers "lights[0].attenuation",
// "material" covers "material.diffuse"; "material.diffuse" does not cover "material.diffuse_x").
// Both as spelt: canonicalPath them first where they come from a user.
bool covers(std::string_view prefix, std::string_view path);

// True when one of `a` and `b` covers the other.
inline bool overlaps(std::string_view a, std::string_view b) { return covers(a, b) || covers(b, a); }

} // namespace lab
