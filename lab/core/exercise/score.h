// score.h — how close an attempt is to an exercise's target, from the renders (exercise.h says what
// is rendered: attemptAsScored, targetAsScored, startAsScored).
//
// Two things, kept apart:
//   - Solved: the exercise's own rule. The attempt's and the target's renders are within the image
//     tolerance (a preset's `check` names) and every field tolerance holds.
//   - The score, a progress measure that means the same read aloud as drawn: 0% at the start, 100%
//     only when solved, and in between rising as the attempt's render approaches the target's:
//         score = clamp(1 − d(attempt) / d(start), 0, 0.99)      (1 when solved)
//     with d(x) the mean absolute difference, in levels per channel, between x's render and the
//     target's over the model's pixels (modelDifference). When the start renders as the target does
//     (d(start) = 0) the picture cannot say how close an attempt is: 0% until solved.
// The GUI's bar, `lab exercise check` and the page's live region all say ExerciseScore::line().
// No GL here: the caller renders.
#pragma once

#include "core/exercise/exercise.h"
#include "core/io/image.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace lab {

// The progress shown while not solved is at most this (99%): 100% is kept for Solved.
inline constexpr double kMaxUnsolvedScore = 0.99;

// The mean absolute difference between two renders of the same size, in levels per channel, over the
// model's pixels: those that are not their image's background colour (within 1 level) in either
// image. 0 when no pixel is the model's; nullopt when the sizes differ.
std::optional<double> modelDifference(const Image& a, const glm::vec3& backgroundA, const Image& b,
                                      const glm::vec3& backgroundB);

// d(start): the start's render (startAsScored) against the target's. Computed once per exercise,
// as the target's render is. nullopt when the sizes differ.
std::optional<double> startDifference(const Exercise& exercise, const Image& startImage, const Image& targetImage);

struct FieldMiss {
    std::string field;
    float difference = 0.0f; // the largest over the field's numbers
    float within = 0.0f;
};

struct ExerciseScore {
    Comparison image;             // attempt against target (image.h): what Solved is decided on
    Tolerance tolerance;          // what it was held to (ExerciseTolerance::image)
    double difference = 0.0;      // d(attempt), levels (modelDifference)
    double startDifference = 0.0; // d(start), levels
    double progress = 0.0;        // 0..1: 1 only when solved, else at most kMaxUnsolvedScore
    std::vector<FieldMiss> misses; // field tolerances not met
    bool solved = false;

    // The score in whole percent, rounded down (never 100 unless solved).
    int percent() const;
    // The score as one line of plain text, for the panel's bar, the command line and a screen
    // reader: "Solved: score 100%" or "Score 42%: not solved yet".
    std::string line() const;
    // What is still too far, "" when solved: "0.5% of the image differs by more than 6 levels (at
    // most 0.2%); material.shininess is 10 away (at most 5)".
    std::string details() const;
    // line() and details(), as `lab exercise check` prints them: "Score 42%: not solved yet; ...".
    std::string summary() const;
};

// Scores the render of attemptAsScored against targetAsScored's (the same size), with d(start) from
// startDifference (nullopt: the start's render failed or differs in size; the score is then 0%
// until solved, as for d(start) = 0).
ExerciseScore scoreExercise(const Exercise& exercise, const Preset& attempt, const Image& attemptImage,
                            const Image& targetImage, std::optional<double> startDifference);

} // namespace lab
