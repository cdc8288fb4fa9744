// headless_app.cpp — App frames into a framebuffer object, through the shared ImGui host.
#include "platform/headless_app.h"

#include "platform/imgui_host.h"
#include "render/gl.h"
#include "render/renderer.h"

#include <imgui.h>

namespace lab {

struct HeadlessApp::Impl {
    std::unique_ptr<ImGuiHost> host;
    std::unique_ptr<Framebuffer> target;
    int width = 0, height = 0;
};

HeadlessApp::HeadlessApp() : impl_(std::make_unique<Impl>()) {}

HeadlessApp::~HeadlessApp() = default;

bool HeadlessApp::start(App& app, int width, int height, std::string& error) {
    Impl& m = *impl_;
    m.width = width;
    m.height = height;
    m.target = std::make_unique<Framebuffer>(width, height);
    if (!m.target->complete()) {
        error = "cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer";
        return false;
    }
    m.host = std::make_unique<ImGuiHost>();
    return m.host->start(app, error);
}

FrameOutput HeadlessApp::frame(FrameInput in) {
    Impl& m = *impl_;
    in.windowWidth = static_cast<float>(m.width);
    in.windowHeight = static_cast<float>(m.height);
    in.framebufferWidth = m.width;
    in.framebufferHeight = m.height;
    in.deltaTime = 1.0f / 60.0f; // a fixed time step: frames are reproducible
    in.targetFramebuffer = m.target->id();
    FrameOutput out = m.host->frame(in, [&] {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(in.windowWidth, in.windowHeight);
        io.DeltaTime = in.deltaTime;
    });
    glFinish();
    return out;
}

Image HeadlessApp::read() const { return impl_->target->readRgb(); }

} // namespace lab
