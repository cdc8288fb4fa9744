// exercise.h — an exercise: a start scene, a target scene, the fields a student may change, and
// when the attempt counts as solved. Its JSON file format ("lighting-lab-exercise" v1):
//
//   { "format": "lighting-lab-exercise", "version": 1,
//     "title": "Find the shininess", "instructions": "Make the highlight match the target's.",
//     "start":  { ...a preset object (format and version may be left out; model paths relative
//                 to the exercise file)... },
//     "target": { "material": { "shininess": 80 } },   // only what differs from start, or a whole
//                                                      // preset (with "format")
//     "open": ["material.shininess"],                  // JSON paths of the fields a student may change
//     "tolerance": { "pixel_tolerance": 6, "max_failing": 0.002, "max_mean": 0.5,
//                    "fields": { "material.shininess": 8 } },   // optional
//     "hints": ["A larger n makes the highlight smaller."] }   // optional
//
// `camera`, `plot`, `name`, `description` (and `check`, `sweep`) are always free (preset_fields.h
// alwaysFree). Every problem is reported with its JSON path. Solved: rendered at 256 x 256 with the
// target's camera, the attempt and the target are within the image tolerance (the names of a
// preset's `check` block; the defaults below), and every field tolerance holds.
// The score of an attempt is score.h. No GL here: the caller renders.
#pragma once

#include "core/io/image.h"
#include "core/scene/preset.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

inline constexpr std::string_view kExerciseFormat = kExerciseFile.format; // "lighting-lab-exercise" (core/scene/file_header.h)
inline constexpr int kExerciseVersion = kExerciseFile.version;
inline constexpr std::size_t kMaxExerciseBytes = 1u << 20;
inline constexpr int kExerciseRenderSide = 256; // the attempt and the target are compared at this size
inline constexpr std::size_t kMaxExerciseHints = 16;

// The image tolerance an exercise has unless it says otherwise: looser than `lab check`'s (a
// student drags sliders, and 31.8 for 32 is a match) but tight enough that a visibly different
// highlight is not solved (tests/exercise_test.cpp measures both).
inline constexpr Tolerance kExerciseTolerance{6, 0.002, 0.5};

// |attempt − target| ≤ within for the number, or for each number of the field ("material.diffuse").
struct FieldTolerance {
    std::string field;
    float within = 0.0f;
    bool operator==(const FieldTolerance&) const = default;
};

struct ExerciseTolerance {
    std::optional<int> pixelTolerance; // pixel_tolerance
    std::optional<float> maxFailing;   // max_failing (a share of the pixels)
    std::optional<float> maxMean;      // max_mean (levels)
    std::vector<FieldTolerance> fields;
    Tolerance image() const; // the given values over kExerciseTolerance
    bool empty() const { return !pixelTolerance && !maxFailing && !maxMean && fields.empty(); }
    bool operator==(const ExerciseTolerance&) const = default;
};

struct Exercise {
    std::string title;
    std::string instructions;
    Preset start;
    Preset target;
    std::vector<std::string> open; // JSON paths (preset_fields.h)
    ExerciseTolerance tolerance;
    std::vector<std::string> hints;
    bool operator==(const Exercise&) const = default;
};

struct LoadedExercise {
    Exercise exercise;
    std::filesystem::path file; // empty when parsed from memory (a link)
    std::filesystem::path folder() const { return file.empty() ? std::filesystem::path{} : file.parent_path(); }
};

// Whether JSON text says it is an exercise ("format": "lighting-lab-exercise" at its top), so the
// lab can open exercises wherever it opens presets. Malformed text is not one.
bool isExerciseText(std::string_view text);

// Parses and validates exercise JSON. `folder` is where model paths resolve (nullopt: none may be given).
std::optional<Exercise> parseExercise(std::string_view text, const std::string& displayName,
                                      const std::optional<std::filesystem::path>& folder, Diagnostics& diagnostics);
std::optional<LoadedExercise> loadExercise(const std::filesystem::path& file, Diagnostics& diagnostics);

// The exercise as JSON: `start` with every key, `target` as only what differs from it.
std::string exerciseToJson(const Exercise& exercise);
// Written atomically.
bool saveExercise(const Exercise& exercise, const std::filesystem::path& file, Diagnostics& diagnostics);

// Whether the student may change the field (or every field under) `path`: open, or always free.
bool fieldIsOpen(const Exercise& exercise, std::string_view path);

// The fields `attempt` changed from the exercise's start that it may not change, by JSON path. A
// glTF model is compared by the file it names (`exerciseFolder`, `attemptFolder`), not its spelling.
std::vector<std::string> lockedChanges(const Exercise& exercise, const Preset& attempt,
                                       const std::filesystem::path& exerciseFolder = {},
                                       const std::filesystem::path& attemptFolder = {});

// `attempt` with every field it may not change put back to the start's value (the lab keeps an
// attempt so whatever edited it: a key, a dropped file's values).
Preset withLockedFieldsOfStart(const Exercise& exercise, const Preset& attempt);

// What is rendered to score `attempt`: it, seen through the target's camera; the target; the start,
// seen as an attempt is (its render is d(start)'s, score.h).
Preset attemptAsScored(const Exercise& exercise, const Preset& attempt);
Preset targetAsScored(const Exercise& exercise);
Preset startAsScored(const Exercise& exercise);

} // namespace lab
