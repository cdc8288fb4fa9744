// imgui_glfw.cpp — the GLFW backend of ImGui with queued keys and drops.
#include "platform/imgui_glfw.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

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

// ImGui 1.86 polls the cursor once a frame: a click's own position is queued here.
void onMouseButton(GLFWwindow* window, int button, int action, int) {
    if (button > 1 || (action != GLFW_PRESS && action != GLFW_RELEASE)) {
        return;
    }
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    queueOf(window)->mouseButtons.push_back({static_cast<float>(x), static_cast<float>(y), button, action == GLFW_PRESS});
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i) {
        queueOf(window)->dropped.emplace_back(paths[i]);
    }
}

} // namespace

GlfwBackend::GlfwBackend(GLFWwindow* window, InputQueue* queue) {
    glfwSetWindowUserPointer(window, queue);
    glfwSetKeyCallback(window, onKey);
    glfwSetDropCallback(window, onDrop);
    glfwSetMouseButtonCallback(window, onMouseButton);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
}

GlfwBackend::~GlfwBackend() { ImGui_ImplGlfw_Shutdown(); }

void takeQueuedInput(InputQueue& queue, FrameInput& in) {
    in.keys.swap(queue.keys);
    queue.keys.clear();
    in.mouseButtons.swap(queue.mouseButtons);
    queue.mouseButtons.clear();
    in.droppedFiles.swap(queue.dropped);
    queue.dropped.clear();
}

} // namespace lab
