// keyboard_test.cpp — the lab driven by the keyboard alone (ui/keyboard.h): no click, the pointer
// only parked over the model, where X gives the keyboard to the window under it (no window manager).
// Where the keyboard is comes from the layout file's "focus" rectangle, the ring's.
#include "gui_harness.h"

#include <cstdlib>

namespace lab::test {
namespace {

bool sameCorner(const Rect& a, const Rect& b) {
    return std::abs(a.x - b.x) <= 1 && std::abs(a.y - b.y) <= 1;
}

bool inside(const Rect& r, const Rect& in) {
    return r.x >= in.x && r.y >= in.y && r.x + r.w <= in.x + in.w && r.y + r.h <= in.y + in.h;
}

Rect grown(const Rect& r, int by) {
    return Rect{r.x - by, r.y - by, r.w + 2 * by, r.h + 2 * by};
}

// Tab into the panel, then Down until the ring is on `widget`; false if 120 steps do not reach it.
bool tabAndWalkDownTo(Lab& lab, const std::string& widget) {
    lab.press("Tab");
    if (!lab.has("focus")) {
        ADD_FAILURE() << "Tab from the model should put the keyboard's ring in the panel";
        return false;
    }
    EXPECT_TRUE(inside(lab.widget("focus"), lab.widget("panel"))) << "Tab from the model goes into the control panel";
    for (int i = 0; i < 120; ++i) {
        if (lab.has("focus") && sameCorner(lab.widget("focus"), lab.widget(widget))) {
            return true;
        }
        lab.press("Down");
    }
    ADD_FAILURE() << "Down never reached " << widget;
    return false;
}

TEST(GuiKeyboard, TheKeyboardAloneReachesTheShininessAndChangesIt) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    EXPECT_FALSE(lab.has("focus")) << "no ring while the model has the keyboard";
    Image before = lab.viewShot();
    Image plotBefore = lab.capture(lab.widget("plot.lobe"));
    ASSERT_TRUE(tabAndWalkDownTo(lab, "material.shininess"));

    // The ring is drawn: the slider's surroundings change when the ring moves on to the next widget.
    Image ringed = lab.capture(grown(lab.widget("material.shininess"), 3));
    lab.press("Down");
    Image plain = lab.capture(grown(lab.widget("material.shininess"), 3));
    EXPECT_GT(changedShare(ringed, plain), 0.03) << "no visible ring around the focused slider";
    lab.press("Up");
    ASSERT_TRUE(sameCorner(lab.widget("focus"), lab.widget("material.shininess")));

    lab.press("space"); // the slider takes the arrows
    for (int i = 0; i < 8; ++i) {
        lab.press("Right");
    }
    lab.press("Escape"); // the change ends; the ring stays on the slider
    ASSERT_TRUE(lab.has("focus"));
    EXPECT_GT(changedShare(plotBefore, lab.capture(lab.widget("plot.lobe"))), 0.005) << "the lobe should have narrowed";
    Image after = lab.viewShot(); // F12 works wherever the keyboard is
    EXPECT_GT(changedShare(before, after), 0.001) << "a sharper exponent changes the highlight";

    // Esc again gives the keyboard back to the model: the ring goes, the arrows step the presets
    // without a question (issue 50), and the edited slide keeps its edit for the way back.
    lab.press("Escape");
    EXPECT_FALSE(lab.has("focus"));
    lab.press("Right");
    EXPECT_FALSE(lab.has("confirm.cancel")) << "stepping to the next preset never asks";
    EXPECT_GT(changedShare(lab.viewShot(), after), 0.001) << "Right, on the model, should open the next preset";
    lab.press("Left");
    EXPECT_EQ(compareImages(lab.viewShot(), after, Tolerance{}).maxDifference, 0) << "the way back shows the edit";
}

TEST(GuiKeyboard, InAWindowTheLettersAndArrowsAreTheWidgetsAndCtrlTabReachesTheNextWindow) {
    START_LAB(lab, "--preset", preset("11-coarse-phong"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    Image phong = lab.viewShot();
    lab.press("Tab");
    ASSERT_TRUE(lab.has("focus"));
    lab.press("1"); // flat shading, on the model; nothing in the panel
    lab.press("Right");
    lab.press("Left");
    EXPECT_EQ(compareImages(lab.viewShot(), phong, Tolerance{}).maxDifference, 0)
        << "letters and arrows in the panel must not be the model's shortcuts";

    lab.press("Tab", "Control_L"); // ImGui's window switcher: another window
    ASSERT_TRUE(lab.has("focus"));
    EXPECT_FALSE(inside(lab.widget("focus"), lab.widget("panel"))) << "Ctrl+Tab should leave the control panel";
    lab.press("Escape");
    EXPECT_FALSE(lab.has("focus")) << "Esc leaves the window: no keyboard trap";
    lab.press("1");
    EXPECT_GT(changedShare(phong, lab.viewShot()), 0.02) << "back on the model, 1 is flat shading again";
    lab.press("h"); // the panels' key: all -> plots and model
    EXPECT_FALSE(lab.has("panel"));
    lab.press("Tab");
    ASSERT_TRUE(lab.has("focus"));
    EXPECT_TRUE(inside(lab.widget("focus"), lab.widget("plots"))) << "with the panel hidden, Tab goes into the plots";
}

} // namespace
} // namespace lab::test
