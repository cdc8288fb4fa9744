// headless_app.h — the interactive lab without a window: App frames rendered offscreen.
//
// The third user of the shared frame sequence (imgui_host.h), beside the desktop window and the
// browser: ImGui on the headless EGL context, each frame drawn into a framebuffer object with a
// fixed time step (1/60 s) and only the input a test gives it. For benchmarks (a full GUI frame)
// and for looking at the GUI where there is no display.
#pragma once

#include "app/app.h"
#include "core/io/image.h"

#include <memory>
#include <string>

namespace lab {

class HeadlessApp {
public:
    HeadlessApp();
    ~HeadlessApp();

    // Needs a current GL context (platform/headless_gl.h). Initializes ImGui and the app.
    bool start(App& app, int width, int height, std::string& error);
    // One frame: App::frame, then ImGui's draw data, into the framebuffer; glFinish.
    FrameOutput frame(FrameInput input = {});
    Image read() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lab
