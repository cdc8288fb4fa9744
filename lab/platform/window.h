// window.h — the platform seam of the interactive lab: a window, its loop, and ImGui's platform
// backend, around App::frame().
//
// One implementation is compiled, chosen by the CMake cache variable LAB_PLATFORM:
//   glfw  glfw_window.cpp — a GLFW window with an OpenGL ES 3 context through EGL, the same GL
//         the headless renderer and WebGL2 use (the desktop default);
//   web   web_window.cpp — the browser's canvas and main loop (forced by Emscripten);
//   none  none_window.cpp — no interactive lab: `lab` renders a preview instead.
// Each provides exactly this function; nothing else in the lab asks which one it is.
#pragma once

#include "app/app.h"

#include <string>

namespace lab {

struct WindowOptions {
    int width = 1600; // never larger than the screen's work area: shrunk to fit
    int height = 900;
    bool sizeGiven = false; // --size: this size (within the work area), else 1600x900 or the work area
    bool fullscreen = false;
};

enum class WindowResult { Closed, NoDisplay, Failed };

// Opens the window and runs the lab until it asks to quit. NoDisplay when no window can be
// opened here (no X server or Wayland compositor, or no interactive platform built), so the
// caller can fall back to a preview; Failed (with `error`) for anything else.
WindowResult runLab(const AppOptions& options, const WindowOptions& window, std::string& error);

} // namespace lab
