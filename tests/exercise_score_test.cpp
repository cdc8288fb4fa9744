// exercise_score_test.cpp — an attempt's score (core/exercise/score.h): Solved by the exercise's own
// rule, and a progress that reads the same aloud as drawn: 0% at the start, 100% only when solved,
// rising as the attempt approaches the target. First from made-up images, then from real renders of
// the shipped 02-shininess with its shininess stepped from the start towards the target.
#include "core/exercise/score.h"

#include "gl_suite.h"
#include "render/offscreen.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace lab {
namespace {

namespace fs = std::filesystem;

using Rgb = std::array<std::uint8_t, 3>;

Image filled(Rgb colour, int side = 16) {
    Image image;
    image.width = side;
    image.height = side;
    for (int i = 0; i < side * side; ++i) {
        image.rgb.insert(image.rgb.end(), colour.begin(), colour.end());
    }
    return image;
}

void setPixel(Image& image, int x, int y, Rgb colour) {
    std::copy(colour.begin(), colour.end(), image.rgb.begin() + (std::ptrdiff_t(y) * image.width + x) * 3);
}

// The shininess from 10 to 60, the background 0.2, 0.4, 0.6: 51, 102, 153 in levels.
Exercise scoredExercise() {
    Exercise e;
    e.title = "Find the shininess";
    e.start.material.shininess = 10.0f;
    e.start.background = {0.2f, 0.4f, 0.6f};
    e.target = e.start;
    e.target.material.shininess = 60.0f;
    e.open = {"material.shininess"};
    return e;
}
constexpr Rgb kBackground{51, 102, 153};
constexpr Rgb kModel{200, 100, 50};

// The right half of a 16 x 16 image is the model (128 pixels) in `model`, the rest background.
Image halfModel(Rgb model) {
    Image image = filled(kBackground);
    for (int y = 0; y < 16; ++y) {
        for (int x = 8; x < 16; ++x) {
            setPixel(image, x, y, model);
        }
    }
    return image;
}

//----------------------------------------------------------------------------------------
// d: the mean difference over the model's pixels
//----------------------------------------------------------------------------------------

TEST(ModelDifference, IsTheMeanChannelDifferenceOverThePixelsEitherImageCovers) {
    const glm::vec3 back{0.2f, 0.4f, 0.6f};
    const Image target = halfModel(kModel);
    // 30 levels off in red on every model pixel: 10 levels a channel, the background not counted.
    EXPECT_DOUBLE_EQ(*modelDifference(halfModel({230, 100, 50}), back, target, back), 10.0);
    EXPECT_DOUBLE_EQ(*modelDifference(target, back, target, back), 0.0);
    // A pixel that is the model in one image only counts: 129 pixels, the new one 3 × 150/3 levels off.
    Image attempt = target;
    setPixel(attempt, 2, 2, {201, 102, 153});
    EXPECT_DOUBLE_EQ(*modelDifference(attempt, back, target, back), 150.0 / 3.0 / 129.0);
    // Nothing but background: no difference to measure.
    EXPECT_DOUBLE_EQ(*modelDifference(filled(kBackground), back, filled(kBackground), back), 0.0);
    EXPECT_FALSE(modelDifference(filled(kModel, 16), back, filled(kModel, 8), back));
}

//----------------------------------------------------------------------------------------
// The score: 0% at the start, 100% only when solved, rising in between
//----------------------------------------------------------------------------------------

TEST(ExerciseScore, TheStartScoresNothingTheTargetEverythingAndHalfWayHalf) {
    Exercise e = scoredExercise();
    const Image target = halfModel(kModel);
    const Image start = halfModel({200, 160, 50}); // 60 levels off in green: d(start) = 20
    const std::optional<double> d0 = startDifference(e, start, target);
    ASSERT_TRUE(d0);
    EXPECT_DOUBLE_EQ(*d0, 20.0);

    ExerciseScore s = scoreExercise(e, e.start, start, target, d0);
    EXPECT_FALSE(s.solved);
    EXPECT_EQ(s.progress, 0.0);
    EXPECT_EQ(s.percent(), 0);
    EXPECT_EQ(s.line(), "Score 0%: not solved yet");

    s = scoreExercise(e, e.start, halfModel({200, 130, 50}), target, d0); // half the way
    EXPECT_FALSE(s.solved);
    EXPECT_DOUBLE_EQ(s.difference, 10.0);
    EXPECT_DOUBLE_EQ(s.progress, 0.5);
    EXPECT_EQ(s.line(), "Score 50%: not solved yet");
    EXPECT_EQ(s.summary().rfind("Score 50%: not solved yet; ", 0), 0u) << s.summary();
    EXPECT_NE(s.details().find("levels"), std::string::npos) << s.details();

    s = scoreExercise(e, e.target, target, target, d0);
    EXPECT_TRUE(s.solved);
    EXPECT_EQ(s.progress, 1.0);
    EXPECT_EQ(s.percent(), 100);
    EXPECT_EQ(s.line(), "Solved: score 100%");
    EXPECT_EQ(s.details(), "");
    EXPECT_EQ(s.summary(), "Solved: score 100%");

    // Further from the target than the start was: 0%, not below.
    s = scoreExercise(e, e.start, halfModel({200, 250, 50}), target, d0);
    EXPECT_EQ(s.progress, 0.0);
    EXPECT_EQ(s.line(), "Score 0%: not solved yet");
}

TEST(ExerciseScore, RisesAsTheAttemptApproachesTheTarget) {
    Exercise e = scoredExercise();
    const Image target = halfModel(kModel);
    const std::optional<double> d0 = startDifference(e, halfModel({200, 200, 50}), target);
    double last = -1.0;
    for (int green = 200; green >= 100; green -= 4) {
        ExerciseScore s = scoreExercise(e, e.start, halfModel({200, std::uint8_t(green), 50}), target, d0);
        EXPECT_GT(s.progress, last) << "green " << green;
        EXPECT_EQ(s.progress == 1.0, s.solved) << "green " << green;
        last = s.progress;
    }
    EXPECT_EQ(last, 1.0);
}

TEST(ExerciseScore, IsNever100PercentUnlessSolved) {
    Exercise e = scoredExercise();
    e.tolerance.maxFailing = 0.0f;
    const Image target = halfModel(kModel);
    const std::optional<double> d0 = startDifference(e, halfModel({200, 200, 50}), target);
    // One pixel off: 1/128 of the way left, but not solved: 99%, not 100%.
    Image attempt = target;
    setPixel(attempt, 12, 5, {250, 100, 50});
    ExerciseScore s = scoreExercise(e, e.start, attempt, target, d0);
    EXPECT_FALSE(s.solved);
    EXPECT_DOUBLE_EQ(s.progress, kMaxUnsolvedScore);
    EXPECT_EQ(s.percent(), 99);
    EXPECT_EQ(s.line(), "Score 99%: not solved yet");
    // The same images, but a field tolerance missed: the picture is the target's, the score is not 100%.
    e.tolerance.fields = {{"material.shininess", 5.0f}};
    Preset attemptPreset = e.target;
    attemptPreset.material.shininess = 70.0f;
    s = scoreExercise(e, attemptPreset, target, target, d0);
    EXPECT_FALSE(s.solved);
    EXPECT_EQ(s.difference, 0.0);
    EXPECT_EQ(s.percent(), 99);
    EXPECT_NE(s.details().find("material.shininess is 10 away (at most 5)"), std::string::npos) << s.details();
}

// An exercise whose start looks like its target (a field the picture cannot show): the picture
// cannot say how close an attempt is, so 0% until solved, never a division by zero.
TEST(ExerciseScore, AStartThatLooksLikeTheTargetScoresNothingUntilSolved) {
    Exercise e = scoredExercise();
    e.tolerance.fields = {{"material.shininess", 5.0f}};
    const Image image = halfModel(kModel);
    const std::optional<double> d0 = startDifference(e, image, image);
    ASSERT_TRUE(d0);
    EXPECT_EQ(*d0, 0.0);
    ExerciseScore s = scoreExercise(e, e.start, image, image, d0);
    EXPECT_FALSE(s.solved);
    EXPECT_EQ(s.progress, 0.0);
    EXPECT_EQ(s.line(), "Score 0%: not solved yet");
    s = scoreExercise(e, e.start, halfModel({200, 130, 50}), image, d0); // a different picture
    EXPECT_EQ(s.progress, 0.0);
    s = scoreExercise(e, e.target, image, image, d0);
    EXPECT_TRUE(s.solved);
    EXPECT_EQ(s.line(), "Solved: score 100%");
    // No start render at all (it failed): the same.
    s = scoreExercise(e, e.start, halfModel({200, 130, 50}), image, std::nullopt);
    EXPECT_EQ(s.progress, 0.0);
    EXPECT_FALSE(s.solved);
}

//----------------------------------------------------------------------------------------
// Solved: the exercise's own rule, unchanged
//----------------------------------------------------------------------------------------

TEST(ExerciseScore, SolvedIsTheExercisesImageTolerance) {
    Exercise e = scoredExercise();
    e.tolerance.maxFailing = 0.0f;
    const Image target = filled(kModel);
    Image attempt = target;
    setPixel(attempt, 3, 4, {250, 100, 50}); // 50 levels off in red
    ExerciseScore s = scoreExercise(e, e.target, attempt, target, 20.0);
    EXPECT_FALSE(s.solved);
    EXPECT_EQ(s.image.failingPixels, 1u);
    EXPECT_EQ(s.image.maxDifference, 50);
    EXPECT_NE(s.details().find("differs by more than 6 levels"), std::string::npos) << s.details();
    e.tolerance.pixelTolerance = 50; // the same pixel within the exercise's pixel tolerance passes
    s = scoreExercise(e, e.target, attempt, target, 20.0);
    EXPECT_TRUE(s.solved) << s.summary();
    // The default pixel tolerance is 6 levels.
    e = scoredExercise();
    e.tolerance.maxFailing = 0.0f;
    attempt = target;
    setPixel(attempt, 0, 0, {206, 100, 50});
    EXPECT_TRUE(scoreExercise(e, e.target, attempt, target, 20.0).solved);
    setPixel(attempt, 0, 0, {207, 100, 50});
    EXPECT_FALSE(scoreExercise(e, e.target, attempt, target, 20.0).solved);
}

TEST(ExerciseScore, AFieldToleranceMissBlocksSolvedEvenWithIdenticalImages) {
    Exercise e = scoredExercise();
    e.tolerance.fields = {{"material.shininess", 5.0f}};
    const Image image = filled(kModel);
    Preset attempt = e.target;
    attempt.material.shininess = 70.0f;
    ExerciseScore s = scoreExercise(e, attempt, image, image, 20.0);
    EXPECT_FALSE(s.solved);
    ASSERT_EQ(s.misses.size(), 1u);
    EXPECT_EQ(s.misses[0].field, "material.shininess");
    EXPECT_EQ(s.misses[0].difference, 10.0f);
    EXPECT_EQ(s.misses[0].within, 5.0f);
    attempt.material.shininess = 64.0f; // within 5
    s = scoreExercise(e, attempt, image, image, 20.0);
    EXPECT_TRUE(s.solved) << s.summary();
    // A field of several numbers: the largest difference counts.
    e.open = {"material.shininess", "material.diffuse"};
    e.tolerance.fields = {{"material.diffuse", 0.1f}};
    attempt = e.target;
    attempt.material.diffuse = e.target.material.diffuse + glm::vec3(0.0f, 0.25f, 0.05f);
    s = scoreExercise(e, attempt, image, image, 20.0);
    ASSERT_EQ(s.misses.size(), 1u);
    EXPECT_NEAR(s.misses[0].difference, 0.25f, 1e-6f);
    EXPECT_FALSE(s.solved);
}

TEST(ExerciseScore, ImagesOfDifferentSizesAreNotSolvedAndScoreNothing) {
    const Exercise e = scoredExercise();
    ExerciseScore s = scoreExercise(e, e.target, filled(kModel, 16), filled(kModel, 8), 20.0);
    EXPECT_FALSE(s.image.sameSize);
    EXPECT_FALSE(s.solved);
    EXPECT_EQ(s.progress, 0.0);
    EXPECT_EQ(s.summary(), "Score 0%: not solved yet; the renders differ in size");
}

//----------------------------------------------------------------------------------------
// Real renders: the shipped 02-shininess, its shininess stepped from the start (8) to the target (80)
//----------------------------------------------------------------------------------------

class ExerciseScoreRendered : public GlSuite<testing::Test, OffscreenRenderer> {
protected:
    static Image render(const Preset& preset) {
        Diagnostics d;
        std::optional<Image> image =
            renderer_->render(LoadedPreset{preset, {}}, kExerciseRenderSide, kExerciseRenderSide, d);
        EXPECT_TRUE(image) << toString(d);
        return image ? *image : Image{};
    }
};

TEST_F(ExerciseScoreRendered, TheShininessExerciseRisesFromZeroAtTheStartToSolvedAtTheTarget) {
    ASSERT_NE(renderer_, nullptr);
    Diagnostics d;
    std::optional<LoadedExercise> loaded = loadExercise(fs::path(LAB_SOURCE_DIR) / "presets/exercises/02-shininess.json", d);
    ASSERT_TRUE(loaded) << toString(d);
    const Exercise& e = loaded->exercise;
    ASSERT_EQ(e.start.material.shininess, 8.0f);
    ASSERT_EQ(e.target.material.shininess, 80.0f);
    const Image target = render(targetAsScored(e));
    const std::optional<double> d0 = startDifference(e, render(startAsScored(e)), target);
    ASSERT_TRUE(d0);
    EXPECT_GT(*d0, 1.0) << "the start's highlight is visibly larger than the target's";

    std::vector<int> percents;
    double last = -1.0;
    for (float n : {8.0f, 12.0f, 16.0f, 20.0f, 25.0f, 30.0f, 40.0f, 50.0f, 60.0f, 70.0f, 80.0f}) {
        Preset attempt = e.start;
        attempt.material.shininess = n;
        ExerciseScore s = scoreExercise(e, attempt, render(attemptAsScored(e, attempt)), target, d0);
        EXPECT_GE(s.progress, last) << "n = " << n << ": " << s.summary();
        EXPECT_EQ(s.percent() == 100, s.solved) << "n = " << n;
        last = s.progress;
        percents.push_back(s.percent());
        RecordProperty("n" + std::to_string(int(n)), s.line());
    }
    EXPECT_EQ(percents.front(), 0) << "the start scores 0%";
    EXPECT_EQ(percents.back(), 100) << "the target solves it";
    EXPECT_GT(percents[5], 20) << "n = 30 is well on the way";
    EXPECT_LT(percents[5], 100);
    EXPECT_LT(percents[7], 100) << "n = 50 is not solved (the CLI tests' near miss)";
}

} // namespace
} // namespace lab
