// touch_test.cpp — fingers become the mouse events the lab already understands (app/touch.h):
// a tap is a click at its place, a drag a left drag, two fingers a middle drag plus the wheel,
// and a second finger never leaves a stray click or orbit behind.
#include "app/touch.h"

#include "app/app.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lab {
namespace {

using Kind = InputEvent::Kind;

int count(const std::vector<InputEvent>& events, Kind kind, int code = -1, int down = -1) {
    int n = 0;
    for (const InputEvent& e : events) {
        n += e.kind == kind && (code < 0 || e.code == code) && (down < 0 || e.down == (down == 1));
    }
    return n;
}

TEST(Touch, ATapIsAClickWhereTheFingerTouchedThenTheCursorLeaves) {
    TouchGestures t;
    std::vector<InputEvent> out;
    t.start(7, 100, 200, out);
    EXPECT_TRUE(out.empty()) << "the press waits: a tap or a drag?";
    t.move(7, 103, 202, out); // within the slop
    EXPECT_TRUE(out.empty());
    t.end(7, 103, 202, out);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(out[0].kind, Kind::Move);
    EXPECT_EQ(out[1].kind, Kind::Button);
    EXPECT_TRUE(out[1].down);
    EXPECT_FALSE(out[2].down);
    EXPECT_FLOAT_EQ(out[2].x, 100.0f);
    EXPECT_FLOAT_EQ(out[2].y, 200.0f);
    EXPECT_EQ(out[3].kind, Kind::Leave);
    std::optional<InputEvent> pending;
    EXPECT_EQ(clicksOf(out, pending).size(), 1u);
}

TEST(Touch, ADragPressesWhereItStartedAndFollowsTheFinger) {
    TouchGestures t;
    std::vector<InputEvent> out;
    t.start(1, 100, 100, out);
    t.move(1, 130, 100, out);
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[1].kind, Kind::Button);
    EXPECT_FLOAT_EQ(out[1].x, 100.0f);
    EXPECT_FLOAT_EQ(out[2].x, 130.0f);
    t.move(1, 160, 120, out);
    t.end(1, 160, 120, out);
    EXPECT_EQ(count(out, Kind::Button, 0, 1), 1);
    EXPECT_EQ(count(out, Kind::Button, 0, 0), 1);
    EXPECT_EQ(out.back().kind, Kind::Leave);
    std::optional<InputEvent> pending;
    EXPECT_TRUE(clicksOf(out, pending).empty()) << "a drag is no click";
}

TEST(Touch, ASecondFingerBeforeAnyMoveIsAPinchWithNoClick) {
    TouchGestures t;
    std::vector<InputEvent> out;
    t.start(1, 100, 100, out);
    t.start(2, 200, 100, out);
    EXPECT_EQ(count(out, Kind::Button, 0), 0) << "no left press at all";
    EXPECT_EQ(count(out, Kind::Button, 2, 1), 1) << "the middle button at the midpoint";
    EXPECT_FLOAT_EQ(out.back().x, 150.0f);
    // Spreading the fingers to twice their distance turns the wheel forward (zoom in):
    // 0.9^wheel = 1/2.
    t.move(1, 50, 100, out);
    t.move(2, 250, 100, out);
    float wheel = 0;
    for (const InputEvent& e : out) {
        wheel += e.kind == Kind::Scroll ? e.y : 0.0f;
    }
    EXPECT_NEAR(std::pow(0.9f, wheel), 0.5f, 1e-3f);
    t.end(1, 50, 100, out);
    EXPECT_EQ(count(out, Kind::Button, 2, 0), 1);
    std::size_t before = out.size();
    t.move(2, 300, 300, out); // the remaining finger does nothing until it lifts
    t.end(2, 300, 300, out);
    EXPECT_EQ(out.size(), before);
    std::optional<InputEvent> pending;
    EXPECT_TRUE(clicksOf(out, pending).empty());
}

TEST(Touch, TwoFingersMovingTogetherPanWithoutZooming) {
    TouchGestures t;
    std::vector<InputEvent> out;
    t.start(1, 100, 100, out);
    t.start(2, 200, 100, out);
    t.move(1, 100, 150, out);
    t.move(2, 200, 150, out);
    auto lastMove = std::find_if(out.rbegin(), out.rend(), [](const InputEvent& e) { return e.kind == Kind::Move; });
    ASSERT_NE(lastMove, out.rend());
    EXPECT_FLOAT_EQ(lastMove->y, 150.0f) << "the cursor is the midpoint";
    float wheel = 0;
    for (const InputEvent& e : out) {
        wheel += e.kind == Kind::Scroll ? e.y : 0.0f;
    }
    EXPECT_NEAR(wheel, 0.0f, 0.05f);
}

TEST(Touch, ASecondFingerDuringADragEndsTheDragFirst) {
    TouchGestures t;
    std::vector<InputEvent> out;
    t.start(1, 100, 100, out);
    t.move(1, 140, 100, out);
    t.start(2, 240, 100, out);
    EXPECT_EQ(count(out, Kind::Button, 0, 1), 1);
    EXPECT_EQ(count(out, Kind::Button, 0, 0), 1) << "the left drag is released before the pinch";
    EXPECT_EQ(count(out, Kind::Button, 2, 1), 1);
    std::optional<InputEvent> pending;
    EXPECT_TRUE(clicksOf(out, pending).empty());
}

TEST(Touch, AThirdFingerAndUnknownFingersAreIgnored) {
    TouchGestures t;
    std::vector<InputEvent> out;
    t.move(9, 1, 1, out);
    t.end(9, 1, 1, out);
    EXPECT_TRUE(out.empty());
    t.start(1, 100, 100, out);
    t.start(2, 200, 100, out);
    std::size_t before = out.size();
    t.start(3, 300, 300, out);
    t.move(3, 320, 300, out);
    t.end(3, 320, 300, out);
    EXPECT_EQ(out.size(), before);
    // After every finger has lifted a new tap is a tap again.
    t.end(1, 100, 100, out);
    t.end(2, 200, 100, out);
    out.clear();
    t.start(4, 10, 10, out);
    t.end(4, 10, 10, out);
    std::optional<InputEvent> pending;
    EXPECT_EQ(clicksOf(out, pending).size(), 1u);
}

// A cancelled touch (a system gesture took it) presses nothing that it had not pressed already.
TEST(Touch, ACancelledTouchIsNoClick) {
    TouchGestures t;
    std::vector<InputEvent> out;
    t.start(1, 100, 100, out);
    t.cancel(1, out);
    EXPECT_TRUE(out.empty()) << "a finger that had not moved pressed nothing";
    t.start(2, 100, 100, out);
    t.move(2, 140, 100, out);
    t.cancel(2, out);
    EXPECT_EQ(count(out, Kind::Button, 0, 1), 1);
    EXPECT_EQ(count(out, Kind::Button, 0, 0), 1) << "a drag in progress is released";
    std::optional<InputEvent> pending;
    EXPECT_TRUE(clicksOf(out, pending).empty());
    out.clear();
    t.start(3, 10, 10, out); // and the next tap is a tap
    t.end(3, 10, 10, out);
    EXPECT_EQ(clicksOf(out, pending).size(), 1u);
}

} // namespace
} // namespace lab
