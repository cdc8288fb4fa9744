// imgui_glfw.h — what the desktop and browser platforms share beyond imgui_host.h: both run
// Dear ImGui's GLFW backend (Emscripten implements GLFW over the canvas), with the key presses and
// drops queued between frames. Not the loop.
#pragma once

#include "app/app.h"

#include <string>
#include <vector>

struct GLFWwindow;

namespace lab {

// Key presses and dropped files collected by GLFW callbacks between frames.
struct InputQueue {
    std::vector<KeyPress> keys;
    std::vector<MouseButtonEvent> mouseButtons; // in GLFW's cursor units (the browser: canvas pixels)
    std::vector<std::string> dropped;
};

// ImGui's GLFW backend on `window` for as long as it lives, with key and drop callbacks feeding
// `queue` (installed first: the backend chains the callbacks installed before it). Needs the
// ImGui context (ImGuiHost).
class GlfwBackend {
public:
    GlfwBackend(GLFWwindow* window, InputQueue* queue);
    ~GlfwBackend();
    GlfwBackend(const GlfwBackend&) = delete;
    GlfwBackend& operator=(const GlfwBackend&) = delete;
};

// Moves what the callbacks queued into the frame's input.
void takeQueuedInput(InputQueue& queue, FrameInput& in);

} // namespace lab
