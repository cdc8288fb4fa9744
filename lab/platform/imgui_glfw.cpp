// imgui_glfw.cpp — input queue and UI scaling for the GLFW-based platforms.
#include "platform/imgui_glfw.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <filesystem>

namespace lab {

namespace {

InputQueue* queueOf(GLFWwindow* window) { return static_cast<InputQueue*>(glfwGetWindowUserPointer(window)); }

// ImGui 1.86 polls key state once a frame; a press and release within one frame would be lost
// for the app's shortcuts, so they are queued here (ImGui calls this after its own callback).
void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    if (action == GLFW_PRESS || action == GLFW_REPEAT) {
        queueOf(window)->keys.push_back(
            {key, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_ALT) != 0});
    }
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i) {
        queueOf(window)->dropped.emplace_back(paths[i]);
    }
}

} // namespace

void installInputQueue(GLFWwindow* window, InputQueue* queue) {
    glfwSetWindowUserPointer(window, queue);
    glfwSetKeyCallback(window, onKey);
    glfwSetDropCallback(window, onDrop);
}

void applyUiScale(float scale, const ImGuiStyle& baseStyle, const std::vector<std::string>& fontFiles) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    bool loaded = false;
    for (const std::string& f : fontFiles) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(f, ec) && io.Fonts->AddFontFromFileTTF(f.c_str(), 15.0f * scale)) {
            loaded = true;
            break;
        }
    }
    if (!loaded) {
        ImFontConfig config;
        config.SizePixels = 13.0f * scale;
        io.Fonts->AddFontDefault(&config);
    }
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
    ImGui::GetStyle() = baseStyle;
    ImGui::GetStyle().ScaleAllSizes(scale);
}

} // namespace lab
