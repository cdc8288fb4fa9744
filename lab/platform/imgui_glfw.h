// imgui_glfw.h — what the desktop and browser platforms share beyond imgui_host.h: both run
// Dear ImGui's GLFW backend (Emscripten implements GLFW over the canvas) for the display size,
// the time and the cursor's shape, while every input event goes through the lab's own queue
// (app/input.h), so none is lost however long a frame takes. Not the loop.
#pragma once

#include "app/app.h"
#include "app/input.h"

struct GLFWwindow;

namespace lab {

// What GLFW's callbacks collected since the loop last looked.
struct PlatformInput {
    InputQueue queue;
    float cursorScale = 1.0f; // GLFW's cursor units to window units (the browser: 1 / device pixel ratio)
    bool changed = false;     // anything happened, input or not (a resize, an uncovered window, focus)
    bool repaint = false;     // the window's picture was lost or resized: draw it whatever changed
    bool notesClosed = false;  // the notes' own window (platform/notes_window.h): its close button
    bool notesRepaint = false; // ... its picture was lost or resized
};

// ImGui's GLFW backend on `window` for as long as it lives, without its input callbacks: the
// lab's callbacks queue every event into `input` instead (focus and the cursor entering go to
// the backend too). Needs the ImGui context (ImGuiHost).
class GlfwBackend {
public:
    GlfwBackend(GLFWwindow* window, PlatformInput* input);
    ~GlfwBackend();
    GlfwBackend(const GlfwBackend&) = delete;
    GlfwBackend& operator=(const GlfwBackend&) = delete;
};

// A second window of the lab's (the speaker's notes): its keys go into `input`'s queue as the main
// window's do, so a clicker or the arrows step the slides from either; its close button and a lost
// picture are input.notesClosed and input.notesRepaint. No ImGui backend on it.
void queueKeysOf(GLFWwindow* window, PlatformInput* input);

// Moves one frame's share of the queued input (and every dropped file) into the frame's input.
void takeQueuedInput(PlatformInput& input, FrameInput& in);

} // namespace lab
