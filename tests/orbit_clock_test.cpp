// orbit_clock_test.cpp — the moving lights can always be paused, and reduced motion opens them paused:
// the clock itself (app/orbit_clock.h), then the lab on its headless platform with
// AppOptions::reducedMotion, resumed by the panel's "Pause moving lights" box.
#include "app/app.h"
#include "app/orbit_clock.h"
#include "platform/headless_app.h"
#include "platform/headless_gl.h"
#include "test_files.h"
#include "ui/widget_map.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

namespace fs = std::filesystem;

Preset orbiting() {
    Preset p;
    p.lights[0].orbit.on = true;
    p.lights[0].orbit.degreesPerSecond = 30.0f;
    return p;
}

constexpr float kStep = 1.0f / 60.0f;

TEST(OrbitClock, ReducedMotionOpensEverySceneWithTheLightsPausedUntilResumed) {
    const Preset p = orbiting();
    OrbitClock clock(true);
    for (int i = 0; i < 5; ++i) {
        EXPECT_FALSE(clock.advance({&p, nullptr}, {}, 1, kStep, false)) << "no frame is asked for";
    }
    EXPECT_EQ(clock.motion(0).secondsOf(0), 0.0);
    EXPECT_EQ(clock.moving(p), MovingLights::Paused);
    clock.togglePaused(); // resumed
    EXPECT_EQ(clock.moving(p), MovingLights::Moving);
    EXPECT_TRUE(clock.advance({&p, nullptr}, {}, 1, kStep, false));
    EXPECT_TRUE(clock.advance({&p, nullptr}, {}, 1, kStep, false));
    EXPECT_DOUBLE_EQ(clock.motion(0).secondsOf(0), 2.0 * double(kStep));
    // The next scene opens paused again, from its own position.
    EXPECT_FALSE(clock.advance({&p, nullptr}, {}, 2, kStep, false));
    EXPECT_EQ(clock.motion(0).secondsOf(0), 0.0);
    EXPECT_EQ(clock.moving(p), MovingLights::Paused);
}

TEST(OrbitClock, TheMotionCanAlwaysBePausedAndGoesOnFromWhereItStood) {
    const Preset p = orbiting();
    OrbitClock clock; // no reduced motion: the light moves once its scene has opened
    clock.advance({&p, nullptr}, {}, 1, kStep, false); // the scene opens: its clocks start at 0
    EXPECT_TRUE(clock.advance({&p, nullptr}, {}, 1, kStep, false));
    EXPECT_EQ(clock.moving(p), MovingLights::Moving);
    clock.togglePaused();
    for (int i = 0; i < 5; ++i) {
        EXPECT_FALSE(clock.advance({&p, nullptr}, {}, 1, kStep, false));
    }
    EXPECT_DOUBLE_EQ(clock.motion(0).secondsOf(0), double(kStep)) << "paused where it stood";
    clock.togglePaused();
    EXPECT_TRUE(clock.advance({&p, nullptr}, {}, 1, kStep, false));
    EXPECT_DOUBLE_EQ(clock.motion(0).secondsOf(0), 2.0 * double(kStep));
    // A scene opened while paused moves (the pause was for that scene).
    clock.togglePaused();
    clock.advance({&p, nullptr}, {}, 2, kStep, false);
    EXPECT_EQ(clock.moving(p), MovingLights::Moving);
    EXPECT_TRUE(clock.advance({&p, nullptr}, {}, 2, kStep, false));
    // A scene without a moving light has nothing to pause.
    EXPECT_EQ(clock.moving(Preset{}), MovingLights::None);
}

// The model's view in the window's picture (window units are pixels here).
Image viewOf(const Image& window) {
    const ui::Rect* r = ui::widgets().find("view");
    EXPECT_NE(r, nullptr) << "the model's view is named \"view\"";
    if (!r) {
        return {};
    }
    Image view{int(r->w), int(r->h), {}};
    for (int y = int(r->y); y < int(r->y + r->h); ++y) {
        const auto row = window.rgb.begin() + (std::ptrdiff_t(y) * window.width + int(r->x)) * 3;
        view.rgb.insert(view.rgb.end(), row, row + std::ptrdiff_t(r->w) * 3);
    }
    return view;
}

struct MovingLightLab {
    HeadlessGl gl;
    TempFolder dir;
    std::unique_ptr<App> app;
    HeadlessApp lab;
    static constexpr int kWidth = 1600, kHeight = 1400; // tall enough for the panel's Lights section

    explicit MovingLightLab(bool reducedMotion) {
        std::string error;
        EXPECT_TRUE(gl.create(error)) << error;
        AppOptions options;
        options.preset = fs::path(LAB_SOURCE_DIR) / "presets/25-moving-light.json";
        options.screenshotFolder = dir.path();
        options.reducedMotion = reducedMotion;
        app = std::make_unique<App>(options);
        EXPECT_TRUE(lab.start(*app, kWidth, kHeight, error)) << error;
    }
    FrameOutput frames(int n, FrameInput in = {}) {
        FrameOutput out = lab.frame(in);
        for (int i = 1; i < n; ++i) {
            out = lab.frame();
        }
        return out;
    }
};

TEST(ReducedMotion, TheMovingLightStandsStillUntilThePanelResumesIt) {
    {
        MovingLightLab moving(false);
        FrameOutput out = moving.frames(3);
        EXPECT_EQ(out.movingLights, MovingLights::Moving);
        EXPECT_GE(out.redrawIn, 0.0f) << "a moving light asks for frames";
        Image before = viewOf(moving.lab.read());
        moving.frames(30); // half a second: 15 degrees
        EXPECT_NE(viewOf(moving.lab.read()).rgb, before.rgb) << "without reduced motion the light moves";
    }
    MovingLightLab lab(true);
    FrameOutput out = lab.frames(3);
    EXPECT_EQ(out.movingLights, MovingLights::Paused);
    // (A note going away may ask for a frame in a few seconds; the orbit's 60 a second are not asked for.)
    EXPECT_FALSE(out.redrawIn >= 0.0f && out.redrawIn <= OrbitClock::kFrameSeconds) << "a paused light asks for no frames";
    Image before = viewOf(lab.lab.read());
    ASSERT_FALSE(before.rgb.empty());
    lab.frames(30);
    EXPECT_EQ(viewOf(lab.lab.read()).rgb, before.rgb) << "with reduced motion the light stands still";

    // The panel's box resumes it: a click on "Pause moving lights" (press and release in two frames).
    const ui::Rect* box = ui::widgets().find("lights.pause");
    ASSERT_NE(box, nullptr) << "the panel offers the pause whenever a light orbits";
    ASSERT_LT(box->y + box->h, float(MovingLightLab::kHeight)) << "the box is in the window";
    const float x = box->x + box->h / 2, y = box->y + box->h / 2;
    FrameInput press, release;
    press.events = {InputEvent::move(x, y), InputEvent::button(0, true, x, y)};
    release.events = {InputEvent::button(0, false, x, y)};
    lab.frames(1, press);
    lab.frames(1, release);
    out = lab.frames(30);
    EXPECT_EQ(out.movingLights, MovingLights::Moving);
    EXPECT_NE(viewOf(lab.lab.read()).rgb, before.rgb) << "resumed, the light moves";
}

} // namespace
} // namespace lab
