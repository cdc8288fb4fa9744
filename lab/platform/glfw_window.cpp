// glfw_window.cpp — the desktop platform: GLFW window, OpenGL ES 3.0 context (EGL), Dear ImGui.
//
// Implemented features:
//   * the loop: poll events, ImGui backends' NewFrame, App::frame, render ImGui on top, swap;
//     it sleeps on events while the window is minimized;
//   * dropped files and the close button go to the app (which may ask about unsaved edits);
//   * presenter scale: fonts are re-rasterized at the new size (DejaVu Sans when installed,
//     ImGui's built-in font otherwise) and the style scaled, instead of blurry stretching;
//   * fullscreen on the primary monitor and back.
// Not here: anything about presets, rendering or the UI's content (lab/app, lab/render, lab/ui).
// Debian's ImGui 1.86 OpenGL3 backend loads desktop GL entry points; on an ES context it raises
// one harmless GL_INVALID_ENUM per frame (it asks for GL_POLYGON_MODE). The lab never reads
// glGetError in the window.
#include "platform/window.h"

#include "platform/imgui_glfw.h"

#include "render/gl.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdlib>
#include <vector>

namespace lab {

namespace {

struct WindowState : InputQueue {
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

} // namespace

WindowResult runWindow(App& app, const WindowOptions& options, std::string& error) {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland)) {
        return WindowResult::NoDisplay;
    }
    glfwSetErrorCallback(nullptr);
    if (!glfwInit()) {
        return WindowResult::NoDisplay;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    glfwWindowHint(GLFW_SAMPLES, 4);
    GLFWwindow* window = glfwCreateWindow(options.width, options.height, "Lighting Lab", nullptr, nullptr);
    if (!window) {
        glfwWindowHint(GLFW_SAMPLES, 0);
        window = glfwCreateWindow(options.width, options.height, "Lighting Lab", nullptr, nullptr);
    }
    if (!window) {
        const char* description = nullptr;
        glfwGetError(&description);
        error = std::string("cannot open an OpenGL ES 3.0 window: ") + (description ? description : "unknown error");
        glfwTerminate();
        return WindowResult::Failed;
    }
    WindowState state;
    installInputQueue(window, &state);
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // the layout is the app's, not a file's
    ImGui::StyleColorsDark();
    ImGuiStyle baseStyle = ImGui::GetStyle();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 300 es");

    WindowResult result = WindowResult::Closed;
    Diagnostics diagnostics;
    if (!app.init(diagnostics)) {
        error = "the lab cannot start:\n" + toString(diagnostics);
        result = WindowResult::Failed;
    } else {
        if (options.fullscreen) {
            toggleFullscreen(window, state);
        }
        float scale = 1.0f;
        applyUiScale(scale, baseStyle, kFonts);
        double last = glfwGetTime();
        bool quit = false;
        while (!quit) {
            if (glfwGetWindowAttrib(window, GLFW_ICONIFIED)) {
                glfwWaitEvents();
                continue;
            }
            glfwPollEvents();
            FrameInput in;
            in.closeRequested = glfwWindowShouldClose(window);
            glfwSetWindowShouldClose(window, GLFW_FALSE);
            in.droppedFiles.swap(state.dropped);
            in.keys.swap(state.keys);
            double now = glfwGetTime();
            in.deltaTime = static_cast<float>(std::max(now - last, 1e-4));
            last = now;
            int w, h;
            glfwGetWindowSize(window, &w, &h);
            glfwGetFramebufferSize(window, &in.framebufferWidth, &in.framebufferHeight);
            in.windowWidth = static_cast<float>(std::max(w, 1));
            in.windowHeight = static_cast<float>(std::max(h, 1));

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            FrameOutput out = app.frame(in);
            ImGui::Render();
            glViewport(0, 0, in.framebufferWidth, in.framebufferHeight);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            glfwSwapBuffers(window);

            glfwSetWindowTitle(window, out.title.c_str());
            if (out.toggleFullscreen) {
                toggleFullscreen(window, state);
            }
            if (out.uiScale != scale) {
                scale = out.uiScale;
                applyUiScale(scale, baseStyle, kFonts);
            }
            quit = out.quit;
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return result;
}

} // namespace lab
