// shader_editor.cpp — the shader editor window.
#include "ui/shader_editor.h"

#include "ui/widgets.h"

#include <imgui_stdlib.h>

namespace lab::ui {

void shaderEditorWindow(ShaderEditorState& s, std::vector<Request>& requests, std::string_view lightingSource) {
    if (!s.open) {
        return;
    }
    ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 46, ImGui::GetFontSize() * 36), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Shader editor", &s.open)) {
        commandButton(Command::CompileShaders, requests);
        mark("shader.compile");
        ImGui::SameLine();
        commandButton(Command::RevertShaders, requests);
        ImGui::SameLine();
        ImGui::TextDisabled(s.customActive ? "running: edited shaders" : "running: built-in shaders");
        ImVec2 editor(-1, -ImGui::GetTextLineHeightWithSpacing() * (s.log.empty() ? 1.0f : 7.0f));
        if (ImGui::BeginTabBar("stages")) {
            if (ImGui::BeginTabItem("lit.frag")) {
                ImGui::InputTextMultiline("##frag", &s.fragment, editor, ImGuiInputTextFlags_AllowTabInput);
                mark("shader.fragment");
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("lit.vert")) {
                ImGui::InputTextMultiline("##vert", &s.vertex, editor, ImGuiInputTextFlags_AllowTabInput);
                mark("shader.vertex");
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("lighting.glsl (read-only)")) {
                std::string text(lightingSource);
                ImGui::InputTextMultiline("##lighting", &text, editor, ImGuiInputTextFlags_ReadOnly);
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        if (!s.log.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, s.lastCompileFailed ? IM_COL32(255, 120, 110, 255) : IM_COL32(140, 220, 140, 255));
            ImGui::BeginChild("log", ImVec2(-1, 0), true);
            for (const std::string& line : s.log) {
                ImGui::TextWrapped("%s", line.c_str());
            }
            ImGui::EndChild();
            mark("shader.log");
            ImGui::PopStyleColor();
        }
    }
    ImGui::End();
}

} // namespace lab::ui
