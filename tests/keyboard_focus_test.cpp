// keyboard_focus_test.cpp — the keyboard between the model and the windows (ui/keyboard.h) and the
// tooltips that stay and close with Esc (ui/tooltip.h), on the headless lab: real App frames with
// ImGui's navigation, keys given as the platform gives them (a press in one frame, its release in
// the next). The GUI test (tests/gui/keyboard_test.cpp) does the same through a real X server.
#include "app/app.h"
#include "core/share/share_link.h"
#include "cpu_imgui.h"
#include "platform/headless_app.h"
#include "platform/headless_gl.h"
#include "test_files.h"
#include "ui/actions.h"
#include "ui/keyboard.h"
#include "ui/widget_map.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h> // is a tooltip window shown

#include <cmath>

namespace lab {
namespace {

namespace fs = std::filesystem;

class Keyboard : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(gl_.create(error)) << error;
        options_.presetFolders = {fs::path(LAB_SOURCE_DIR) / "presets"};
        options_.preset = fs::path(LAB_SOURCE_DIR) / "presets/05-full-phong.json";
        options_.screenshotFolder = dir_.path();
        app_ = std::make_unique<App>(options_);
        ASSERT_TRUE(lab_.start(*app_, 1280, 800, error)) << error;
        frames(3);
    }

    FrameOutput frames(int n, FrameInput in = {}) {
        FrameOutput out = lab_.frame(in);
        for (int i = 1; i < n; ++i) {
            out = lab_.frame();
        }
        link_ = out.link;
        return out;
    }
    // A key pressed in one frame, released in the next, then two frames for ImGui's navigation to land.
    void press(int key, unsigned modifiers = 0) {
        FrameInput down, up;
        down.events = {InputEvent::key(key, true, modifiers)};
        up.events = {InputEvent::key(key, false, modifiers)};
        frames(1, down);
        frames(3, up);
    }
    void moveTo(float x, float y) {
        FrameInput in;
        in.events = {InputEvent::move(x, y)};
        frames(3, in);
    }

    static const ui::Rect* widget(const char* name) { return ui::widgets().find(name); }
    static bool atCorner(const char* name) {
        const ui::Rect *f = widget("focus"), *w = widget(name);
        return f && w && std::abs(f->x - w->x) <= 1.0f && std::abs(f->y - w->y) <= 1.0f;
    }
    static bool tooltipShown() {
        ImGuiWindow* w = ImGui::FindWindowByName("##Tooltip_00");
        return w && w->Active;
    }
    float shininess() {
        Diagnostics d;
        std::optional<Linked> linked = parseLink(link_, options_.presetFolders[0], d);
        const Preset* p = linked ? std::get_if<Preset>(&*linked) : nullptr;
        return p ? p->material.shininess : 32.0f; // "preset=05-full-phong": the file's own, 32
    }
    // Tab, then Down until the ring is on `name` (at most 120 steps).
    bool walkTo(const char* name) {
        press(keys::Tab);
        for (int i = 0; i < 120 && widget("focus") && !atCorner(name); ++i) {
            press(keys::Down);
        }
        return atCorner(name);
    }

    HeadlessGl gl_;
    TempFolder dir_;
    AppOptions options_;
    std::unique_ptr<App> app_;
    HeadlessApp lab_;
    std::string link_;
};

TEST_F(Keyboard, TabEntersThePanelTheArrowsChangeTheShininessAndEscGivesTheKeysBack) {
    EXPECT_EQ(widget("focus"), nullptr) << "no ring while the model has the keyboard";
    ASSERT_EQ(shininess(), 32.0f);
    ASSERT_TRUE(walkTo("material.shininess")) << "Down from the panel's first widget should reach the shininess";
    const std::string before = link_;
    press('1');         // flat shading on the model: not while a widget has the keyboard
    press(keys::Right); // the next preset on the model: here the next widget on the line, then back
    press(keys::Left);
    EXPECT_EQ(link_, before) << "plain keys in the panel must not be the model's shortcuts";
    ASSERT_TRUE(atCorner("material.shininess"));

    press(keys::Space); // the slider takes the arrows
    for (int i = 0; i < 5; ++i) {
        press(keys::Right);
    }
    press(keys::Escape); // the change ends, the ring stays
    EXPECT_GT(shininess(), 40.0f) << "five steps right on the logarithmic slider raise the exponent";
    EXPECT_TRUE(atCorner("material.shininess"));

    press(keys::Escape); // back to the model
    EXPECT_EQ(widget("focus"), nullptr);
    const std::string edited = link_;
    press('1');
    EXPECT_NE(link_, edited) << "back on the model, 1 is flat shading again";
}

// Tab from a widget goes on to the next field below it, not back to the window's first (ImGui 1.86's
// own Tab restarts from the top unless a field is being typed in).
TEST_F(Keyboard, TabFromAWidgetGoesOnToTheNextField) {
    ASSERT_TRUE(walkTo("material.shininess"));
    const float shininessY = widget("material.shininess")->y;
    press(keys::Right); // the help marker: not a field
    ASSERT_FALSE(atCorner("material.shininess"));
    press(keys::Tab);
    ASSERT_NE(widget("focus"), nullptr);
    EXPECT_GT(widget("focus")->y, shininessY) << "Tab went back up to " << widget("focus")->y;
    press(keys::Escape); // the field's typing ends
    press(keys::Escape);
    EXPECT_EQ(widget("focus"), nullptr);
}

TEST_F(Keyboard, EnterOnTheModelTakesTheKeyboardIntoThePanelAsTabDoes) {
    EXPECT_EQ(frames(1).keys, KeyOwner::Canvas);
    press(keys::Enter);
    EXPECT_EQ(frames(1).keys, KeyOwner::Panel) << "the frame says who has the keys (the page decides about Tab)";
    ASSERT_NE(widget("focus"), nullptr);
    const ui::Rect *f = widget("focus"), *panel = widget("panel");
    EXPECT_TRUE(f->x >= panel->x && f->y >= panel->y && f->y + f->h <= panel->y + panel->h);
}

// The browser's setting: Tab is the page's (it leaves the canvas for the page's controls: no trap in
// the canvas), Enter enters the panel; on the ImGui context alone, without the app.
TEST(KeyboardFocus, WhereTabIsThePagesEnterStillEntersThePanel) {
    CpuImGui imgui(1.0f);
    ImGui::GetIO().DisplaySize = ImVec2(800, 600);
    auto frame = [] {
        ImGui::NewFrame();
        ImGui::Begin("Lighting Lab###panel");
        ImGui::Button("a");
        ImGui::End();
        ImGui::Render();
    };
    frame();
    ui::KeyboardFocus keyboard;
    keyboard.tabEntersWindows(false);
    std::vector<ui::KeyPress> tab{{keys::Tab, kNoModifier}};
    EXPECT_EQ(keyboard.beforeNewFrame(tab, false), KeyOwner::Canvas);
    EXPECT_FALSE(tab[0].used) << "the page's Tab must reach the browser untouched";
    frame();
    std::vector<ui::KeyPress> enter{{keys::Enter, kNoModifier}};
    EXPECT_EQ(keyboard.beforeNewFrame(enter, false), KeyOwner::Panel);
    EXPECT_TRUE(enter[0].used);
    keyboard.tabEntersWindows(true);
    std::vector<ui::KeyPress> escapeAndClick{};
    EXPECT_EQ(keyboard.beforeNewFrame(escapeAndClick, true), KeyOwner::Canvas) << "a mouse press gives the keys back";
    std::vector<ui::KeyPress> tabAgain{{keys::Tab, kNoModifier}};
    EXPECT_EQ(keyboard.beforeNewFrame(tabAgain, false), KeyOwner::Panel);
}

// F1's help is read row by row from the keyboard (it may be taller than the screen and scroll), and
// left: Esc gives the keyboard back to the model, the next Esc closes the help.
TEST_F(Keyboard, TheHelpIsReadRowByRowAndEscLeavesThenClosesIt) {
    press(keys::F1);
    ASSERT_NE(widget("help"), nullptr);
    press(keys::Tab); // the help has ImGui's focus: Tab goes into it, not into the panel
    ASSERT_NE(widget("focus"), nullptr);
    const ui::Rect* help = widget("help");
    const float first = widget("focus")->y;
    EXPECT_TRUE(widget("focus")->x >= help->x && widget("focus")->y >= help->y) << "the ring is in the help";
    for (int i = 0; i < 5; ++i) {
        press(keys::Down);
    }
    EXPECT_GT(widget("focus")->y, first) << "Down goes from row to row";
    press(keys::Escape);
    EXPECT_EQ(widget("focus"), nullptr);
    EXPECT_NE(widget("help"), nullptr);
    press(keys::Escape);
    EXPECT_EQ(widget("help"), nullptr) << "Esc on the model closes the help";
}

// Page Up / Page Down a tenth of the slider (of its logarithm for the shininess's 1…1000), Home / End
// its ends; the ring stays on the slider (ImGui's navigation would page away from it).
TEST_F(Keyboard, PageKeysHomeAndEndMoveASliderThatHasTheKeyboard) {
    ASSERT_TRUE(walkTo("material.shininess"));
    press(keys::Space);
    press(keys::End);
    EXPECT_FLOAT_EQ(shininess(), 1000.0f);
    press(keys::Home);
    EXPECT_FLOAT_EQ(shininess(), 1.0f);
    press(keys::PageUp);
    press(keys::PageUp);
    EXPECT_NEAR(shininess(), std::pow(1000.0f, 0.2f), 0.01f);
    press(keys::PageDown);
    EXPECT_NEAR(shininess(), std::pow(1000.0f, 0.1f), 0.01f);
    EXPECT_TRUE(atCorner("material.shininess"));
    press(keys::Escape);
    EXPECT_TRUE(atCorner("material.shininess"));
}

TEST_F(Keyboard, AHelpMarkerShowsItsTooltipOnTheRingAndEscClosesItFirst) {
    ASSERT_TRUE(walkTo("material.shininess"));
    press(keys::Right); // the "(?)" beside the slider
    ASSERT_NE(widget("focus"), nullptr);
    EXPECT_FALSE(atCorner("material.shininess")) << "Right should move the ring to the help marker";
    EXPECT_TRUE(tooltipShown()) << "the marker's help shows while it has the ring";
    press(keys::Escape);
    EXPECT_FALSE(tooltipShown()) << "Esc closes the tooltip";
    EXPECT_NE(widget("focus"), nullptr) << "... and only the tooltip: the ring stays";
    press(keys::Escape);
    EXPECT_EQ(widget("focus"), nullptr) << "the next Esc gives the keyboard back to the model";
}

TEST_F(Keyboard, ATooltipStaysWhileThePointerIsOverItAndGoesWhenItLeaves) {
    ASSERT_NE(widget("material.shininess"), nullptr);
    const ui::Rect slider = *widget("material.shininess"); // a copy: the next frame makes the map anew
    // The marker is the last thing on the slider's line: find it by hovering along the line's end.
    const float y = slider.y + slider.h / 2;
    float markerX = -1;
    for (float x = slider.x + slider.w; x < slider.x + slider.w + 120 && markerX < 0; x += 4) {
        moveTo(x, y);
        if (tooltipShown()) {
            markerX = x;
        }
    }
    ASSERT_GE(markerX, 0) << "no tooltip while hovering the shininess's help marker";
    ImGuiWindow* tip = ImGui::FindWindowByName("##Tooltip_00");
    ImRect r = tip->Rect();
    EXPECT_GE(r.Min.y, y) << "the tooltip opens below the marker, not under the pointer";
    moveTo(r.Min.x + 5, r.Max.y - 5); // onto the tooltip's text
    EXPECT_TRUE(tooltipShown()) << "the pointer can reach the tooltip: it stays (WCAG 1.4.13)";
    press(keys::Escape);
    EXPECT_FALSE(tooltipShown()) << "Esc closes it (WCAG 1.4.13)";
    moveTo(markerX, y);
    EXPECT_FALSE(tooltipShown()) << "closed until the pointer leaves: back on the marker it stays closed";
    moveTo(10, 10);
    moveTo(markerX, y);
    EXPECT_TRUE(tooltipShown()) << "after leaving, hovering shows it again";
    const ui::Rect* view = widget("view");
    ASSERT_NE(view, nullptr);
    moveTo(view->x + view->w / 2, view->y + view->h / 2);
    EXPECT_FALSE(tooltipShown()) << "away from both, it goes";
}

} // namespace
} // namespace lab
