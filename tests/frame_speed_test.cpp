// frame_speed_test.cpp — the view's frame time: the median of an interaction's frames, shown
// while it goes on and for a while after, nothing before or long after.
#include "app/frame_speed.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

TEST(FrameSpeed, NothingIsShownBeforeTheFirstInteraction) {
    FrameSpeed s;
    EXPECT_FALSE(s.shownMs(0.0));
    EXPECT_FALSE(s.shownMs(100.0));
    EXPECT_LT(s.hidesIn(100.0), 0.0f);
}

TEST(FrameSpeed, TheMedianOfTheInteractionsFramesNotTheLastOne) {
    FrameSpeed s;
    const float costs[] = {0.020f, 0.010f, 0.250f, 0.012f, 0.011f}; // one slow frame among them
    double t = 10.0;
    for (float c : costs) {
        s.interactionFrame(t, c);
        t += 0.016;
    }
    ASSERT_TRUE(s.shownMs(t));
    EXPECT_FLOAT_EQ(*s.shownMs(t), 12.0f);
    s.interactionFrame(t, 0.030f); // six frames: the mean of the middle two, 12 and 20
    EXPECT_FLOAT_EQ(*s.shownMs(t), 16.0f);
}

TEST(FrameSpeed, ShownForAFewSecondsAfterTheInteractionThenNothing) {
    FrameSpeed s;
    s.interactionFrame(5.0, 0.040f);
    EXPECT_FLOAT_EQ(*s.shownMs(5.0 + FrameSpeed::kLingerSeconds - 0.1), 40.0f);
    EXPECT_NEAR(s.hidesIn(6.0), static_cast<float>(FrameSpeed::kLingerSeconds - 1.0), 1e-5f);
    EXPECT_FALSE(s.shownMs(5.0 + FrameSpeed::kLingerSeconds + 0.1));
    EXPECT_LT(s.hidesIn(5.0 + FrameSpeed::kLingerSeconds + 0.1), 0.0f);
}

TEST(FrameSpeed, APauseStartsANewInteraction) {
    FrameSpeed s;
    for (int i = 0; i < 10; ++i) {
        s.interactionFrame(1.0 + 0.02 * i, 0.100f); // a slow drag
    }
    s.interactionFrame(1.2 + FrameSpeed::kGapSeconds + 0.1, 0.005f); // later, a fast one
    EXPECT_FLOAT_EQ(*s.shownMs(2.0), 5.0f);
}

TEST(FrameSpeed, ALongInteractionKeepsItsLatestFrames) {
    FrameSpeed s;
    double t = 0.0;
    for (std::size_t i = 0; i < FrameSpeed::kMaxSamples; ++i, t += 0.01) {
        s.interactionFrame(t, 0.200f);
    }
    for (std::size_t i = 0; i < FrameSpeed::kMaxSamples; ++i, t += 0.01) {
        s.interactionFrame(t, 0.010f);
    }
    EXPECT_FLOAT_EQ(*s.shownMs(t), 10.0f);
}

} // namespace
} // namespace lab
