// imgui_glfw.cpp — GLFW's events into the lab's input queue; ImGui's GLFW backend for the rest.
#include "platform/imgui_glfw.h"

#include "ui/actions.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include <utility>

namespace lab {

namespace {

PlatformInput& inputOf(GLFWwindow* window) { return *static_cast<PlatformInput*>(glfwGetWindowUserPointer(window)); }

void push(GLFWwindow* window, const InputEvent& e) {
    PlatformInput& input = inputOf(window);
    input.queue.push(e);
    input.changed = true;
}

unsigned modifiersOf(int mods) {
    return ((mods & GLFW_MOD_CONTROL) ? kCtrl : 0u) | ((mods & GLFW_MOD_SHIFT) ? kShift : 0u) |
           ((mods & GLFW_MOD_ALT) ? kAlt : 0u);
}

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    if (key >= 0) {
        push(window, InputEvent::key(key, action != GLFW_RELEASE, modifiersOf(mods), action == GLFW_REPEAT));
    }
}

void onChar(GLFWwindow* window, unsigned int c) { push(window, InputEvent::character(c)); }

void onCursor(GLFWwindow* window, double x, double y) {
    float s = inputOf(window).cursorScale;
    push(window, InputEvent::move(static_cast<float>(x) * s, static_cast<float>(y) * s));
}

// The press's own place, as GLFW knows it now (the cursor events before it are queued already).
void onMouseButton(GLFWwindow* window, int button, int action, int) {
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    float s = inputOf(window).cursorScale;
    push(window, InputEvent::button(button, action == GLFW_PRESS, static_cast<float>(x) * s, static_cast<float>(y) * s));
}

void onScroll(GLFWwindow* window, double dx, double dy) {
    push(window, InputEvent::scroll(static_cast<float>(dx), static_cast<float>(dy)));
}

void onEnter(GLFWwindow* window, int entered) {
    ImGui_ImplGlfw_CursorEnterCallback(window, entered);
    if (!entered) {
        push(window, InputEvent::leave());
    }
}

void onFocus(GLFWwindow* window, int focused) {
    ImGui_ImplGlfw_WindowFocusCallback(window, focused);
    inputOf(window).changed = true;
}

void onRepaint(GLFWwindow* window) {
    inputOf(window).changed = true;
    inputOf(window).repaint = true;
}

void onNotesRepaint(GLFWwindow* window) {
    inputOf(window).notesRepaint = true;
    inputOf(window).changed = true;
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i) {
        inputOf(window).queue.drop(paths[i]);
    }
    inputOf(window).changed = true;
}

} // namespace

GlfwBackend::GlfwBackend(GLFWwindow* window, PlatformInput* input) {
    glfwSetWindowUserPointer(window, input);
    ImGui_ImplGlfw_InitForOpenGL(window, false);
    glfwSetKeyCallback(window, onKey);
    glfwSetCharCallback(window, onChar);
    glfwSetCursorPosCallback(window, onCursor);
    glfwSetMouseButtonCallback(window, onMouseButton);
    glfwSetScrollCallback(window, onScroll);
    glfwSetCursorEnterCallback(window, onEnter);
    glfwSetWindowFocusCallback(window, onFocus);
    glfwSetDropCallback(window, onDrop);
    glfwSetWindowSizeCallback(window, [](GLFWwindow* w, int, int) { onRepaint(w); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { onRepaint(w); });
    glfwSetWindowRefreshCallback(window, onRepaint);
    glfwSetWindowIconifyCallback(window, [](GLFWwindow* w, int) { onRepaint(w); });
}

GlfwBackend::~GlfwBackend() { ImGui_ImplGlfw_Shutdown(); }

void queueKeysOf(GLFWwindow* window, PlatformInput* input) {
    glfwSetWindowUserPointer(window, input);
    glfwSetKeyCallback(window, onKey);
    glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
        inputOf(w).notesClosed = true;
        inputOf(w).changed = true;
    });
    glfwSetWindowRefreshCallback(window, onNotesRepaint);
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { onNotesRepaint(w); });
}

void takeQueuedInput(PlatformInput& input, FrameInput& in) {
    in.notesWindowClosed = std::exchange(input.notesClosed, false);
    in.events = input.queue.takeFrame();
    in.repaint = std::exchange(input.repaint, false);
    in.droppedFiles = input.queue.takeDropped();
}

} // namespace lab
