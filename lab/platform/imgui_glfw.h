// imgui_glfw.h — what the desktop and browser platforms share: both run Dear ImGui on GLFW
// (Emscripten implements GLFW over the canvas). Input queueing and UI scaling; not the loop.
#pragma once

#include "app/app.h"

#include <string>
#include <vector>

struct GLFWwindow;
struct ImGuiStyle;

namespace lab {

// Key presses and dropped files collected by GLFW callbacks between frames.
struct InputQueue {
    std::vector<KeyPress> keys;
    std::vector<std::string> dropped;
};

// Installs key and drop callbacks feeding `queue`. Call before ImGui_ImplGlfw_InitForOpenGL,
// which chains the callbacks installed before it.
void installInputQueue(GLFWwindow* window, InputQueue* queue);

// Rebuilds the font atlas at `scale` (the first font file that exists, else ImGui's own font)
// and scales a copy of `baseStyle`. Needs the ImGui OpenGL3 backend initialized.
void applyUiScale(float scale, const ImGuiStyle& baseStyle, const std::vector<std::string>& fontFiles);

} // namespace lab
