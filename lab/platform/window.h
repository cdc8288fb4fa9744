// window.h — the platform seam for the interactive lab: a window, its loop, and ImGui's
// platform and renderer backends, around App::frame().
//
// One implementation is compiled per target: glfw_window.cpp on the desktop (a GLFW window with
// an OpenGL ES 3 context through EGL, the same GL the headless renderer and WebGL2 use), and a
// browser one for the WebAssembly build. Each provides exactly this function.
#pragma once

#include "app/app.h"

#include <string>

namespace lab {

struct WindowOptions {
    int width = 1600;
    int height = 900;
    bool fullscreen = false;
};

enum class WindowResult { Closed, NoDisplay, Failed };

// Opens the window and runs the app until it asks to quit. NoDisplay when no window can be
// opened here (no X server or Wayland compositor), so the caller can fall back to a preview;
// Failed (with `error`) for anything else.
WindowResult runWindow(App& app, const WindowOptions& options, std::string& error);

} // namespace lab
