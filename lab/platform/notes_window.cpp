// notes_window.cpp — the speaker's notes in a window of their own (GLFW, OpenGL ES 3.0 through EGL).
#include "platform/notes_window.h"

#include "render/gl.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <utility>

namespace lab {

namespace {

constexpr float kNotesFontPixels = 30.0f; // read from a lectern, an arm's length away

// Where the notes go: on another monitor than the lab's when there is one (the laptop's screen
// beside the projector), most of it; else the top left of the only one, a third of it.
void placement(GLFWwindow* main, int& x, int& y, int& w, int& h) {
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    int mx = 0, my = 0, mw = 0, mh = 0;
    glfwGetWindowPos(main, &mx, &my);
    glfwGetWindowSize(main, &mw, &mh);
    const int cx = mx + mw / 2, cy = my + mh / 2;
    GLFWmonitor* chosen = count > 0 ? monitors[0] : nullptr;
    for (int i = 0; i < count; ++i) {
        int ax = 0, ay = 0, aw = 0, ah = 0;
        glfwGetMonitorWorkarea(monitors[i], &ax, &ay, &aw, &ah);
        const bool labsOwn = cx >= ax && cx < ax + aw && cy >= ay && cy < ay + ah;
        if (!labsOwn) {
            chosen = monitors[i];
            break;
        }
    }
    int ax = 0, ay = 0, aw = 1280, ah = 800;
    if (chosen) {
        glfwGetMonitorWorkarea(chosen, &ax, &ay, &aw, &ah);
    }
    const bool other = count > 1 && chosen != nullptr;
    w = std::max(320, other ? aw * 3 / 4 : std::min(720, aw / 2));
    h = std::max(240, other ? ah * 3 / 4 : std::min(480, ah / 2));
    x = other ? ax + (aw - w) / 2 : ax;
    y = other ? ay + (ah - h) / 2 : ay;
}

// The clock as it is now: the model's is the frame's, which may be minutes old in an idle lab.
ui::NotesModel now(ui::NotesModel m) {
    m.clock = ui::wallClock();
    return m;
}

} // namespace

NotesWindow::NotesWindow(GLFWwindow* main, PlatformInput* input, std::vector<std::string> fontFiles)
    : main_(main), input_(input), fontFiles_(std::move(fontFiles)) {}

NotesWindow::~NotesWindow() { close(); }

bool NotesWindow::open() {
    int x = 0, y = 0, w = 0, h = 0;
    placement(main_, x, y, w, h);
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);       // placed first, then shown
    glfwWindowHint(GLFW_FOCUS_ON_SHOW, GLFW_FALSE); // the keys stay where they were (either window takes them)
    window_ = glfwCreateWindow(w, h, "Speaker notes - Lighting Lab", nullptr, nullptr);
    glfwDefaultWindowHints();
    if (!window_) {
        const char* description = nullptr;
        glfwGetError(&description);
        std::fprintf(stderr, "lab: cannot open the speaker notes' window: %s\n", description ? description : "unknown error");
        return false;
    }
    glfwSetWindowPos(window_, x, y);
    queueKeysOf(window_, input_);
    ImGuiContext* mainContext = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    loadUiFont(fontFiles_, imguiBuiltinFont, kNotesFontPixels);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0); // never waits for the second screen's refresh: the lab's own frames do
    const bool backend = ImGui_ImplOpenGL3_Init("#version 300 es");
    glfwMakeContextCurrent(main_);
    ImGui::SetCurrentContext(mainContext);
    if (!backend) {
        close();
        return false;
    }
    glfwShowWindow(window_);
    return true;
}

void NotesWindow::close() {
    if (context_) {
        ImGuiContext* mainContext = ImGui::GetCurrentContext();
        glfwMakeContextCurrent(window_);
        ImGui::SetCurrentContext(context_);
        if (ImGui::GetIO().BackendRendererUserData) {
            ImGui_ImplOpenGL3_Shutdown();
        }
        ImGui::DestroyContext(context_);
        context_ = nullptr;
        glfwMakeContextCurrent(main_);
        ImGui::SetCurrentContext(mainContext);
    }
    if (window_) {
        glfwDestroyWindow(window_);
        window_ = nullptr;
    }
    input_->notesClosed = input_->notesRepaint = false;
}

void NotesWindow::draw() {
    ImGuiContext* mainContext = ImGui::GetCurrentContext();
    glfwMakeContextCurrent(window_);
    ImGui::SetCurrentContext(context_);
    int w = 0, h = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window_, &w, &h);
    glfwGetFramebufferSize(window_, &fw, &fh);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(std::max(w, 1)), static_cast<float>(std::max(h, 1)));
    io.DisplayFramebufferScale = ImVec2(w > 0 ? static_cast<float>(fw) / w : 1.0f, h > 0 ? static_cast<float>(fh) / h : 1.0f);
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    ui::notesScreen(shown_);
    ImGui::Render();
    glViewport(0, 0, fw, fh);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window_);
    glfwMakeContextCurrent(main_);
    ImGui::SetCurrentContext(mainContext);
    input_->notesRepaint = false;
}

void NotesWindow::update(const std::optional<ui::NotesModel>& model) {
    if (!model) {
        close();
        failed_ = false; // asked for again: tried again
        return;
    }
    if (!window_) {
        if (failed_ || (failed_ = !open())) {
            return;
        }
        shown_ = now(*model);
        draw();
        return;
    }
    if (ui::NotesModel next = now(*model); next != shown_ || input_->notesRepaint) {
        shown_ = std::move(next);
        draw();
    }
}

void NotesWindow::refresh() {
    if (window_ && (input_->notesRepaint || shown_.clock != ui::wallClock())) {
        shown_.clock = ui::wallClock();
        draw();
    }
}

double NotesWindow::wakeIn() const {
    if (!window_) {
        return -1.0;
    }
    const std::time_t t = std::time(nullptr);
    return static_cast<double>(60 - t % 60) + 0.05;
}

} // namespace lab
