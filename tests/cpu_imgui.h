// cpu_imgui.h — an ImGui context for tests that draw the lab's windows on the CPU (no renderer).
#pragma once

#include <imgui.h>

#include <filesystem>
#include <system_error>

namespace lab {

// An ImGui context as the lab's host sets it up at scale `s` (DejaVu Sans at 15·s when installed,
// the built-in font at 13·s otherwise; every style size scaled), its font atlas built on the CPU.
class CpuImGui {
public:
    explicit CpuImGui(float s) : previous_(ImGui::GetCurrentContext()), context_(ImGui::CreateContext()) {
        ImGui::SetCurrentContext(context_);
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DeltaTime = 1.0f / 60.0f;
        ImGui::StyleColorsDark();
        ImGui::GetStyle().ScaleAllSizes(s);
        const char* dejavu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
        std::error_code ec;
        if (!std::filesystem::is_regular_file(dejavu, ec) || !io.Fonts->AddFontFromFileTTF(dejavu, 15.0f * s)) {
            ImFontConfig config;
            config.SizePixels = 13.0f * s;
            io.Fonts->AddFontDefault(&config);
        }
        unsigned char* pixels;
        int w, h;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    ~CpuImGui() {
        ImGui::DestroyContext(context_);
        ImGui::SetCurrentContext(previous_);
    }
    CpuImGui(const CpuImGui&) = delete;
    CpuImGui& operator=(const CpuImGui&) = delete;

private:
    ImGuiContext* previous_;
    ImGuiContext* context_;
};

} // namespace lab
