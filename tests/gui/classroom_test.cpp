// classroom_test.cpp — the lab in front of a class: on a projector's screen, in presenter mode,
// with captions, shipped presets that stay as they are, and a probe that shows where it looks.
//
// GuiFit runs once per screen size (CTest starts an Xvfb of 1024x768, 1280x800 and 1920x1080
// for it); the others run on the GUI suite's screen.
#include "gui_harness.h"

#include "core/exercise/exercise.h"
#include "core/io/image.h"

#include <array>
#include <cstdio>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

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
    // H cycles all / plots and model / model only; presenter mode may have hidden the panel.
    for (int i = 0; i < 3 && !(lab.has("panel") && lab.has("plots")); ++i) {
        lab.press("h");
        lab.settle();
    }
    ASSERT_TRUE(lab.has("panel") && lab.has("plots")) << "H should bring every panel back";
    expectEverythingFits(lab, screenW, screenH, "presenter 2.5x, all panels");
}

bool intersects(const Rect& a, const Rect& b) {
    return a.w > 0 && a.h > 0 && b.w > 0 && b.h > 0 && a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

std::string str(const Rect& r) {
    return "(" + std::to_string(r.x) + " " + std::to_string(r.y) + " " + std::to_string(r.w) + " " + std::to_string(r.h) + ")";
}

// The view's text (header, caption, toast, frame time, compare labels) lies inside the view,
// over neither the model's viewport (each half's, in compare mode) nor another piece of text, and
// no light marker covers any of it. The model itself (F12's picture of the model's viewport,
// outside compare mode) touches none of its viewport's borders: it is whole.
void expectModelWholeAndUncovered(Lab& lab, const std::string& mode) {
    auto rects = lab.layout();
    ASSERT_TRUE(rects.count("view") && rects.count("view.area") && rects.count("view.header")) << mode;
    const Rect area = rects["view.area"];
    std::vector<Rect> models;
    for (const char* name : {"view.a", "view.b"}) {
        if (rects.count(name)) {
            models.push_back(rects[name]);
        }
    }
    if (models.empty()) {
        models.push_back(rects["view"]);
    }
    std::vector<std::pair<std::string, Rect>> text;
    for (const char* name : {"view.header", "view.caption", "view.toast", "view.frame-time", "view.label-a", "view.label-b"}) {
        if (rects.count(name)) {
            text.emplace_back(name, rects[name]);
        }
    }
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto& [name, r] = text[i];
        EXPECT_TRUE(inside(r, area)) << mode << ": " << name << " " << str(r) << " leaves the view " << str(area);
        for (const Rect& model : models) {
            EXPECT_FALSE(intersects(r, model)) << mode << ": " << name << " " << str(r) << " over the model's viewport " << str(model);
        }
        for (std::size_t j = i + 1; j < text.size(); ++j) {
            EXPECT_FALSE(intersects(r, text[j].second)) << mode << ": " << name << " over " << text[j].first;
        }
        for (const auto& [marker, m] : rects) {
            if (marker.rfind("view.light", 0) == 0) {
                EXPECT_FALSE(intersects(r, m)) << mode << ": " << marker << " " << str(m) << " over " << name;
            }
        }
    }
    if (models.size() == 1) {
        Image shot = lab.viewShot();
        ASSERT_GT(shot.width, 2) << mode;
        const std::uint8_t* bg = &shot.rgb[0]; // a corner: the background
        bool touched = false;
        int modelPixels = 0;
        for (int y = 0; y < shot.height; ++y) {
            for (int x = 0; x < shot.width; ++x) {
                const std::uint8_t* p = &shot.rgb[3 * static_cast<std::size_t>(y * shot.width + x)];
                if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 6) {
                    ++modelPixels;
                    touched = touched || x == 0 || y == 0 || x == shot.width - 1 || y == shot.height - 1;
                }
            }
        }
        EXPECT_GT(modelPixels, shot.width * shot.height / 20) << mode << ": the model should fill a fair share of its viewport";
        EXPECT_FALSE(touched) << mode << ": the model is cut at its viewport's border (" << shot.width << "x" << shot.height << ")";
    }
}

// The first seconds a class sees, on each projector's screen: the model whole and no text over
// it — normal (with the start's "Opened" message), in presenter mode (the caption), and in
// compare mode; for a sphere with the default camera and for a glTF model framed by the lab.
TEST(GuiFit, TheModelIsWholeAndNoTextCoversItNormalPresenterAndCompare) {
    for (const char* name : {"05-full-phong", "24-gltf-trefoil"}) {
        START_LAB(lab, "--preset", preset(name));
        lab.settle();
        ASSERT_TRUE(lab.has("view.toast")) << "the start's message is shown";
        expectModelWholeAndUncovered(lab, std::string(name) + " normal");
        Rect view = lab.widget("view");
        lab.moveTo(view.cx(), view.cy());
        lab.press("p");
        lab.settle();
        ASSERT_TRUE(lab.has("view.caption")) << "presenter mode shows the caption";
        expectModelWholeAndUncovered(lab, std::string(name) + " presenter");
        lab.press("c");
        lab.settle();
        expectModelWholeAndUncovered(lab, std::string(name) + " presenter, compare");
        lab.press("p");
        lab.settle();
        expectModelWholeAndUncovered(lab, std::string(name) + " compare");
    }
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

// Plots at the probe: the plots take the probed point's θi, a drag that starts on the probe's
// marker moves the point (not the camera) and the plots follow, and the preset — its plot settings
// included — stays exactly as it was.
TEST(GuiClassroom, PlotsAtTheProbeFollowTheDraggedMarkerAndLeaveThePreset) {
    TempFolder dir;
    const fs::path file = dir.path() / "mine.json";
    fs::copy_file(preset("05-full-phong"), file);
    START_LAB(lab, "--preset", file.string());
    const Rect view = lab.widget("view");
    const Image model = lab.viewShot();
    const Image incidentOff = lab.capture(lab.widget("plot.incident")); // the preset's θi
    lab.click(view.cx(), view.cy());
    ASSERT_TRUE(lab.has("probe.plots-here")) << "the probe's window offers plots at the point";
    // The probe's window opens over the plots: moved aside by its title bar, over the panel.
    const Rect window = lab.widget("probe"), panel = lab.widget("panel");
    lab.drag(window.x + 60, window.y + 8, panel.x + 60, panel.y + panel.h / 3);
    const Rect box = lab.widget("probe.plots-here");
    lab.click(box.x + box.h / 2, box.cy());
    // The slider and the lobe are found again each time: the readout above them grows and shrinks.
    auto incident = [&] { return lab.capture(lab.widget("plot.incident")); };
    auto lobe = [&] { return lab.capture(lab.widget("plot.lobe")); };
    const Image incidentAtCentre = incident(), lobeAtCentre = lobe();
    EXPECT_GT(changedShare(incidentOff, incidentAtCentre), 0.01) << "θi is the point's, not the preset's";

    // The marker dragged up and to the right over the sphere: the probe goes with it.
    const Rect marker = lab.widget("view.probe-marker");
    lab.drag(marker.cx(), marker.cy(), marker.cx() + 90, marker.cy() - 70);
    const Rect moved = lab.widget("view.probe-marker");
    EXPECT_NEAR(moved.cx(), marker.cx() + 90, 8);
    EXPECT_NEAR(moved.cy(), marker.cy() - 70, 8);
    EXPECT_GT(changedShare(incidentAtCentre, incident()), 0.01) << "the plots' θi follows the point";
    EXPECT_GT(changedShare(lobeAtCentre, lobe()), 0.01) << "the lobe follows the point";
    EXPECT_EQ(compareImages(lab.viewShot(), model, Tolerance{}).maxDifference, 0) << "the drag must not orbit the camera";

    // Off again: the preset's own angle, which nothing changed; saved, the preset is as it was.
    lab.click(box.x + box.h / 2, box.cy());
    EXPECT_LT(changedShare(incidentOff, incident()), 0.0005);
    lab.moveTo(view.cx(), view.y + 10);
    lab.press("s", "Control_L");
    lab.settle();
    Diagnostics d;
    std::optional<LoadedPreset> saved = loadPreset(file, d), original = loadPreset(preset("05-full-phong"), d);
    ASSERT_TRUE(saved && original) << toString(d);
    EXPECT_EQ(saved->preset.plotIncidentDeg, original->preset.plotIncidentDeg);
    EXPECT_TRUE(saved->preset == original->preset) << "plots at the probe changed the preset";
}

// What a real decoder (zbarimg) reads in `code`, written as a PNG into `folder`; "" when nothing.
std::string decodedQr(const Image& code, const fs::path& folder) {
    fs::path png = folder / "qr.png";
    std::string error;
    EXPECT_TRUE(writePng(code, png, error)) << error;
    std::string command = std::string(LAB_ZBARIMG) + " --raw -q '" + png.string() + "' 2>/dev/null";
    std::string decoded;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[1024];
        while (std::fgets(buffer, sizeof buffer, pipe)) {
            decoded += buffer;
        }
        ::pclose(pipe);
    }
    return decoded;
}

// Q: the scene's link on the course page (--share-base, remembered in the settings file) as a QR
// code a phone reads: the code captured from the screen decodes, with a real decoder, to the link.
TEST(GuiClassroom, TheQrCodeOnTheScreenDecodesToTheExercisesLinkOnTheCoursePage) {
    TempFolder config;
    ::setenv("XDG_CONFIG_HOME", config.path().c_str(), 1);
    {
        START_LAB(lab, "--preset", std::string(LAB_SOURCE_DIR "/presets/exercises/02-shininess.json"), "--share-base",
                  "https://course.example.org/lab/");
        ::unsetenv("XDG_CONFIG_HOME");
        Rect view = lab.widget("view");
        lab.moveTo(view.cx(), view.cy());
        lab.press("q");
        ASSERT_TRUE(lab.has("share.qr"));
        EXPECT_EQ(decodedQr(lab.capture(lab.widget("share.qr")), config.path()), "https://course.example.org/lab/#exercise=02-shininess\n");
        lab.press("q");
        EXPECT_FALSE(lab.has("share.qr")) << "Q closes it again";
    }
    ::unsetenv("XDG_CONFIG_HOME");
    EXPECT_NE(readText(config.path() / "lighting-lab" / "settings.json").find("https://course.example.org/lab/"),
              std::string::npos)
        << "--share-base is remembered";
}

// The course page's address typed in the QR code's window: one that is not an address is refused
// there with the reason and no code; a good one makes the code at once and is remembered.
TEST(GuiClassroom, TheCourseAddressIsGivenInTheQrWindowAndRemembered) {
    TempFolder config;
    ::setenv("XDG_CONFIG_HOME", config.path().c_str(), 1);
    {
        START_LAB(lab, "--preset", std::string(LAB_SOURCE_DIR "/presets/exercises/02-shininess.json"));
        ::unsetenv("XDG_CONFIG_HOME");
        Rect view = lab.widget("view");
        lab.moveTo(view.cx(), view.cy());
        lab.press("q");
        ASSERT_TRUE(lab.has("share.problem") && lab.has("share.address")) << "no address yet: the window asks for one";
        EXPECT_FALSE(lab.has("share.qr"));
        Rect field = lab.widget("share.address");
        lab.click(field.x + 10, field.cy());
        lab.type("ftp://course.example.org/lab/");
        lab.press("Return");
        lab.settle();
        EXPECT_TRUE(lab.has("share.address-problem")) << "an ftp:// address is refused, with its reason";
        EXPECT_FALSE(lab.has("share.qr"));
        lab.click(field.x + 10, field.cy());
        lab.press("a", "Control_L"); // over the refused text
        lab.type("https://course.example.org/lab/");
        lab.press("Return");
        lab.settle();
        ASSERT_TRUE(lab.has("share.qr")) << "a good address makes the code";
        EXPECT_FALSE(lab.has("share.address-problem"));
        EXPECT_EQ(decodedQr(lab.capture(lab.widget("share.qr")), config.path()), "https://course.example.org/lab/#exercise=02-shininess\n");
    }
    EXPECT_NE(readText(config.path() / "lighting-lab" / "settings.json").find("https://course.example.org/lab/"),
              std::string::npos)
        << "the address given in the window is remembered";
}

// The themes: --theme light paints the UI in the light theme's colours (core/plots/theme.h), the
// panel's radio button turns it dark, and that choice is remembered in the settings file. With
// LAB_THEME_SHOTS set, the window in each theme is written there as a PNG, to be looked at.
TEST(GuiClassroom, TheThemeColoursTheUiAndThePanelsChoiceIsRemembered) {
    TempFolder config;
    ::setenv("XDG_CONFIG_HOME", config.path().c_str(), 1);
    const char* shots = std::getenv("LAB_THEME_SHOTS");
    {
        START_LAB(lab, "--preset", preset("12-blinn-phong"), "--theme", "light");
        ::unsetenv("XDG_CONFIG_HOME"); // the lab has it; the other tests do not
        auto background = [&] { // the panel's background right of the theme's radio buttons
            const Rect r = lab.widget("theme.light");
            const Image spot = lab.capture({r.x + r.w + 6, r.cy(), 1, 1});
            return std::array<int, 3>{spot.rgb[0], spot.rgb[1], spot.rgb[2]};
        };
        auto keep = [&](const char* name) {
            std::string error;
            if (shots && !writePng(lab.capture(lab.widget("window")), fs::path(shots) / name, error)) {
                ADD_FAILURE() << error;
            }
        };
        EXPECT_EQ(background(), (std::array<int, 3>{244, 244, 247})) << "the light theme's window";
        keep("theme-light.png");
        Rect dark = scrolledTo(lab, "theme.dark");
        lab.click(dark.cx(), dark.cy());
        EXPECT_EQ(background(), (std::array<int, 3>{26, 27, 32})) << "the dark theme's window";
        keep("theme-dark.png");
    }
    ::unsetenv("XDG_CONFIG_HOME");
    EXPECT_NE(readText(config.path() / "lighting-lab" / "settings.json").find("\"theme\": \"dark\""), std::string::npos)
        << "the panel's choice is remembered";
}

// Make exercise: the scene is the target; tick the shininess, set its start, title, save: the file
// is an exercise with that field open, and the lab shows it as a student sees it.
TEST(GuiClassroom, MakeExerciseSavesAnExerciseWithTheTickedFieldOpen) {
    TempFolder dir;
    const fs::path file = dir.path() / "made.json";
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Rect make = lab.widget("exercise.make");
    lab.click(make.cx(), make.cy());
    ASSERT_TRUE(lab.has("draft.title"));
    Rect tick = scrolledTo(lab, "open.material.shininess");
    lab.click(tick.cx(), tick.cy());
    Rect shininess = lab.widget("material.shininess");
    lab.moveTo(shininess.x + 20, shininess.cy());
    lab.x().key("Control_L", true);
    lab.click(shininess.x + 20, shininess.cy());
    lab.x().key("Control_L", false);
    lab.press("a", "Control_L");
    lab.type("8");
    lab.press("Return");
    Rect save = scrolledTo(lab, "draft.save"); // the button; its path field is left of it
    lab.click(save.x - 60, save.cy());
    lab.type(file.string());
    lab.press("Return");
    lab.settle();
    Diagnostics d;
    std::optional<LoadedExercise> made = loadExercise(file, d);
    ASSERT_TRUE(made) << toString(d);
    EXPECT_EQ(made->exercise.open, std::vector<std::string>{"material.shininess"});
    EXPECT_EQ(made->exercise.start.material.shininess, 8.0f);
    EXPECT_EQ(made->exercise.target.material.shininess, 32.0f) << "the scene when Make exercise was pressed";
    EXPECT_TRUE(lab.has("exercise.title")) << "the saved exercise opens as a student sees it";
    EXPECT_FALSE(lab.has("material.diffuse"));
}

} // namespace
} // namespace lab::test
