// gui_test.cpp — the interactive lab, driven as a person would drive it.
//
// Each test starts the real `lab` in a real window (CTest runs this under Xvfb), finds widgets
// through the rectangles the lab writes with --layout-file, sends real X input (XTEST), drops
// real files (XDND), and checks the pictures: screenshots of the 3D view the lab writes on F12,
// and captures of the screen. The layout file's frame counter is how a test waits for the lab to
// have seen its input; no test depends on a fixed sleep.
#include "x11_driver.h"

#include "core/image.h"
#include "core/preset.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace lab::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Rect {
    int x = 0, y = 0, w = 0, h = 0;
    int cx() const { return x + w / 2; }
    int cy() const { return y + h / 2; }
};

// One running lab, with helpers to drive it.
class Lab {
public:
    explicit Lab(const std::vector<std::string>& args) {
        layout_ = dir_.path() / "layout.txt";
        shots_ = dir_.path() / "shots";
        fs::create_directories(shots_);
        std::vector<std::string> argv{LAB_EXE, "--layout-file", layout_.string(), "--screenshot-dir", shots_.string()};
        argv.insert(argv.end(), args.begin(), args.end());
        pid_ = ::fork();
        if (pid_ == 0) {
            std::vector<char*> c;
            for (std::string& a : argv) {
                c.push_back(a.data());
            }
            c.push_back(nullptr);
            ::execv(c[0], c.data());
            ::_exit(127);
        }
    }

    ~Lab() {
        if (pid_ > 0) {
            ::kill(pid_, SIGTERM);
            int status = 0;
            ::waitpid(pid_, &status, 0);
        }
    }

    // Waits for the window and its first frames; false if the lab did not come up.
    bool ready() {
        if (!x_.connected()) {
            return false;
        }
        window_ = x_.findWindow("Lighting Lab", 20.0);
        return window_ != 0 && waitFrames(3);
    }

    X11Driver& x() { return x_; }
    unsigned long window() const { return window_; }

    std::map<std::string, Rect> layout() {
        std::map<std::string, Rect> rects;
        std::istringstream in(readText(layout_));
        std::string name;
        while (in >> name) {
            if (name == "frame") {
                in >> frame_;
                continue;
            }
            Rect r;
            in >> r.x >> r.y >> r.w >> r.h;
            rects[name] = r;
        }
        return rects;
    }

    bool has(const std::string& widget) { return layout().count(widget) > 0; }

    Rect widget(const std::string& name) {
        auto rects = layout();
        auto it = rects.find(name);
        EXPECT_NE(it, rects.end()) << "no widget \"" << name << "\" in the layout";
        return it == rects.end() ? Rect{} : it->second;
    }

    bool waitFrames(unsigned long long n) {
        layout();
        unsigned long long target = frame_ + n;
        auto end = Clock::now() + std::chrono::seconds(30);
        while (Clock::now() < end) {
            layout();
            if (frame_ >= target) {
                return true;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return false;
    }

    void moveTo(int wx, int wy) {
        int sx = wx, sy = wy;
        x_.toScreen(window_, sx, sy);
        x_.moveMouse(sx, sy);
        waitFrames(1);
    }

    void click(int wx, int wy, int times = 1) {
        moveTo(wx, wy);
        for (int i = 0; i < times; ++i) {
            x_.button(1, true);
            waitFrames(1);
            x_.button(1, false);
            waitFrames(1);
        }
    }

    // Drags with the left button from (x0, y0) to (x1, y1) in window coordinates, in steps.
    void drag(int x0, int y0, int x1, int y1) {
        moveTo(x0, y0);
        x_.button(1, true);
        waitFrames(1);
        for (int i = 1; i <= 5; ++i) {
            moveTo(x0 + (x1 - x0) * i / 5, y0 + (y1 - y0) * i / 5);
        }
        x_.button(1, false);
        waitFrames(2);
    }

    // Presses and releases a key, held across frames so ImGui 1.86's polling sees it.
    void press(const std::string& key, const std::string& modifier = "") {
        if (!modifier.empty()) {
            x_.key(modifier, true);
        }
        x_.key(key, true);
        waitFrames(2);
        x_.key(key, false);
        if (!modifier.empty()) {
            x_.key(modifier, false);
        }
        waitFrames(2);
    }

    void type(const std::string& text) {
        x_.type(text);
        waitFrames(2);
    }

    // F12, then the PNG of the 3D view the lab writes.
    Image viewShot() {
        std::set<fs::path> before = files();
        press("F12");
        fs::path added;
        auto end = Clock::now() + std::chrono::seconds(20);
        while (added.empty() && Clock::now() < end) {
            for (const fs::path& f : files()) {
                if (!before.count(f)) {
                    added = f;
                }
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        std::string error = "none was written";
        std::optional<Image> image = added.empty() ? std::nullopt : readPng(added, error);
        EXPECT_TRUE(image) << "no screenshot from F12: " << error;
        return image.value_or(Image{});
    }

    // The screen inside a widget's rectangle, after the lab has drawn two more frames.
    Image capture(const Rect& r) {
        waitFrames(2);
        int sx = r.x, sy = r.y;
        x_.toScreen(window_, sx, sy);
        return x_.capture(sx, sy, r.w, r.h);
    }

private:
    std::set<fs::path> files() const {
        std::set<fs::path> all;
        for (const fs::directory_entry& e : fs::directory_iterator(shots_)) {
            all.insert(e.path());
        }
        return all;
    }

    TempFolder dir_;
    fs::path layout_, shots_;
    pid_t pid_ = -1;
    X11Driver x_;
    unsigned long window_ = 0;
    unsigned long long frame_ = 0;
};

//----------------------------------------------------------------------------------------
// Picture measurements
//----------------------------------------------------------------------------------------

double meanChannel(const Image& image, int channel) {
    double sum = 0;
    for (std::size_t i = static_cast<std::size_t>(channel); i < image.rgb.size(); i += 3) {
        sum += image.rgb[i];
    }
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size() / 3);
}

int brightest(const Image& image) {
    int best = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        best = std::max(best, (image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2]) / 3);
    }
    return best;
}

// Share of pixels whose channels differ by more than 8 levels.
double changedShare(const Image& a, const Image& b) {
    Comparison c = compareImages(a, b, Tolerance{8, 0.0, 0.0});
    return c.sameSize ? c.failingShare : 1.0;
}

// Pixels that look like the lab's red error text (255, 150, 140) or log text (255, 120, 110).
int reddishPixels(const Image& image) {
    int n = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        n += image.rgb[i] > 180 && image.rgb[i + 1] < 170 && image.rgb[i + 2] < 160 && image.rgb[i] > image.rgb[i + 1] + 60;
    }
    return n;
}

std::string preset(const std::string& name) { return std::string(LAB_SOURCE_DIR) + "/presets/" + name + ".json"; }

#define START_LAB(lab, ...)                                                                        \
    Lab lab({__VA_ARGS__});                                                                        \
    ASSERT_TRUE(lab.ready()) << "the lab did not open a window (is DISPLAY set? CTest runs this under xvfb-run)"

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

TEST(Gui, DroppedBrokenPresetShowsTheErrorAndKeepsTheScene) {
    START_LAB(lab, "--preset", preset("05-full-phong"));
    Image before = lab.viewShot();
    Rect view = lab.widget("view");
    std::string error;
    ASSERT_TRUE(lab.x().dropFile(lab.window(), std::string(LAB_SOURCE_DIR) + "/tests/data/broken.json", view.cx(),
                                 view.cy(), error))
        << error;
    lab.waitFrames(3);
    ASSERT_TRUE(lab.has("error")) << "no error window after dropping a broken preset";
    EXPECT_GT(reddishPixels(lab.capture(lab.widget("error"))), 50) << "the validator's messages should be shown";
    lab.moveTo(view.cx(), view.cy());
    lab.press("Escape");
    EXPECT_FALSE(lab.has("error"));
    Image after = lab.viewShot();
    EXPECT_EQ(compareImages(after, before, Tolerance{}).maxDifference, 0) << "the scene must be exactly as it was";

    // A good preset dropped the same way does open: the drop path is real.
    ASSERT_TRUE(lab.x().dropFile(lab.window(), preset("01-ambient-only"), view.cx(), view.cy(), error)) << error;
    lab.waitFrames(3);
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
    ASSERT_TRUE(lab.x().dropFile(lab.window(), std::string(LAB_SOURCE_DIR) + "/presets/models/trefoil.glb", view.cx(),
                                 view.cy(), error))
        << error;
    lab.waitFrames(3);
    EXPECT_FALSE(lab.has("error"));
    EXPECT_GT(changedShare(lab.viewShot(), sphere), 0.05) << "the knot should replace the sphere";
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
    lab.waitFrames(2);
    Diagnostics d;
    std::optional<LoadedPreset> saved = loadPreset(file, d);
    ASSERT_TRUE(saved) << toString(d);
    EXPECT_EQ(saved->preset.shading, Shading::Flat);
    EXPECT_EQ(saved->preset.material.diffuse, glm::vec3(0.8f, 0.25f, 0.2f)); // the rest as it was
}

} // namespace
} // namespace lab::test
