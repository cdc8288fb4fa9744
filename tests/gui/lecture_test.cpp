// lecture_test.cpp — a lecture run as an instructor runs it, in a real window under Xvfb: the
// shipped deck stepped with the keys a presentation clicker sends, a live edit on every slide and
// no dialog, the speaker's notes, a prepared comparison with its labels, the equation over the
// model in presenter mode, and the pointer the back row sees, in the screenshot too.
// With LAB_GUI_SHOTS=<folder> the captures are written there to be looked at.
#include "gui_harness.h"

#include <cstdlib>

namespace lab::test {
namespace {

const std::string kDeck = std::string(LAB_SOURCE_DIR) + "/presets/decks/lecture.json";

void keep(const Image& image, const std::string& name) {
    if (const char* folder = std::getenv("LAB_GUI_SHOTS")) {
        std::string error;
        fs::create_directories(folder);
        writePng(image, fs::path(folder) / (name + ".png"), error);
    }
}

Image window(Lab& lab) { return lab.capture(lab.widget("window")); }

TEST(GuiLecture, TheDeckStepsWithAClickersKeysAndAnEditOnEverySlideAsksNothing) {
    START_LAB(lab, "--deck", kDeck);
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    ASSERT_TRUE(lab.has("view.header"));
    std::set<int> widths;
    for (const char* key : {"Right", "Next", "space", "Right", "Right", "Prior", "Right"}) {
        lab.press("2");   // a live edit: Gouraud shading
        lab.press("bracketright"); // (no binding: a key the lab ignores)
        lab.press(key);
        lab.settle();
        EXPECT_FALSE(lab.has("confirm.discard")) << "stepping with " << key << " asked about unsaved changes";
        widths.insert(lab.widget("view.header").w);
    }
    EXPECT_GE(widths.size(), 3u) << "the header should follow the slides";
    lab.press("s"); // the speaker's notes
    lab.settle();
    ASSERT_TRUE(lab.has("notes"));
    EXPECT_GT(brightest(lab.capture(lab.widget("notes"))), 150);
    keep(window(lab), "lecture-notes");
    lab.press("Home");
    lab.settle();
    lab.press("2");
    lab.settle();
    Image edited = lab.capture(lab.widget("view.header"));
    lab.press("r"); // Reset slide: the file's again
    lab.settle();
    EXPECT_GT(changedShare(edited, lab.capture(lab.widget("view.header"))), 0.001) << "R should drop the edit from the header";
}

// The window the lab opened for the notes, on the screen, once it shows text (it draws after the
// lab's frame); an empty image when it never did within 10 s.
Image notesPicture(Lab& lab, unsigned long notes, const Image* differentFrom = nullptr) {
    auto end = Clock::now() + std::chrono::seconds(10);
    Image image;
    int x = 0, y = 0, w = 0, h = 0;
    while (Clock::now() < end && lab.x().screenRect(notes, x, y, w, h)) {
        image = lab.x().capture(x, y, w, h);
        if (brightest(image) > 150 && (!differentFrom || changedShare(*differentFrom, image) > 0.001)) {
            return image;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return Image{};
}

TEST(GuiLecture, TheNotesHaveAWindowOfTheirOwnAndItsKeysStepTheSlides) {
    START_LAB(lab, "--deck", kDeck, "--size", "1024x768");
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("s", "Shift_L");
    lab.settle();
    const unsigned long notes = lab.x().findWindow("Speaker notes", 10.0);
    ASSERT_NE(notes, 0u) << "Shift+S should open the speaker notes' own window";
    EXPECT_FALSE(lab.has("notes")) << "not the strip too: the room would read it";
    Image first = notesPicture(lab, notes);
    ASSERT_GT(first.width, 200) << "the notes' window should show its text";
    keep(first, "lecture-notes-window");
    // The instructor's keys on the laptop's screen: the pointer over the notes (no window manager
    // here: the keys go to the window under the pointer), and Right steps the lab.
    int x = 0, y = 0, w = 0, h = 0;
    ASSERT_TRUE(lab.x().screenRect(notes, x, y, w, h));
    int lx = 0, ly = 0;
    lab.x().toScreen(lab.window(), lx, ly);
    ASSERT_LT(x + 20, lx) << "the test needs a place on the notes that the lab's window does not cover";
    const std::string before = lab.x().title(lab.window());
    lab.x().moveMouse(x + 10, y + h / 2);
    lab.press("Right");
    lab.settle();
    EXPECT_NE(lab.x().title(lab.window()), before) << "Right in the notes' window should step the lab (its title names the slide's file)";
    Image second = notesPicture(lab, notes, &first);
    EXPECT_GT(second.width, 0) << "the notes should follow the slide";
    lab.press("s", "Shift_L"); // from the notes' window too: closes it
    lab.settle();
    auto end = Clock::now() + std::chrono::seconds(10);
    while (lab.x().findWindow("Speaker notes", 0.1) != 0 && Clock::now() < end) {
    }
    EXPECT_EQ(lab.x().findWindow("Speaker notes", 0.1), 0u) << "Shift+S again should close the notes' window";
}

TEST(GuiLecture, APreparedComparisonOpensWithLabelsNamingWhatDiffers) {
    START_LAB(lab, "--deck", kDeck, "--size", "1280x800");
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    for (int i = 0; i < 12 && !lab.has("view.label-b"); ++i) { // to "10. Gouraud against Phong"
        lab.press("Right");
        lab.settle();
    }
    ASSERT_TRUE(lab.has("view.label-a") && lab.has("view.label-b")) << "the slide should open in compare mode";
    Image a = lab.capture(lab.widget("view.label-a")), b = lab.capture(lab.widget("view.label-b"));
    EXPECT_GT(brightest(a), 150);
    EXPECT_GT(changedShare(a, b), 0.0) << "A's and B's labels should differ";
    keep(window(lab), "lecture-compare");
}

TEST(GuiLecture, PresenterModeShowsTheEquationAndThePointerIsInTheScreenshot) {
    START_LAB(lab, "--preset", preset("13-cook-torrance-beckmann-schlick"), "--presenter", "--size", "1024x768");
    ASSERT_TRUE(lab.has("view.equation")) << "presenter mode shows the BRDF's equation over the model";
    Rect eq = lab.widget("view.equation"), view = lab.widget("view");
    EXPECT_GE(eq.x, view.x);
    EXPECT_LE(eq.x + eq.w, view.x + view.w) << "the equation is never cut";
    EXPECT_TRUE(eq.y + eq.h <= view.y + view.h / 3 || eq.y >= view.y + 2 * view.h / 3)
        << "it keeps to the top or the bottom third: the model is seen";
    ASSERT_TRUE(lab.has("view.light1"));
    const Rect light = lab.widget("view.light1");
    EXPECT_TRUE(light.x + light.w <= eq.x || eq.x + eq.w <= light.x || light.y + light.h <= eq.y || eq.y + eq.h <= light.y)
        << "the equation covers the light's marker (at " << light.x << ", " << light.y << ")";
    lab.moveTo(view.cx(), view.cy());
    lab.press("x");
    lab.settle();
    ASSERT_TRUE(lab.has("view.pointer"));
    keep(window(lab), "lecture-presenter-1024");
    Image shot = lab.viewShot();
    ASSERT_GT(shot.width, 0);
    // The ring's yellow somewhere on a circle around the centre of the view.
    int yellow = 0;
    for (std::size_t i = 0; i + 2 < shot.rgb.size(); i += 3) {
        yellow += shot.rgb[i] > 230 && shot.rgb[i + 1] > 210 && shot.rgb[i + 2] < 40;
    }
    EXPECT_GT(yellow, 200) << "the screenshot should show the pointer the room saw";
    keep(shot, "lecture-pointer-screenshot");
}

// What is cut at a side of its window in this frame (the lab marks it "clipped:...", ui/widget_map.h).
std::vector<std::string> clipped(Lab& lab, const std::string& when) {
    std::vector<std::string> cut;
    for (const auto& [name, rect] : lab.layout()) {
        if (name.rfind("clipped:", 0) == 0 && rect.w > 0) {
            cut.push_back(when + ": " + name.substr(8));
        }
    }
    return cut;
}

// A projector's screen in presenter mode with every panel shown (H until the panel is there): no
// window and no widget is cut at a side, on any tab of the plots, nor in the help; no plots tab's
// name shortened, no readout word past the plots' side, no caption cut at its strip's end, and the
// header's "what the model shows" whole (its file name may give way: the caption and the panel say it).
TEST(GuiLecture, PresenterModeOnAProjectorCutsNoText) {
    for (const std::string size : {"1024x768", "1280x800"}) {
        for (const std::string name : {"13-cook-torrance-beckmann-schlick", "23-spot-light"}) {
            START_LAB(lab, "--preset", preset(name), "--presenter", "--size", size);
            lab.moveTo(lab.widget("view").cx(), lab.widget("view").cy());
            for (int i = 0; i < 3 && !lab.has("panel"); ++i) {
                lab.press("h");
                lab.settle();
            }
            ASSERT_TRUE(lab.has("panel")) << size << ": H should show the panel";
            std::vector<std::string> cut = clipped(lab, size + " " + name);
            for (const char* tab : {"plot.view.plane", "plot.view.lobe3d", "plot.view.energy", "plot.view.slice"}) {
                if (lab.has(tab) && lab.widget(tab).w > 0) {
                    lab.click(lab.widget(tab).cx(), lab.widget(tab).cy());
                    lab.settle();
                    for (std::string& c : clipped(lab, size + " " + name + " " + tab)) {
                        cut.push_back(std::move(c));
                    }
                }
            }
            keep(window(lab), "presenter-" + size + "-" + name);
            lab.moveTo(lab.widget("view").cx(), lab.widget("view").cy());
            lab.press("F1");
            lab.settle();
            for (std::string& c : clipped(lab, size + " " + name + " help")) {
                cut.push_back(std::move(c));
            }
            keep(window(lab), "presenter-" + size + "-" + name + "-help");
            EXPECT_TRUE(cut.empty()) << ::testing::PrintToString(cut);
        }
    }
}

// Preset 13 with `display` (a JSON object) as its opening display, written into `dir`: its path.
std::string withDisplay(const TempFolder& dir, const std::string& display) {
    std::string text = readText(preset("13-cook-torrance-beckmann-schlick"));
    text.insert(text.rfind('}'), ", \"display\": " + display);
    writeText(dir.path() / "with-display.json", text);
    return (dir.path() / "with-display.json").string();
}

// A preset's display.plots opens the plots window on that tab; the next preset (the shipped list's
// first: none names a tab) leaves it.
TEST(GuiLecture, ThePresetsDisplayOpensThePlotsOnItsTab) {
    TempFolder dir;
    START_LAB(lab, "--preset", withDisplay(dir, R"({"plots": "energy"})"), "--size", "1280x800");
    EXPECT_TRUE(lab.has("plot.energy.readout")) << "the preset's display names the Energy tab";
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("Right");
    lab.settle();
    EXPECT_TRUE(lab.has("plot.energy.readout")) << "a preset that names no tab leaves it as it was";
    lab.click(lab.widget("plot.view.plane").cx(), lab.widget("plot.view.plane").cy());
    lab.settle();
    EXPECT_FALSE(lab.has("plot.energy.readout")) << "the tabs decide again once the preset is open";
}

TEST(GuiLecture, AViewThatIsConstantOnTheModelSaysSo) {
    TempFolder dir;
    START_LAB(lab, "--preset", withDisplay(dir, R"({"view": "f"})"), "--size", "1280x800");
    ASSERT_TRUE(lab.has("view.legend")) << "the preset's display opens the F view";
    Rect legend = lab.widget("view.legend");
    EXPECT_GT(legend.w, 0);
    keep(window(lab), "lecture-f-view");
    // The model is one colour (F = 0.04 on a 0-1 palette), not a gradient over 0.04 ... 0.04001.
    Image model = lab.capture(lab.widget("view"));
    int lo = 255, hi = 0;
    for (int y = model.height / 2 - 20; y < model.height / 2 + 20; ++y) {
        const std::uint8_t* p = &model.rgb[(static_cast<std::size_t>(y) * model.width + model.width / 2) * 3];
        lo = std::min<int>(lo, p[1]);
        hi = std::max<int>(hi, p[1]);
    }
    EXPECT_LE(hi - lo, 3) << "F spread over the palette would show a gradient that is 1e-5";
}

} // namespace
} // namespace lab::test
