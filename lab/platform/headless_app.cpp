// headless_app.cpp — App::frame into a framebuffer object with ImGui's OpenGL3 backend.
#include "platform/headless_app.h"

#include "render/gl.h"
#include "render/renderer.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace lab {

struct HeadlessApp::Impl {
    App* app = nullptr;
    std::unique_ptr<Framebuffer> target;
    int width = 0, height = 0;
    bool started = false;
};

HeadlessApp::HeadlessApp() : impl_(std::make_unique<Impl>()) {}

HeadlessApp::~HeadlessApp() {
    if (impl_->started) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui::DestroyContext();
    }
}

bool HeadlessApp::start(App& app, int width, int height, std::string& error) {
    Impl& m = *impl_;
    m.app = &app;
    m.width = width;
    m.height = height;
    m.target = std::make_unique<Framebuffer>(width, height);
    if (!m.target->complete()) {
        error = "cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer";
        return false;
    }
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    ImGui::StyleColorsDark();
    if (!ImGui_ImplOpenGL3_Init("#version 300 es")) {
        error = "ImGui's OpenGL3 backend did not start";
        return false;
    }
    m.started = true;
    Diagnostics diagnostics;
    if (!app.init(diagnostics)) {
        error = toString(diagnostics);
        return false;
    }
    return true;
}

FrameOutput HeadlessApp::frame(FrameInput in) {
    Impl& m = *impl_;
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(m.width), static_cast<float>(m.height));
    io.DeltaTime = 1.0f / 60.0f; // a fixed time step: frames are reproducible
    in.windowWidth = static_cast<float>(m.width);
    in.windowHeight = static_cast<float>(m.height);
    in.framebufferWidth = m.width;
    in.framebufferHeight = m.height;
    in.deltaTime = io.DeltaTime;
    in.targetFramebuffer = m.target->id();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    FrameOutput out = m.app->frame(in);
    ImGui::Render();
    m.target->bind();
    glViewport(0, 0, m.width, m.height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
    return out;
}

Image HeadlessApp::read() const { return impl_->target->readRgb(); }

} // namespace lab
