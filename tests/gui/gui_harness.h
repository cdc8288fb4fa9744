// gui_harness.h — the interactive lab, driven as a person would drive it: the harness.
//
// Each test starts the real `lab` in a real window (CTest runs this under Xvfb), finds widgets
// through the rectangles the lab writes with --layout-file, sends real X input (XTEST), drops
// real files (XDND), and checks the pictures: screenshots of the 3D view the lab writes on F12,
// and captures of the screen. The lab draws only when something changes (app/frame_pacer.h), so
// a test waits for it to settle: the layout file's frame counter has moved past the frame before
// the input, and its last frame says no more are due ("settled 1"). No test depends on a fixed
// sleep.
#pragma once

#include "x11_driver.h"

#include "core/io/image.h"
#include "core/scene/preset.h"
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
        return window_ != 0 && settle(0);
    }

    X11Driver& x() { return x_; }
    pid_t pid() const { return pid_; }
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
            if (name == "settled") {
                in >> settled_;
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

    // The frames drawn so far (the layout file's counter).
    unsigned long long frame() {
        layout();
        return frame_;
    }

    // Waits until the lab has drawn past frame `since` and owes no more frames: whatever input
    // came after `since` has been seen and shown. Input that makes no event at all (a move to
    // where the cursor already is) draws nothing: after 1.5 s without a frame that is settled too.
    bool settle(unsigned long long since) {
        auto start = Clock::now(), end = start + std::chrono::seconds(30);
        while (Clock::now() < end) {
            layout();
            if (settled_ && (frame_ > since || Clock::now() > start + std::chrono::milliseconds(1500))) {
                return true;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        ADD_FAILURE() << "the lab did not settle within 30 s (frame " << frame_ << ")";
        return false;
    }
    // ... since the harness's last input.
    bool settle() { return settle(sent_); }

    void moveTo(int wx, int wy) {
        int sx = wx, sy = wy;
        x_.toScreen(window_, sx, sy);
        send([&] { x_.moveMouse(sx, sy); });
    }

    void click(int wx, int wy, int times = 1) {
        moveTo(wx, wy);
        for (int i = 0; i < times; ++i) {
            send([&] { x_.button(1, true); });
            send([&] { x_.button(1, false); });
        }
    }

    // Presses the left button at (wx, wy) and keeps it down until release(): the lab has seen it.
    void hold(int wx, int wy) {
        moveTo(wx, wy);
        send([&] { x_.button(1, true); });
    }
    void release() {
        send([&] { x_.button(1, false); });
    }

    // Drags with the left button from (x0, y0) to (x1, y1) in window coordinates, in steps.
    void drag(int x0, int y0, int x1, int y1) {
        moveTo(x0, y0);
        send([&] { x_.button(1, true); });
        for (int i = 1; i <= 5; ++i) {
            moveTo(x0 + (x1 - x0) * i / 5, y0 + (y1 - y0) * i / 5);
        }
        send([&] { x_.button(1, false); });
    }

    // Drops a real file (XDND) at (wx, wy) in window coordinates.
    bool drop(const std::string& path, int wx, int wy, std::string& error) {
        bool ok = false;
        send([&] { ok = x_.dropFile(window_, path, wx, wy, error); });
        return ok;
    }

    // Presses and releases a key at once: the lab queues both (app/input.h), so a press
    // shorter than a frame still counts.
    void press(const std::string& key, const std::string& modifier = "") {
        send([&] {
            if (!modifier.empty()) {
                x_.key(modifier, true);
            }
            x_.key(key, true);
            x_.key(key, false);
            if (!modifier.empty()) {
                x_.key(modifier, false);
            }
        });
    }

    void type(const std::string& text) {
        send([&] { x_.type(text); });
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

    // The files the lab has written into its screenshot folder (screenshots, sweeps, figures).
    std::set<fs::path> shotFiles() const { return files(); }

    // The screen inside a widget's rectangle, once the lab has settled.
    Image capture(const Rect& r) {
        settle();
        int sx = r.x, sy = r.y;
        x_.toScreen(window_, sx, sy);
        return x_.capture(sx, sy, r.w, r.h);
    }

private:
    // Sends input, and waits for the lab to have shown its effect.
    template <class F>
    void send(F&& input) {
        sent_ = frame();
        input();
        settle();
    }

    // The finished files only: the lab writes each through a hidden ".NAME.tmp-XXXXXX" it then
    // renames, and a listing taken in between would name a file that is gone when it is read.
    std::set<fs::path> files() const {
        std::set<fs::path> all;
        for (const fs::directory_entry& e : fs::directory_iterator(shots_)) {
            if (e.path().filename().string().rfind('.', 0) != 0) {
                all.insert(e.path());
            }
        }
        return all;
    }

    TempFolder dir_;
    fs::path layout_, shots_;
    pid_t pid_ = -1;
    X11Driver x_;
    unsigned long window_ = 0;
    unsigned long long frame_ = 0, sent_ = 0;
    int settled_ = 0;
};

//----------------------------------------------------------------------------------------
// Picture measurements
//----------------------------------------------------------------------------------------

inline double meanChannel(const Image& image, int channel) {
    double sum = 0;
    for (std::size_t i = static_cast<std::size_t>(channel); i < image.rgb.size(); i += 3) {
        sum += image.rgb[i];
    }
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size() / 3);
}

inline int brightest(const Image& image) {
    int best = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        best = std::max(best, (image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2]) / 3);
    }
    return best;
}

// Share of pixels whose channels differ by more than 8 levels.
inline double changedShare(const Image& a, const Image& b) {
    Comparison c = compareImages(a, b, Tolerance{8, 0.0, 0.0});
    return c.sameSize ? c.failingShare : 1.0;
}

// Pixels that look like the lab's red error text (255, 150, 140) or log text (255, 120, 110).
inline int reddishPixels(const Image& image) {
    int n = 0;
    for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        n += image.rgb[i] > 180 && image.rgb[i + 1] < 170 && image.rgb[i + 2] < 160 && image.rgb[i] > image.rgb[i + 1] + 60;
    }
    return n;
}

inline std::string preset(const std::string& name) { return std::string(LAB_SOURCE_DIR) + "/presets/" + name + ".json"; }

// Scrolls the control panel (the wheel over it) until `widget` is inside the window: down while it
// is below the view's bottom, up while it is above its top. The wheel goes where the widget's column
// meets the middle of the view, or, where something there takes the wheel for itself (the preset
// list at the end of its own scrolling), a quarter or three quarters of the way down.
inline Rect scrolledTo(Lab& lab, const std::string& widget) {
    Rect area = lab.widget("view.area"), w = lab.widget(widget);
    const int heights[] = {area.y + area.h / 2, area.y + area.h / 4, area.y + 3 * area.h / 4};
    int at = 0;
    for (int i = 0; i < 40 && (w.y + w.h > area.y + area.h - 4 || w.y < area.y); ++i) {
        const int button = w.y < area.y ? 4 : 5;
        lab.moveTo(w.x + 4, heights[at]);
        unsigned long long before = lab.frame();
        lab.x().button(button, true);
        lab.x().button(button, false);
        lab.settle(before);
        const int was = w.y;
        w = lab.widget(widget);
        at = w.y == was ? (at + 1) % 3 : at; // the panel did not move: the wheel went elsewhere
    }
    return w;
}

#define START_LAB(lab, ...)                                                                        \
    Lab lab({__VA_ARGS__});                                                                        \
    ASSERT_TRUE(lab.ready()) << "the lab did not open a window (is DISPLAY set? CTest runs this under xvfb-run)"

} // namespace lab::test
