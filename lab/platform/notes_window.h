// notes_window.h — the desktop's second window: the speaker's notes on the laptop's screen while
// the lab fills the projector (Command::NotesWindow, Shift+S). It opens while a frame hands it a
// model (FrameOutput::notesWindow) and closes when one does not; its close button tells the app
// (FrameInput::notesWindowClosed). Its keys are the lab's (imgui_glfw.h queueKeysOf): the arrows,
// Page Up/Down and Space step the slides from either window. It has an ImGui context and an
// OpenGL ES context of its own, and draws only when what it shows changes: the model, the
// clock's minute, a lost picture. GLFW only (glfw_window.cpp).
#pragma once

#include "platform/imgui_glfw.h"
#include "platform/imgui_host.h"
#include "ui/tools/notes.h"

#include <optional>
#include <string>
#include <vector>

struct ImGuiContext;

namespace lab {

class NotesWindow {
public:
    NotesWindow(GLFWwindow* main, PlatformInput* input, std::vector<std::string> fontFiles);
    ~NotesWindow();
    NotesWindow(const NotesWindow&) = delete;
    NotesWindow& operator=(const NotesWindow&) = delete;

    // After each of the main window's frames: opens, draws or closes the window as `model` says.
    // The main window's contexts (GL and ImGui) are current again after it.
    void update(const std::optional<ui::NotesModel>& model);
    // Between frames: draws again when the clock's minute changed or the picture was lost.
    void refresh();
    // How long the loop may sleep before refresh() has a new minute to show; < 0: no limit (closed).
    double wakeIn() const;

private:
    bool open();
    void close();
    void draw();

    GLFWwindow* main_ = nullptr;
    GLFWwindow* window_ = nullptr;
    PlatformInput* input_ = nullptr;
    ImGuiContext* context_ = nullptr;
    std::vector<std::string> fontFiles_;
    ui::NotesModel shown_;
    bool failed_ = false; // it could not open: not tried again this session
};

} // namespace lab
