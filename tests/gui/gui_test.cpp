// gui_test.cpp — the interactive lab, driven as a person would drive it.
//
// Each test starts the real `lab` in a real window (CTest runs this under Xvfb); the harness
// (gui_harness.h) finds widgets through --layout-file, sends real X input and drops real files.
#include "gui_harness.h"

namespace lab::test {
namespace {

namespace fs = std::filesystem;

//----------------------------------------------------------------------------------------
// The tests
//----------------------------------------------------------------------------------------

TEST(Gui, EditingTheDiffuseColourChangesTheRender) {
    START_LAB(lab, "--preset", preset("02-diffuse-only"));
    Image before = lab.viewShot();
    Rect diffuse = lab.widget("material.diffuse");
    // The R field of the colour editor: Ctrl+click to type a number (a double-click would depend
    // on two clicks landing within ImGui's 0.3 s, which slow frames under load can miss), Enter.
    lab.moveTo(diffuse.x + 20, diffuse.cy());
    lab.x().key("Control_L", true);
    lab.click(diffuse.x + 20, diffuse.cy());
    lab.x().key("Control_L", false);
    lab.type("0.1");
    lab.press("Return");
    Image after = lab.viewShot();
    EXPECT_LT(meanChannel(after, 0), meanChannel(before, 0) - 15.0) << "the sphere should have lost most of its red";
    EXPECT_NEAR(meanChannel(after, 1), meanChannel(before, 1), 2.0) << "green was not edited";
}

TEST(Gui, FlatGouraudPhongChangeTheHighlight) {
    START_LAB(lab, "--preset", preset("09-coarse-flat"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy()); // keyboard focus follows the pointer without a window manager
    lab.press("1");
    Image flat = lab.viewShot();
    lab.press("2");
    Image gouraud = lab.viewShot();
    lab.press("3");
    Image phong = lab.viewShot();
    // Phong shading finds the sharp highlight that Gouraud's vertices miss.
    EXPECT_GT(brightest(phong), brightest(gouraud) + 40) << "phong " << brightest(phong) << ", gouraud " << brightest(gouraud);
    EXPECT_GT(changedShare(flat, gouraud), 0.02) << "flat facets should differ from Gouraud's gradients";
    EXPECT_GT(changedShare(gouraud, phong), 0.001);
}

TEST(Gui, PolarPlotFollowsTheShininess) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Rect plot = lab.widget("plot.lobe");
    Image before = lab.capture(plot);
    Rect shininess = lab.widget("material.shininess");
    lab.drag(shininess.x + shininess.w / 2, shininess.cy(), shininess.x + shininess.w - 4, shininess.cy());
    Image after = lab.capture(plot);
    EXPECT_GT(changedShare(before, after), 0.005) << "a sharper exponent should narrow the drawn lobe";
    // One drag is one undo step: Ctrl+Z brings the plot back exactly.
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("z", "Control_L");
    Image undone = lab.capture(plot);
    EXPECT_LT(changedShare(before, undone), 0.0005);
}

// The plots window's "3D lobe" tab opens, draws the lobe inside its window, and a drag orbits it.
TEST(Gui, TheLobe3dTabOpensAndADragOrbitsIt) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Rect tab = lab.widget("plot.view.lobe3d");
    lab.click(tab.cx(), tab.cy());
    ASSERT_TRUE(lab.has("plot.lobe3d") && lab.has("plot.lobe3d.map"));
    EXPECT_FALSE(lab.has("plot.lobe")) << "the plane plots give way to the 3D view";
    Rect lobe = lab.widget("plot.lobe3d"), plots = lab.widget("plots");
    EXPECT_TRUE(lobe.x >= plots.x && lobe.y >= plots.y && lobe.x + lobe.w <= plots.x + plots.w &&
                lobe.y + lobe.h <= plots.y + plots.h)
        << "the 3D lobe lies inside the plots' window";
    Image before = lab.capture(lobe);
    lab.drag(lobe.cx(), lobe.cy(), lobe.cx() + lobe.w / 4, lobe.cy() + lobe.h / 8);
    Image after = lab.capture(lobe);
    EXPECT_GT(changedShare(before, after), 0.02) << "a drag in the 3D lobe should orbit it";
}

TEST(Gui, DroppedBrokenPresetShowsTheErrorAndKeepsTheScene) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Image before = lab.viewShot();
    Rect view = lab.widget("view");
    std::string error;
    ASSERT_TRUE(lab.drop(std::string(LAB_SOURCE_DIR) + "/tests/data/broken.json", view.cx(),
                                 view.cy(), error))
        << error;
    lab.settle();
    ASSERT_TRUE(lab.has("error")) << "no error window after dropping a broken preset";
    EXPECT_GT(reddishPixels(lab.capture(lab.widget("error"))), 50) << "the validator's messages should be shown";
    lab.moveTo(view.cx(), view.cy());
    lab.press("Escape");
    EXPECT_FALSE(lab.has("error"));
    Image after = lab.viewShot();
    EXPECT_EQ(compareImages(after, before, Tolerance{}).maxDifference, 0) << "the scene must be exactly as it was";

    // A good preset dropped the same way does open: the drop path is real.
    ASSERT_TRUE(lab.drop(preset("01-ambient-only"), view.cx(), view.cy(), error)) << error;
    lab.settle();
    EXPECT_GT(changedShare(lab.viewShot(), before), 0.05);
}

TEST(Gui, BrokenShaderShowsItsLogAndTheModelStillRenders) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Image before = lab.viewShot();
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("e", "Control_L");
    Rect editor = lab.widget("shader.fragment");
    lab.click(editor.cx(), editor.cy());
    lab.press("a", "Control_L");
    lab.type("void main() { oops; }");
    lab.press("Return", "Control_L");
    ASSERT_TRUE(lab.has("shader.log"));
    EXPECT_GT(reddishPixels(lab.capture(lab.widget("shader.log"))), 30) << "the compile log should be shown in red";
    Image after = lab.viewShot();
    EXPECT_EQ(compareImages(after, before, Tolerance{}).maxDifference, 0) << "the previous shaders keep rendering";
}

TEST(Gui, UndoAndRedoFromTheKeyboard) {
    START_LAB(lab, "--preset", preset("11-coarse-phong"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    Image phong = lab.viewShot();
    lab.press("1");
    Image flat = lab.viewShot();
    ASSERT_GT(changedShare(phong, flat), 0.02);
    lab.press("z", "Control_L");
    EXPECT_EQ(compareImages(lab.viewShot(), phong, Tolerance{}).maxDifference, 0);
    lab.press("y", "Control_L");
    EXPECT_EQ(compareImages(lab.viewShot(), flat, Tolerance{}).maxDifference, 0);
}

TEST(Gui, ArrowKeysStepThroughThePresets) {
    START_LAB(lab, "--preset", preset("01-ambient-only"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    Image first = lab.viewShot();
    lab.press("Right");
    Image second = lab.viewShot();
    EXPECT_GT(changedShare(first, second), 0.05) << "02-diffuse-only should look different from 01-ambient-only";
    lab.press("Left");
    EXPECT_EQ(compareImages(lab.viewShot(), first, Tolerance{}).maxDifference, 0);
}

TEST(Gui, DroppedGltfModelIsLoaded) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Image sphere = lab.viewShot();
    Rect view = lab.widget("view");
    std::string error;
    ASSERT_TRUE(lab.drop(std::string(LAB_SOURCE_DIR) + "/presets/models/trefoil.glb", view.cx(),
                                 view.cy(), error))
        << error;
    lab.settle();
    EXPECT_FALSE(lab.has("error"));
    EXPECT_GT(changedShare(lab.viewShot(), sphere), 0.05) << "the knot should replace the sphere";
    // The drop framed the knot in the same undo step: one Ctrl+Z brings back the sphere and its camera.
    lab.moveTo(view.cx(), view.cy());
    lab.press("z", "Control_L");
    EXPECT_EQ(compareImages(lab.viewShot(), sphere, Tolerance{}).maxDifference, 0);
}

TEST(Gui, FFramesTheModelAndCtrlZUndoesIt) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    Image before = lab.viewShot();
    lab.press("f");
    EXPECT_GT(changedShare(lab.viewShot(), before), 0.02) << "framed, the sphere fills more of the view";
    lab.press("z", "Control_L");
    EXPECT_EQ(compareImages(lab.viewShot(), before, Tolerance{}).maxDifference, 0);
}

// An idle lab draws nothing (issue 12: it used to redraw continuously, 150% CPU under llvmpipe),
// and the frame after a key press shows the press on the screen.
TEST(Gui, AnIdleLabDrawsNothingAndAKeyPressIsShownAtOnce) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    Image before = lab.capture(view);
    unsigned long long idleFrom = lab.frame();
    std::this_thread::sleep_for(std::chrono::seconds(2));
    EXPECT_LE(lab.frame() - idleFrom, 2u) << "frames drawn in 2 s without input";
    lab.press("1"); // flat shading
    EXPECT_GT(lab.frame(), idleFrom) << "the key press should draw";
    EXPECT_GT(changedShare(lab.capture(view), before), 0.02) << "the settled frame after the press shows flat shading";
}

TEST(Gui, CtrlSSavesTheEditsToThePresetFile) {
    TempFolder dir;
    fs::path file = dir.path() / "mine.json";
    fs::copy_file(preset("05-full-phong"), file);
    START_LAB(lab, "--preset", file.string());
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("1");
    lab.press("s", "Control_L");
    lab.settle();
    Diagnostics d;
    std::optional<LoadedPreset> saved = loadPreset(file, d);
    ASSERT_TRUE(saved) << toString(d);
    EXPECT_EQ(saved->preset.shading, Shading::Flat);
    EXPECT_EQ(saved->preset.material.diffuse, glm::vec3(0.8f, 0.25f, 0.2f)); // the rest as it was
}

// A preset whose light orbits: the live view changes by itself, the screenshot (F12) is the
// preset's light position whenever it is taken, and the motion pauses while a slider is held.
TEST(Gui, AMovingLightMovesTheViewButNotTheScreenshotAndPausesWhileHeld) {
    // Always at full resolution: a slow frame while the slider is held (a drag, to the lab) would
    // otherwise draw the view at a lower resolution, and the pictures compared would differ by that.
    START_LAB(lab, "--preset", preset("25-moving-light"), "--frame-budget", "0");
    const Rect view = lab.widget("view");
    Image shotBefore = lab.viewShot();
    Image first = lab.capture(view);
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    Image later = lab.capture(view);
    EXPECT_GT(changedShare(first, later), 0.002) << "the highlight should travel as the light orbits";
    Image shotAfter = lab.viewShot();
    EXPECT_LT(changedShare(shotBefore, shotAfter), 0.0005) << "screenshots show the preset's position";
    // Held on the shininess slider (pressed, not moved): the orbit waits.
    const Rect shininess = lab.widget("material.shininess");
    lab.hold(shininess.cx(), shininess.cy());
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    Image held = lab.capture(view);
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    Image stillHeld = lab.capture(view);
    lab.release();
    EXPECT_LT(changedShare(held, stillHeld), 0.0005) << "the light should pause while a slider is held";
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    EXPECT_GT(changedShare(stillHeld, lab.capture(view)), 0.002) << "and go on when it is let go";
}

TEST(Gui, SweepShowsTheGridAndARefusedValue) {
    START_LAB(lab, "--preset", preset("06-shininess-10"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("g", "Control_L");
    ASSERT_TRUE(lab.has("sweep.grid")) << "Ctrl+G should show the sweep's grid";
    // The default sweep (shininess 10..50 against k_s 0.2..1): cells on a white page, each a blue
    // sphere on the preset's dark background.
    Image grid = lab.capture(lab.widget("sweep.grid"));
    int white = 0, dark = 0, blue = 0;
    for (std::size_t i = 0; i + 2 < grid.rgb.size(); i += 3) {
        int r = grid.rgb[i], g = grid.rgb[i + 1], b = grid.rgb[i + 2];
        white += r > 240 && g > 240 && b > 240;
        dark += r < 30 && g < 30 && b < 40;
        blue += b > r + 40 && b > 80;
    }
    const double pixels = static_cast<double>(grid.width) * grid.height;
    EXPECT_GT(white / pixels, 0.05) << "the page around the cells";
    EXPECT_GT(dark / pixels, 0.2) << "the cells' background";
    EXPECT_GT(blue / pixels, 0.05) << "the spheres";
    // A value out of range: nothing while it is typed, then (Enter) the reader's message in red,
    // and Save PNG is off.
    Rect values = lab.widget("sweep.values1");
    lab.click(values.cx(), values.cy());
    lab.press("a", "Control_L");
    lab.type("10,-5");
    EXPECT_FALSE(lab.has("sweep.error")) << "the grid waits for the end of the typing";
    lab.press("Return");
    ASSERT_TRUE(lab.has("sweep.error"));
    EXPECT_GT(reddishPixels(lab.capture(lab.widget("sweep.error"))), 30) << "the refusal should be shown in red";
    Rect save = lab.widget("sweep.save");
    lab.click(save.cx(), save.cy());
    EXPECT_TRUE(lab.shotFiles().empty()) << "Save PNG is off while a value is refused";
    // A key typed (any key the command line takes), values, Enter: Save PNG writes the grid that
    // `lab render --sweep` writes with the same arguments and cells.
    Rect key = lab.widget("sweep.key1");
    lab.click(key.cx(), key.cy());
    lab.press("a", "Control_L");
    lab.type("lights[0].attenuation[2]");
    values = lab.widget("sweep.values1");
    lab.click(values.cx(), values.cy());
    lab.press("a", "Control_L");
    lab.type("0,0.1");
    lab.press("Return");
    EXPECT_FALSE(lab.has("sweep.error"));
    save = lab.widget("sweep.save");
    lab.click(save.cx(), save.cy());
    std::set<fs::path> saved = lab.shotFiles();
    ASSERT_EQ(saved.size(), 1u) << "Save PNG should write one file";
    EXPECT_NE(saved.begin()->filename().string().find("-sweep-"), std::string::npos) << saved.begin()->filename();
    TempFolder dir;
    std::string command = std::string(LAB_EXE) + " render " + preset("06-shininess-10") +
                          " --sweep 'lights[0].attenuation[2]=0,0.1' --sweep material.specular=0.2,0.5,1 --size 256x256 --out " +
                          (dir.path() / "grid.png").string() + " > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::string error;
    std::optional<Image> fromGui = readPng(*saved.begin(), error), fromCli = readPng(dir.path() / "grid.png", error);
    ASSERT_TRUE(fromGui && fromCli) << error;
    Comparison c = compareImages(*fromGui, *fromCli, Tolerance{});
    EXPECT_TRUE(c.passes(Tolerance{})) << "max " << c.maxDifference << ", failing share " << c.failingShare;
}

// The frame time is what a frame costs while the model changes (app/frame_speed.h): nothing at
// the start (whose first frames compile and upload), shown during a drag and a few seconds after,
// gone when idle; T hides it; presenter mode shows none until T.
TEST(Gui, TheFrameTimeShowsWhileTheModelChangesAndNotWhenIdle) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    EXPECT_FALSE(lab.has("view.frame-time")) << "no frame time before anything changed";
    Rect view = lab.widget("view");
    auto orbit = [&] { lab.drag(view.cx() - 60, view.cy(), view.cx() + 60, view.cy() + 20); };
    orbit();
    EXPECT_TRUE(lab.has("view.frame-time")) << "a drag shows what its frames cost";
    auto end = Clock::now() + std::chrono::seconds(10);
    while (lab.has("view.frame-time") && Clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50)); // the lab redraws to hide it (3 s)
    }
    EXPECT_FALSE(lab.has("view.frame-time")) << "idle, the frame time goes";
    lab.press("t");
    orbit();
    EXPECT_FALSE(lab.has("view.frame-time")) << "T hides it";
    lab.press("t");
    lab.press("p");
    lab.settle();
    view = lab.widget("view");
    orbit();
    EXPECT_FALSE(lab.has("view.frame-time")) << "presenter mode shows none";
    lab.press("t");
    orbit();
    EXPECT_TRUE(lab.has("view.frame-time")) << "... until asked (T)";
}

// The columns [x0, x1) of an image.
Image columns(const Image& image, int x0, int x1) {
    Image out{x1 - x0, image.height, {}};
    for (int y = 0; y < image.height; ++y) {
        auto row = image.rgb.begin() + (std::ptrdiff_t(y) * image.width + x0) * 3;
        out.rgb.insert(out.rgb.end(), row, row + std::ptrdiff_t(x1 - x0) * 3);
    }
    return out;
}

// The equation's D button shows D across the model (issue 26): the picture changes, the legend
// strip appears under the model, not over it, with the value under the pointer; the wipe brings
// the lit model back left of its divider, and a drag on the divider moves it.
TEST(Gui, AFactorButtonShowsItOnTheModelWithItsLegendAndTheWipeSplitsIt) {
    START_LAB(lab, "--preset", preset("13-cook-torrance-beckmann-schlick"));
    Image lit = lab.viewShot();
    EXPECT_FALSE(lab.has("view.legend")) << "the lit model has no legend";
    Rect d = scrolledTo(lab, "equation.d");
    lab.click(d.cx(), d.cy());
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy()); // on the model: its value is read under the pointer
    Image dView = lab.viewShot();
    ASSERT_FALSE(dView.rgb.empty());
    auto corner = [](const Image& image) { return int(image.rgb[0]) + image.rgb[1] + image.rgb[2]; };
    EXPECT_GT(corner(lit), 20) << "the preset's background";
    EXPECT_EQ(corner(dView), 0) << "a value view is drawn on black";
    ASSERT_TRUE(lab.has("view.legend"));
    Rect legend = lab.widget("view.legend");
    EXPECT_GE(legend.y, view.y + view.h) << "the legend is under the model, not over it";
    EXPECT_TRUE(lab.has("view.legend-bar"));
    Rect wipe = scrolledTo(lab, "equation.wipe");
    lab.click(wipe.x + 8, wipe.cy());
    ASSERT_TRUE(lab.has("view.wipe"));
    view = lab.widget("view");
    Rect handle = lab.widget("view.wipe");
    EXPECT_NEAR(handle.cx(), view.cx(), 3) << "the divider starts in the middle";
    Image wiped = lab.viewShot();
    ASSERT_EQ(wiped.width, dView.width);
    int half = wiped.width / 2;
    EXPECT_EQ(corner(wiped), corner(lit)) << "the lit model (and its background) left of the divider";
    EXPECT_GT(changedShare(columns(wiped, 0, half - 4), columns(dView, 0, half - 4)), 0.2) << "not D left of it";
    EXPECT_LT(changedShare(columns(wiped, half + 4, wiped.width), columns(dView, half + 4, dView.width)), 0.01)
        << "D right of it";
    lab.drag(handle.cx(), handle.cy(), view.x + view.w / 4, handle.cy());
    EXPECT_NEAR(lab.widget("view.wipe").cx(), view.x + view.w / 4, 4) << "the drag moved the divider";
    Image moved = lab.viewShot();
    int quarter = moved.width / 4;
    EXPECT_LT(changedShare(columns(moved, quarter + 4, moved.width), columns(dView, quarter + 4, dView.width)), 0.01)
        << "D right of the moved divider: the camera did not turn";
}

// An exercise (presets/exercises/02-shininess.json, opened from the panel's list): only its open field is on the panel, the
// target is beside the attempt, and typing the exponent that matches it shows "Solved".
TEST(Gui, AnExerciseShowsOnlyItsOpenFieldsAndReachingTheTargetSaysSolved) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    EXPECT_FALSE(lab.has("exercise.title"));
    Rect open = scrolledTo(lab, "exercises.02-shininess"); // the shipped exercises under the preset list
    lab.click(open.cx(), open.cy());
    ASSERT_TRUE(lab.has("exercise.title"));
    EXPECT_TRUE(lab.has("exercise.score")) << "the start is scored";
    EXPECT_FALSE(lab.has("exercise.solved")) << "the start does not solve it";
    EXPECT_TRUE(lab.has("view.b")) << "the target is drawn beside the attempt";
    EXPECT_TRUE(lab.has("material.shininess")) << "the open field";
    for (const char* locked : {"material.diffuse", "material.specular", "lights.add", "shading.flat", "brdf.Phong",
                               "ambient_light", "background", "compare", "exercise.make"}) {
        EXPECT_FALSE(lab.has(locked)) << locked << " is not open in this exercise";
    }
    Image target = lab.capture(lab.widget("view.b"));
    Rect shininess = lab.widget("material.shininess");
    lab.moveTo(shininess.x + 20, shininess.cy());
    lab.x().key("Control_L", true);
    lab.click(shininess.x + 20, shininess.cy());
    lab.x().key("Control_L", false);
    lab.type("78");
    lab.press("Return");
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    ASSERT_TRUE(lab.has("exercise.solved")) << "78 for the target's 80 is within the tolerance";
    EXPECT_LT(changedShare(target, lab.capture(lab.widget("view.b"))), 0.001) << "the target does not change";
    // Start again: back to the exponent 8, not solved; Undo brings the attempt back.
    Rect reset = lab.widget("exercise.reset");
    lab.click(reset.cx(), reset.cy());
    lab.moveTo(view.cx(), view.cy());
    EXPECT_FALSE(lab.has("exercise.solved"));
    lab.press("z", "Control_L");
    EXPECT_TRUE(lab.has("exercise.solved")) << "undo brings the solved attempt back";
}

} // namespace
} // namespace lab::test
