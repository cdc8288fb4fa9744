// file_header.h — the "format" and "version" every file of the lab starts with, checked once.
//
// Presets ("lighting-lab-preset"), exercises ("lighting-lab-exercise") and decks ("lighting-lab-deck") open with the same two
// keys. A file that is not what was asked for gets one clear message, not fifty: the format
// missing or wrong (with a hint when it is the lab's other kind of file), the version missing,
// not an integer, newer than this program reads, or below 1.
//
// This file owns the two formats and their check. It does not read the rest of a file.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace lab {

struct FileFormat {
    std::string_view format; // "lighting-lab-preset"
    int version;             // the newest this program reads
    std::string_view what;   // "a preset", for the hint
};

inline constexpr FileFormat kPresetFile{"lighting-lab-preset", 1, "a preset"};
inline constexpr FileFormat kExerciseFile{"lighting-lab-exercise", 1, "an exercise"};
inline constexpr FileFormat kDeckFile{"lighting-lab-deck", 1, "a deck"};

// What is wrong with `object`'s "format" and "version" for a file of `expected`: the key and the
// message; nullopt when both are right.
struct HeaderProblem {
    std::string key;
    std::string message;
};
std::optional<HeaderProblem> fileHeaderProblem(const nlohmann::ordered_json& object, const FileFormat& expected);

} // namespace lab
