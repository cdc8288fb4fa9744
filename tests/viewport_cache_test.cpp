// viewport_cache_test.cpp — the 3D view drawn only when what it shows changes, and at a reduced
// resolution only while dragging (app/viewport_cache.h), on real App frames (HeadlessApp).
#include "app/app.h"
#include "platform/headless_app.h"
#include "platform/headless_gl.h"
#include "test_files.h"
#include "ui/actions.h"
#include "ui/widget_map.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

namespace fs = std::filesystem;

class ViewCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(gl_.create(error)) << error;
        AppOptions options;
        options.preset = fs::path(LAB_SOURCE_DIR) / "presets" / "05-full-phong.json";
        options.presetFolders = {fs::path(LAB_SOURCE_DIR) / "presets"};
        options.screenshotFolder = dir_.path();
        options.userFolder = dir_.path();
        app_ = std::make_unique<App>(options);
        ASSERT_TRUE(lab_.start(*app_, 1280, 800, error)) << error;
        frame();
        const ui::Rect* view = ui::widgets().find("view");
        ASSERT_TRUE(view);
        view_ = *view;
    }

    // One frame with these events; every frame says the last one took `cost` seconds.
    FrameOutput frame(std::vector<InputEvent> events = {}, float cost = 0.01f) {
        FrameInput in;
        in.events = std::move(events);
        in.lastFrameSeconds = cost;
        return lab_.frame(in);
    }

    HeadlessGl gl_;
    TempFolder dir_;
    std::unique_ptr<App> app_;
    HeadlessApp lab_;
    ui::Rect view_;
};

TEST_F(ViewCacheTest, HoveringAndUnchangedFramesDoNotDrawTheView) {
    EXPECT_FALSE(frame().viewportDrawn) << "nothing changed: the cached view is shown";
    EXPECT_FALSE(frame({InputEvent::move(20, 20)}).viewportDrawn) << "hovering the panel changes nothing in the view";
    EXPECT_FALSE(frame({InputEvent::move(view_.x + 30, view_.y + 40)}).viewportDrawn);
    EXPECT_TRUE(frame({InputEvent::key('1', true)}).viewportDrawn) << "flat shading changes the view";
    EXPECT_FALSE(frame({InputEvent::key('1', false)}).viewportDrawn);
}

TEST_F(ViewCacheTest, ADragOnASlowMachineIsDrawnSmallerAndTheFrameAfterItIsFullAndExact) {
    float cx = view_.x + view_.w / 2, cy = view_.y + view_.h / 2;
    frame({InputEvent::move(cx, cy)});
    frame({InputEvent::button(0, true, cx, cy)});
    float lowest = 1.0f;
    for (int i = 1; i <= 8; ++i) {
        // Frames of 300 ms: far over the 50 ms budget.
        FrameOutput out = frame({InputEvent::move(cx + 10.0f * i, cy)}, 0.3f);
        EXPECT_TRUE(out.viewportDrawn) << "the orbit moves the camera every frame";
        lowest = std::min(lowest, out.viewportScale);
    }
    EXPECT_LT(lowest, 0.6f) << "slow frames while dragging lower the view's resolution";
    FrameOutput released = frame({InputEvent::button(0, false, cx + 80, cy)}, 0.3f);
    EXPECT_EQ(released.viewportScale, 1.0f) << "the frame that ends the drag is full resolution";
    EXPECT_TRUE(released.viewportDrawn);
    EXPECT_FALSE(frame({}, 0.3f).viewportDrawn);
    Image afterDrag = lab_.read();

    // The same scene drawn again without any interaction: M twice (the normal matrix, and back).
    EXPECT_TRUE(frame({InputEvent::key('M', true)}, 0.3f).viewportDrawn);
    frame({InputEvent::key('M', false)}, 0.3f);
    EXPECT_TRUE(frame({InputEvent::key('M', true)}, 0.3f).viewportDrawn);
    frame({InputEvent::key('M', false)}, 0.3f);
    Image redrawn = lab_.read();
    ASSERT_EQ(afterDrag.width, redrawn.width);
    EXPECT_TRUE(afterDrag.rgb == redrawn.rgb) << "the frame after the drag must be the full-resolution frame, pixel for pixel";
}

// Issue 28: a light that moves by itself uses the same frame budget as a drag.
TEST_F(ViewCacheTest, AMovingLightOnASlowMachineIsDrawnSmallerAndFullOnceItStops) {
    FrameInput open;
    open.droppedFiles = {(fs::path(LAB_SOURCE_DIR) / "presets" / "25-moving-light.json").string()};
    lab_.frame(open);
    float lowest = 1.0f;
    for (int i = 0; i < 8; ++i) {
        FrameOutput out = frame({}, 0.3f);
        EXPECT_TRUE(out.viewportDrawn) << "the light moves every frame";
        lowest = std::min(lowest, out.viewportScale);
    }
    EXPECT_LT(lowest, 0.6f) << "slow frames while a light moves lower the view's resolution";
    // Stop the light in the same scene: scroll the panel to the light's "orbit the model" box and
    // click it, the frames as slow as before.
    const ui::Rect* panel = ui::widgets().find("panel");
    ASSERT_NE(panel, nullptr);
    const ui::Rect p = *panel;
    const ui::Rect* box = nullptr;
    for (int i = 0; i < 80; ++i) {
        box = ui::widgets().find("lights[0].orbit.on");
        if (box && box->y >= p.y && box->y + box->h <= p.y + p.h) {
            break;
        }
        frame({InputEvent::move(p.x + p.w / 2, p.y + p.h / 2), InputEvent::scroll(0.0f, -1.0f)}, 0.3f);
        box = nullptr;
    }
    ASSERT_NE(box, nullptr) << "the orbit box was not scrolled into the panel";
    const float bx = box->x + box->h / 2, by = box->y + box->h / 2;
    frame({InputEvent::move(bx, by)}, 0.3f);
    frame({InputEvent::button(0, true, bx, by)}, 0.3f);
    FrameOutput stopped = frame({InputEvent::button(0, false, bx, by)}, 0.3f);
    EXPECT_TRUE(stopped.viewportDrawn) << "the light is back where its orbit starts";
    EXPECT_EQ(stopped.viewportScale, 1.0f) << "the frame in which the light stops is full resolution";
    EXPECT_FALSE(frame({}, 0.3f).viewportDrawn) << "the light stands still: nothing to draw";
}

// Issue 28, the app's side of the plots' lag: each frame of a slider drag that changes the
// material owes the next frame (redrawIn 0: the lagging readouts become exact without input); a
// drag paused with the slider held owes nothing (idle); the release draws the exact frame, after
// which the app is idle again.
TEST_F(ViewCacheTest, ADragOwesAFrameWhileItChangesTheMaterialAndNothingWhileItPauses) {
    const ui::Rect* found = ui::widgets().find("material.shininess");
    ASSERT_NE(found, nullptr);
    const ui::Rect slider = *found;
    const float x = slider.x + slider.w * 0.3f, y = slider.y + slider.h / 2;
    frame({InputEvent::move(x, y)});
    frame({InputEvent::button(0, true, x, y)});
    for (int i = 1; i <= 6; ++i) {
        EXPECT_EQ(frame({InputEvent::move(x + 6.0f * i, y)}).redrawIn, 0.0f) << "frame " << i << " of the drag";
    }
    FrameOutput paused;
    for (int i = 0; i < 4; ++i) {
        paused = frame();
    }
    EXPECT_NE(paused.redrawIn, 0.0f) << "a paused drag owes no frames";
    frame({InputEvent::button(0, false, x + 36.0f, y)});
    FrameOutput after;
    for (int i = 0; i < 4; ++i) {
        after = frame();
    }
    EXPECT_NE(after.redrawIn, 0.0f) << "after the release the app is idle";
}

TEST_F(ViewCacheTest, FastFramesKeepFullResolutionWhileDragging) {
    float cx = view_.x + view_.w / 2, cy = view_.y + view_.h / 2;
    frame({InputEvent::move(cx, cy)});
    frame({InputEvent::button(0, true, cx, cy)});
    for (int i = 1; i <= 4; ++i) {
        EXPECT_EQ(frame({InputEvent::move(cx + 10.0f * i, cy)}, 0.01f).viewportScale, 1.0f);
    }
    frame({InputEvent::button(0, false, cx + 40, cy)});
}

} // namespace
} // namespace lab
