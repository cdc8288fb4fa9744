// score.cpp — the score of an attempt: Solved by the exercise's rule, and the progress towards the target.
#include "core/exercise/score.h"

#include "core/exercise/preset_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <glm/common.hpp>

namespace lab {

namespace {

// A background colour in levels, as the renderer clears to it.
glm::ivec3 levels(const glm::vec3& colour) {
    return glm::ivec3(glm::round(glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f)) * 255.0f));
}

// The field tolerances `attempt` does not meet.
std::vector<FieldMiss> fieldMisses(const Exercise& exercise, const Preset& attempt) {
    std::vector<FieldMiss> misses;
    PresetJson tried = presetValue(attempt), target = presetValue(exercise.target);
    for (const FieldTolerance& f : exercise.tolerance.fields) {
        const PresetJson* a = fieldAt(tried, f.field);
        const PresetJson* t = fieldAt(target, f.field);
        float worst = 0.0f;
        if (!a || !t || a->is_number() != t->is_number() || (a->is_array() && a->size() != t->size())) {
            worst = INFINITY;
        } else if (a->is_number()) {
            worst = std::abs(a->get<float>() - t->get<float>());
        } else {
            for (std::size_t i = 0; i < a->size(); ++i) {
                worst = std::max(worst, std::abs((*a)[i].get<float>() - (*t)[i].get<float>()));
            }
        }
        // Within float rounding of the edge counts (0.95 against 1 within 0.05 is 0.0500001 in float).
        if (!(worst <= f.within + 1e-5f * std::max(1.0f, f.within))) {
            misses.push_back({f.field, worst, f.within});
        }
    }
    return misses;
}

} // namespace

std::optional<double> modelDifference(const Image& a, const glm::vec3& backgroundA, const Image& b,
                                      const glm::vec3& backgroundB) {
    if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size()) {
        return std::nullopt;
    }
    const glm::ivec3 ba = levels(backgroundA), bb = levels(backgroundB);
    std::uint64_t sum = 0;
    std::size_t model = 0;
    for (std::size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
        bool aBack = true, bBack = true;
        int d = 0;
        for (int c = 0; c < 3; ++c) {
            aBack = aBack && std::abs(int(a.rgb[i + c]) - ba[c]) <= 1;
            bBack = bBack && std::abs(int(b.rgb[i + c]) - bb[c]) <= 1;
            d += std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c]));
        }
        if (!(aBack && bBack)) {
            ++model;
            sum += std::uint64_t(d);
        }
    }
    return model == 0 ? 0.0 : double(sum) / (3.0 * double(model));
}

std::optional<double> startDifference(const Exercise& exercise, const Image& startImage, const Image& targetImage) {
    return modelDifference(startImage, exercise.start.background, targetImage, exercise.target.background);
}

int ExerciseScore::percent() const {
    return solved ? 100 : std::clamp(static_cast<int>(std::floor(progress * 100.0 + 1e-9)), 0, 99);
}

std::string ExerciseScore::line() const {
    return solved ? std::string("Solved: score 100%")
                  : "Score " + std::to_string(percent()) + "%: not solved yet";
}

std::string ExerciseScore::details() const {
    if (solved) {
        return {};
    }
    if (!image.sameSize) {
        return "the renders differ in size";
    }
    std::string s;
    auto add = [&s](const char* text) { s += (s.empty() ? "" : "; ") + std::string(text); };
    char text[256];
    if (image.failingShare > tolerance.maxFailingShare) {
        std::snprintf(text, sizeof text, "%.1f%% of the image differs by more than %d levels (at most %.1f%%)",
                      image.failingShare * 100.0, tolerance.pixelTolerance, tolerance.maxFailingShare * 100.0);
        add(text);
    }
    if (image.meanDifference > tolerance.maxMeanDifference) {
        std::snprintf(text, sizeof text, "the mean difference is %.2f levels (at most %.2f)", image.meanDifference,
                      tolerance.maxMeanDifference);
        add(text);
    }
    for (const FieldMiss& m : misses) {
        std::snprintf(text, sizeof text, "%s is %.3g away (at most %.3g)", m.field.c_str(), double(m.difference),
                      double(m.within));
        add(text);
    }
    return s;
}

std::string ExerciseScore::summary() const {
    std::string more = details();
    return more.empty() ? line() : line() + "; " + more;
}

ExerciseScore scoreExercise(const Exercise& exercise, const Preset& attempt, const Image& attemptImage,
                            const Image& targetImage, std::optional<double> startDifference) {
    ExerciseScore score;
    score.tolerance = exercise.tolerance.image();
    score.image = compareImages(attemptImage, targetImage, score.tolerance);
    score.misses = fieldMisses(exercise, attempt);
    score.solved = score.image.passes(score.tolerance) && score.misses.empty();
    std::optional<double> d = modelDifference(attemptImage, attempt.background, targetImage, exercise.target.background);
    score.difference = d.value_or(0.0);
    score.startDifference = startDifference.value_or(0.0);
    if (score.solved) {
        score.progress = 1.0;
    } else if (d && score.startDifference > 0.0) {
        score.progress = std::clamp(1.0 - *d / score.startDifference, 0.0, kMaxUnsolvedScore);
    } // else the picture cannot tell how close the attempt is: 0 until solved
    return score;
}

} // namespace lab
