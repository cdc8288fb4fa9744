// classroom_test.cpp — the lab in front of a class: on a projector's screen, in presenter mode,
// with captions, shipped presets that stay as they are, and a probe that shows where it looks.
//
// GuiFit runs once per screen size (CTest starts an Xvfb of 1024x768, 1280x800 and 1920x1080
// for it); the others run on the GUI suite's screen.
#include "gui_harness.h"

#include <cstdlib>

namespace lab::test {
namespace {

namespace fs = std::filesystem;

bool inside(const Rect& r, const Rect& in) {
    return r.x >= in.x && r.y >= in.y && r.x + r.w <= in.x + in.w && r.y + r.h <= in.y + in.h;
}

// The window fits the screen, and every plot lies whole inside the window and inside the
// plots' own window (not cut off by a scroll area), before and in presenter mode.
void expectEverythingFits(Lab& lab, int screenW, int screenH, const std::string& mode) {
    auto rects = lab.layout();
    ASSERT_TRUE(rects.count("window") && rects.count("plots")) << mode;
    const Rect window = rects["window"], plots = rects["plots"];
    EXPECT_LE(window.w, screenW) << mode;
    EXPECT_LE(window.h, screenH) << mode;
    EXPECT_TRUE(inside(plots, window)) << mode << ": the plots' window leaves the window";
    EXPECT_TRUE(inside(rects["view"], window)) << mode;
    int plotCount = 0;
    for (const auto& [name, r] : rects) {
        if (name.rfind("plot.", 0) == 0 && r.w > 0 && r.h > 0) {
            ++plotCount;
            EXPECT_TRUE(inside(r, plots)) << mode << ": " << name << " is cut off (" << r.x << " " << r.y << " " << r.w
                                          << " " << r.h << ")";
        }
    }
    EXPECT_GT(plotCount, 0) << mode;
    // The panel's rows of buttons wrap rather than run past its edge (the PNG scale beside Export
    // figures once did at 1600x900).
    if (rects.count("panel")) {
        const Rect panel = rects["panel"];
        for (const char* name : {"sweep.open", "screenshot", "figures.export", "figures.scale", "compare"}) {
            if (rects.count(name)) {
                const Rect r = rects[name];
                EXPECT_LE(r.x + r.w, panel.x + panel.w) << mode << ": " << name << " runs past the panel's edge";
            }
        }
    }
}

TEST(GuiFit, TheWindowAndEveryPlotFitTheScreenNormalAndInPresenterMode) {
    START_LAB(lab, "--preset", preset("12-blinn-phong"));
    int screenW = 0, screenH = 0;
    lab.x().screenSize(screenW, screenH);
    lab.settle();
    expectEverythingFits(lab, screenW, screenH, "normal");
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("p");
    lab.settle();
    expectEverythingFits(lab, screenW, screenH, "presenter 1.75x");
    for (int i = 0; i < 4; ++i) {
        lab.press("equal", "Control_L");
    }
    lab.settle();
    expectEverythingFits(lab, screenW, screenH, "presenter 2.5x");
    // Tab cycles all / plots and model / model only; presenter mode may have hidden the panel.
    for (int i = 0; i < 3 && !(lab.has("panel") && lab.has("plots")); ++i) {
        lab.press("Tab");
        lab.settle();
    }
    ASSERT_TRUE(lab.has("panel") && lab.has("plots")) << "Tab should bring every panel back";
    expectEverythingFits(lab, screenW, screenH, "presenter 2.5x, all panels");
}

TEST(GuiClassroom, TheCaptionTellsThePresetsStoryAndFollowsTheSteps) {
    START_LAB(lab, "--preset", preset("09-coarse-flat"), "--presenter");
    ASSERT_TRUE(lab.has("view.caption")) << "presenter mode shows the caption";
    Rect first = lab.widget("view.caption");
    EXPECT_GT(brightest(lab.capture(first)), 200) << "the caption's text should be drawn";
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("Right"); // 10-coarse-gouraud: another name and description
    lab.settle();
    Rect second = lab.widget("view.caption");
    EXPECT_TRUE(first.w != second.w || first.h != second.h) << "the caption should follow the preset";
    lab.press("i");
    lab.settle();
    EXPECT_FALSE(lab.has("view.caption"));
}

TEST(GuiClassroom, SavingAShippedPresetLeavesPresetsAsTheyAre) {
    TempFolder home;
    ::setenv("XDG_DATA_HOME", home.path().c_str(), 1);
    std::string before = readText(preset("05-full-phong"));
    {
        START_LAB(lab, "--preset", preset("05-full-phong"));
        ::unsetenv("XDG_DATA_HOME");
        Rect view = lab.widget("view");
        lab.moveTo(view.cx(), view.cy());
        lab.press("1");
        lab.press("s", "Control_L");
        lab.settle();
    }
    ::unsetenv("XDG_DATA_HOME");
    EXPECT_EQ(readText(preset("05-full-phong")), before) << "a shipped preset was overwritten";
    Diagnostics d;
    std::optional<LoadedPreset> copy = loadPreset(home.path() / "lighting-lab" / "presets" / "05-full-phong.json", d);
    ASSERT_TRUE(copy) << toString(d);
    EXPECT_EQ(copy->preset.shading, Shading::Flat);
}

TEST(GuiClassroom, AnOrbitAloneDoesNotAskAboutUnsavedChanges) {
    TempFolder dir;
    fs::copy_file(preset("05-full-phong"), dir.path() / "a.json");
    fs::copy_file(preset("12-blinn-phong"), dir.path() / "b.json");
    START_LAB(lab, "--preset", (dir.path() / "a.json").string());
    Rect view = lab.widget("view");
    lab.drag(view.cx() - 60, view.cy(), view.cx() + 60, view.cy() + 20);
    lab.press("Right");
    lab.settle();
    EXPECT_FALSE(lab.has("confirm.discard")) << "an orbit is not an unsaved change";
    lab.press("Left");
    lab.settle();
    EXPECT_FALSE(lab.has("confirm.discard"));
}

TEST(GuiClassroom, TheProbeMarkerAppearsAndGoesWithTheProbe) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Rect view = lab.widget("view");
    EXPECT_FALSE(lab.has("view.probe-marker"));
    lab.click(view.cx(), view.cy()); // the sphere is in the middle
    lab.settle();
    ASSERT_TRUE(lab.has("view.probe-marker")) << "a probe marks its pixel";
    Rect marker = lab.widget("view.probe-marker");
    EXPECT_NEAR(marker.cx(), view.cx(), 6);
    EXPECT_NEAR(marker.cy(), view.cy(), 6);
    lab.click(view.x + 12, view.y + view.h - 12); // beside the model: the probe closes
    lab.settle();
    EXPECT_FALSE(lab.has("view.probe-marker"));
}

} // namespace
} // namespace lab::test
