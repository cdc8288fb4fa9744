// glfw_window.cpp — the desktop platform: GLFW window, OpenGL ES 3.0 context (EGL), Dear ImGui.
//
// Implemented features:
//   * the loop: events, one frame (imgui_host.h: ImGui's frame, App::frame, ImGui's draw data on
//     top), swap — only when a frame is due (app/frame_pacer.h); otherwise it sleeps in GLFW
//     until an event or the app's timer, so an idle lab costs no CPU;
//   * every input event is queued (imgui_glfw.h) and handed out a frame's share at a time;
//   * no swap for a frame that would look exactly as the last (imgui_host.h);
//   * dropped files and the close button go to the app (which may ask about unsaved edits);
//   * presenter scale: fonts are re-rasterized at the new size (DejaVu Sans when installed,
//     ImGui's built-in font otherwise) and the style scaled, instead of blurry stretching;
//   * the window fits the screen it opens on: 1600x900 or --size, shrunk to the monitor's work
//     area and centred in it;
//   * fullscreen on the primary monitor and back;
//   * the speaker's notes in a second window when the app asks (notes_window.h).
// Not here: anything about presets, rendering or the UI's content (lab/app, lab/render, lab/ui).
// Debian's ImGui 1.86 OpenGL3 backend loads desktop GL entry points; on an ES context it raises
// one harmless GL_INVALID_ENUM per frame (it asks for GL_POLYGON_MODE). The lab never reads
// glGetError in the window.
#include "platform/window.h"

#include "app/frame_pacer.h"
#include "platform/imgui_glfw.h"
#include "platform/imgui_host.h"
#include "platform/notes_window.h"

#include "render/gl.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

namespace lab {

namespace {

struct WindowState : PlatformInput {
    int windowedX = 100, windowedY = 100, windowedW = 1600, windowedH = 900;
};

const std::vector<std::string> kFonts = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"};

void toggleFullscreen(GLFWwindow* window, WindowState& state) {
    if (glfwGetWindowMonitor(window)) {
        glfwSetWindowMonitor(window, nullptr, state.windowedX, state.windowedY, state.windowedW, state.windowedH, 0);
        return;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) {
        return;
    }
    glfwGetWindowPos(window, &state.windowedX, &state.windowedY);
    glfwGetWindowSize(window, &state.windowedW, &state.windowedH);
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

// The primary monitor's work area (the screen less task bars), or nothing without a monitor.
bool workArea(int& x, int& y, int& w, int& h) {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) {
        return false;
    }
    glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
    return w > 0 && h > 0;
}

// The window's size: the asked one (1600x900 by default), never larger than the work area; a
// projector's 1024x768 or 1280x800 gets the whole of it.
WindowOptions fitted(WindowOptions options) {
    int x = 0, y = 0, w = 0, h = 0;
    if (workArea(x, y, w, h)) {
        options.width = std::min(options.width, w);
        options.height = std::min(options.height, h);
    }
    return options;
}

// A GLFW window with an OpenGL ES 3.0 context (EGL); nullptr with `error`. No multisampling:
// the model's viewport has its own (AppOptions::viewportSamples), and the view is copied into the window with
// a blit, which a multisampled window would refuse.
GLFWwindow* openWindow(const WindowOptions& options, std::string& error) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    glfwWindowHint(GLFW_SAMPLES, 0);
    GLFWwindow* window = glfwCreateWindow(options.width, options.height, "Lighting Lab", nullptr, nullptr);
    if (!window) {
        const char* description = nullptr;
        glfwGetError(&description);
        error = std::string("cannot open an OpenGL ES 3.0 window: ") + (description ? description : "unknown error");
        return nullptr;
    }
    int x = 0, y = 0, w = 0, h = 0;
    if (workArea(x, y, w, h)) { // centred in the work area, so no edge is off screen
        glfwSetWindowPos(window, x + (w - options.width) / 2, y + (h - options.height) / 2);
    }
    return window;
}

FrameInput nextInput(GLFWwindow* window, WindowState& state, double& last, float lastCost) {
    FrameInput in;
    in.closeRequested = glfwWindowShouldClose(window);
    glfwSetWindowShouldClose(window, GLFW_FALSE);
    takeQueuedInput(state, in);
    double now = glfwGetTime();
    in.deltaTime = static_cast<float>(std::max(now - last, 1e-4));
    in.lastFrameSeconds = lastCost;
    last = now;
    int w, h;
    glfwGetWindowSize(window, &w, &h);
    glfwGetFramebufferSize(window, &in.framebufferWidth, &in.framebufferHeight);
    in.windowWidth = static_cast<float>(std::max(w, 1));
    in.windowHeight = static_cast<float>(std::max(h, 1));
    return in;
}

// Sleeps in GLFW as long as the pacer allows (until an event, or the app's timer, or the notes'
// clock's next minute), then takes the events that came.
void waitForEvents(GLFWwindow* window, WindowState& state, const FramePacer& pacer, double notesWakeIn) {
    double sleep = pacer.sleepFor(glfwGetTime(), !state.queue.empty());
    if (notesWakeIn >= 0.0) {
        sleep = sleep < 0.0 ? notesWakeIn : std::min(sleep, notesWakeIn);
    }
    if (glfwGetWindowAttrib(window, GLFW_ICONIFIED) || sleep < 0.0) {
        glfwWaitEvents();
    } else if (sleep > 0.0) {
        glfwWaitEventsTimeout(sleep);
    } else {
        glfwPollEvents();
    }
}

// The loop: a frame when one is due (app/frame_pacer.h), asleep otherwise.
void loop(GLFWwindow* window, WindowState& state, ImGuiHost& host, NotesWindow& notes) {
    FramePacer pacer;
    double last = glfwGetTime();
    float lastCost = 0.0f;
    for (bool quit = false; !quit;) {
        waitForEvents(window, state, pacer, notes.wakeIn());
        notes.refresh();
        if (std::exchange(state.changed, false)) {
            pacer.input();
        }
        bool queued = !state.queue.empty();
        if (glfwGetWindowAttrib(window, GLFW_ICONIFIED) ||
            (!pacer.due(glfwGetTime(), queued) && !glfwWindowShouldClose(window))) {
            continue;
        }
        double start = glfwGetTime();
        FrameInput in = nextInput(window, state, last, lastCost);
        in.framesDue = pacer.dueAfterThis(!state.queue.empty());
        FrameOutput out = host.frame(in, [] { ImGui_ImplGlfw_NewFrame(); });
        if (out.presented) {
            glfwSwapBuffers(window);
        }
        lastCost = static_cast<float>(glfwGetTime() - start);
        pacer.drawn(glfwGetTime(), out.redrawIn, !state.queue.empty());
        notes.update(out.notesWindow);
        glfwSetWindowTitle(window, out.title.c_str());
        if (out.toggleFullscreen) {
            toggleFullscreen(window, state);
        }
        quit = out.quit;
    }
}

WindowResult runWindow(const AppOptions& appOptions, const WindowOptions& options, std::string& error) {
    GLFWwindow* window = openWindow(fitted(options), error);
    if (!window) {
        return WindowResult::Failed;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    WindowResult result = WindowResult::Closed;
    {
        AppOptions withSamples = appOptions;
        withSamples.viewportSamples = 4;
        withSamples.notesWindows = true;
        App app(withSamples); // its GL objects go before the context does
        WindowState state;
        ImGuiHost host(kFonts);
        GlfwBackend backend(window, &state);
        NotesWindow notes(window, &state, kFonts); // closed before the host's context goes
        glfwSetWindowCloseCallback(window, [](GLFWwindow* w) { static_cast<PlatformInput*>(glfwGetWindowUserPointer(w))->changed = true; });
        if (!host.start(app, error)) {
            result = WindowResult::Failed;
        } else {
            if (options.fullscreen) {
                toggleFullscreen(window, state);
            }
            loop(window, state, host, notes);
        }
    }
    glfwDestroyWindow(window);
    return result;
}

} // namespace

WindowResult runLab(const AppOptions& options, const WindowOptions& window, std::string& error) {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland)) {
        return WindowResult::NoDisplay;
    }
    glfwSetErrorCallback(nullptr);
    if (!glfwInit()) {
        return WindowResult::NoDisplay;
    }
    WindowResult result = runWindow(options, window, error);
    glfwTerminate();
    return result;
}

} // namespace lab
