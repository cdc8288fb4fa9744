// imgui_host.cpp — ImGui context, OpenGL3 backend, fonts and the frame order.
#include "platform/imgui_host.h"

#include "render/gl.h"
#include "render/renderer.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <filesystem>

namespace lab {

struct ImGuiHost::Impl {
    std::vector<std::string> fontFiles;
    App* app = nullptr;
    ImGuiStyle baseStyle;
    float scale = 0.0f;
    bool backend = false;

    // Rebuilds the font atlas at `s` and scales a copy of the base style, instead of stretching.
    void applyScale(float s) {
        scale = s;
        ImGuiIO& io = ImGui::GetIO();
        io.Fonts->Clear();
        bool loaded = false;
        for (const std::string& f : fontFiles) {
            std::error_code ec;
            if (!loaded && std::filesystem::is_regular_file(f, ec)) {
                loaded = io.Fonts->AddFontFromFileTTF(f.c_str(), 15.0f * s) != nullptr;
            }
        }
        if (!loaded) {
            ImFontConfig config;
            config.SizePixels = 13.0f * s;
            io.Fonts->AddFontDefault(&config);
        }
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
        ImGui::GetStyle() = baseStyle;
        ImGui::GetStyle().ScaleAllSizes(s);
    }
};

ImGuiHost::ImGuiHost(std::vector<std::string> fontFiles) : impl_(std::make_unique<Impl>()) {
    impl_->fontFiles = std::move(fontFiles);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // the layout is the app's, not a file's
    ImGui::StyleColorsDark();
    impl_->baseStyle = ImGui::GetStyle();
}

ImGuiHost::~ImGuiHost() {
    if (impl_->backend) {
        ImGui_ImplOpenGL3_Shutdown();
    }
    ImGui::DestroyContext();
}

bool ImGuiHost::start(App& app, std::string& error) {
    Impl& m = *impl_;
    if (!ImGui_ImplOpenGL3_Init("#version 300 es")) {
        error = "ImGui's OpenGL3 backend did not start";
        return false;
    }
    m.backend = true;
    m.applyScale(1.0f);
    Diagnostics diagnostics;
    if (!app.init(diagnostics)) {
        error = "the lab cannot start:\n" + toString(diagnostics);
        return false;
    }
    m.app = &app;
    return true;
}

FrameOutput ImGuiHost::frame(const FrameInput& in, const std::function<void()>& platformNewFrame) {
    Impl& m = *impl_;
    ImGui_ImplOpenGL3_NewFrame();
    platformNewFrame();
    ImGui::NewFrame();
    FrameOutput out = m.app->frame(in);
    ImGui::Render();
    bindFramebuffer(in.targetFramebuffer);
    glViewport(0, 0, in.framebufferWidth, in.framebufferHeight);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (out.uiScale != m.scale) {
        m.applyScale(out.uiScale);
    }
    return out;
}

} // namespace lab
