// input_test.cpp — input handed to frames without losing any, frames drawn only when due, and
// the 3D view's resolution while dragging (app/input.h, app/frame_pacer.h, app/viewport_cache.h).
#include "app/app.h"
#include "app/frame_pacer.h"
#include "app/input.h"
#include "app/viewport_cache.h"
#include "ui/actions.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

using Kind = InputEvent::Kind;

std::vector<std::vector<InputEvent>> frames(InputQueue& q) {
    std::vector<std::vector<InputEvent>> all;
    while (!q.empty()) {
        all.push_back(q.takeFrame());
        if (all.back().empty()) {
            q.takeDropped();
        }
    }
    return all;
}

TEST(Input, AClickShorterThanAFrameIsSeenDownThenUpAtItsOwnPlace) {
    InputQueue q;
    q.push(InputEvent::move(10, 10));
    q.push(InputEvent::move(50, 60));
    q.push(InputEvent::button(0, true, 50, 60));
    q.push(InputEvent::button(0, false, 50, 60));
    auto f = frames(q);
    ASSERT_EQ(f.size(), 3u) << "the move, the press and the release each need a frame of their own";
    ASSERT_EQ(f[0].size(), 1u) << "consecutive moves merge into where the cursor ended up";
    EXPECT_EQ(f[0][0].x, 50);
    EXPECT_TRUE(f[1][0].kind == Kind::Button && f[1][0].down);
    EXPECT_TRUE(f[2][0].kind == Kind::Button && !f[2][0].down);
}

TEST(Input, TwoClicksInOneFrameStayTwoClicks) {
    InputQueue q;
    for (int i = 0; i < 2; ++i) {
        q.push(InputEvent::button(0, true, 5, 5));
        q.push(InputEvent::button(0, false, 5, 5));
    }
    std::optional<InputEvent> pending;
    int clicks = 0;
    for (const auto& frame : frames(q)) {
        clicks += static_cast<int>(clicksOf(frame, pending).size());
    }
    EXPECT_EQ(clicks, 2);
}

TEST(Input, AKeyTappedWithinAFrameIsDownForAFrame) {
    InputQueue q;
    q.push(InputEvent::key(keys::Tab, true));
    q.push(InputEvent::key(keys::Tab, false));
    auto f = frames(q);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_TRUE(f[0][0].down);
    EXPECT_FALSE(f[1][0].down);
}

TEST(Input, TextAndEditingKeysKeepTheirOrder) {
    // "ab", Backspace, "c": Backspace must not be applied before "ab" nor after "c".
    InputQueue q;
    q.push(InputEvent::key('A', true));
    q.push(InputEvent::character('a'));
    q.push(InputEvent::key('A', false));
    q.push(InputEvent::key('B', true));
    q.push(InputEvent::character('b'));
    q.push(InputEvent::key('B', false));
    q.push(InputEvent::key(259, true)); // GLFW_KEY_BACKSPACE
    q.push(InputEvent::key(259, false));
    q.push(InputEvent::character('c'));
    std::string order;
    for (const auto& frame : frames(q)) {
        for (const InputEvent& e : frame) {
            if (e.kind == Kind::Char) {
                order += static_cast<char>(e.code);
            } else if (e.kind == Kind::Key && e.code == 259 && e.down) {
                order += "<";
            }
        }
        order += "|";
    }
    std::string flat;
    for (char c : order) {
        if (c != '|') {
            flat += c;
        }
    }
    EXPECT_EQ(flat, "ab<c");
    // And no frame holds text on both sides of the Backspace.
    EXPECT_EQ(order.find("<c"), std::string::npos) << order;
    EXPECT_EQ(order.find("b<"), std::string::npos) << order;
}

TEST(Input, EveryEventIsHandedOutExactlyOnce) {
    InputQueue q;
    int pushed = 0;
    for (int i = 0; i < 50; ++i) {
        q.push(InputEvent::button(i % 3, i % 2 == 0, 1, 1));
        q.push(InputEvent::key(65 + i % 5, i % 2 == 0, kShift, false));
        q.push(InputEvent::character(97 + i % 26));
        q.push(InputEvent::scroll(0, 1));
        pushed += 4;
    }
    q.drop("a.json");
    int taken = 0;
    for (const auto& frame : frames(q)) {
        taken += static_cast<int>(frame.size());
    }
    EXPECT_EQ(taken, pushed);
}

TEST(Input, RepeatsArePressesForShortcutsButNoChange) {
    InputQueue q;
    q.push(InputEvent::key(keys::Right, true));
    q.push(InputEvent::key(keys::Right, true, 0, true));
    q.push(InputEvent::key(keys::Right, true, 0, true));
    auto f = frames(q);
    ASSERT_EQ(f.size(), 1u) << "the repeats of a held key go with its press";
    EXPECT_EQ(f[0].size(), 3u);
}

TEST(FramePacer, DrawsAfterInputAndThenSleeps) {
    FramePacer p;
    int drawn = 0;
    for (int i = 0; i < 10 && p.due(0.0, false); ++i, ++drawn) {
        p.drawn(0.0, -1.0f);
    }
    EXPECT_EQ(drawn, FramePacer::kSettleFrames) << "the first frames, then nothing";
    EXPECT_FALSE(p.due(100.0, false));
    EXPECT_LT(p.sleepFor(100.0, false), 0.0) << "asleep until an event";
    EXPECT_TRUE(p.due(100.0, true)) << "queued input is due at once";
    p.input();
    EXPECT_TRUE(p.due(100.0, false));
    EXPECT_EQ(p.dueAfterThis(false), FramePacer::kSettleFrames - 1);
}

// A tap arrives as four events that take four frames; the settling frames follow the last of them
// (a tab bar that the tap showed needs them to lay out).
TEST(FramePacer, SettlingFramesFollowTheFrameThatTookTheLastEvent) {
    FramePacer p;
    while (p.due(0.0, false)) {
        p.drawn(0.0, -1.0f);
    }
    p.input();
    int queued = 4, afterLast = 0;
    for (int i = 0; i < 20 && p.due(0.0, queued > 0); ++i) {
        if (queued == 0) {
            ++afterLast;
        }
        queued = queued > 0 ? queued - 1 : 0; // this frame takes one event
        p.drawn(0.0, -1.0f, queued > 0);
    }
    EXPECT_EQ(afterLast, FramePacer::kSettleFrames - 1);
}

TEST(FramePacer, WakesForTheAppsTimer) {
    FramePacer p;
    while (p.due(0.0, false)) {
        p.drawn(0.0, 4.0f); // a toast for 4 s
    }
    EXPECT_NEAR(p.sleepFor(1.0, false), 3.0, 1e-9);
    EXPECT_FALSE(p.due(3.9, false));
    EXPECT_TRUE(p.due(4.0, false));
    p.drawn(4.0, -1.0f);
    EXPECT_FALSE(p.due(50.0, false));
    p.drawn(4.0, 0.0f); // "again at once"
    EXPECT_TRUE(p.due(4.0, false));
}

TEST(ViewportResolution, LowersWhileDraggingSlowFramesAndIsFullAfterwards) {
    ViewportResolution r;
    EXPECT_EQ(r.update(true, 0.010f, 0.05f), 1.0f) << "fast frames keep full resolution";
    float s = 1.0f;
    for (int i = 0; i < 20; ++i) {
        // A frame whose cost is 20 ms of UI plus 300 ms of shading at full resolution.
        s = r.update(true, 0.02f + 0.3f * s * s, 0.05f);
    }
    EXPECT_LT(s, 0.5f);
    EXPECT_GE(s, ViewportResolution::kLowest);
    EXPECT_LE(0.02f + 0.3f * s * s, 0.05f * 1.05f) << "converges to a frame within the budget";
    EXPECT_EQ(r.update(false, 1.0f, 0.05f), 1.0f) << "full resolution the moment the drag ends";
    EXPECT_EQ(r.update(true, 10.0f, 0.0f), 1.0f) << "a budget of 0 turns it off";
}

TEST(ViewportResolution, NeverMoreThanHalvesThePixelsAtOnce) {
    ViewportResolution r;
    float s = r.update(true, 100.0f, 0.05f);
    EXPECT_GE(s * s, 0.5f - 1e-6f);
}

} // namespace
} // namespace lab
