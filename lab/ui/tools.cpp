// tools.cpp — probe and help windows.
#include "ui/tools.h"

#include "ui/widgets.h"

#include <imgui_stdlib.h>

namespace lab::ui {

void helpWindow(bool& open) {
    if (!open) {
        return;
    }
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.92f);
    if (ImGui::Begin("Keyboard shortcuts (F1)", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
        if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            for (const HelpRow& row : helpRows()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(row.keys.c_str());
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(row.help.c_str());
            }
            ImGui::EndTable();
        }
    }
    mark("help");
    ImGui::End();
}

namespace {

void vec(const char* name, const glm::vec3& v) { ImGui::Text("%-3s (%+.3f, %+.3f, %+.3f)", name, v.x, v.y, v.z); }
void rgb(const char* name, const glm::vec3& v) { ImGui::Text("%-18s %.4f  %.4f  %.4f", name, v.x, v.y, v.z); }

} // namespace

void probeWindow(const ProbeResult& probe, const Preset& preset, bool& open, float x, float y) {
    if (!open) {
        return;
    }
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 26, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("Pixel probe", &open)) {
        ImGui::TextDisabled("Eye space. Shading: %s%s", std::string(toString(preset.shading)).c_str(),
                            preset.shading == Shading::Gouraud ? " (the pixel interpolates vertex colours; this is the per-pixel value)" : "");
        vec("p", probe.positionEye);
        vec("N", probe.N);
        vec("V", probe.V);
        rgb("emissive", probe.emissive);
        rgb("global ambient", probe.globalAmbient);
        for (const ProbeLight& l : probe.lights) {
            ImGui::Separator();
            ImGui::Text("Light %d", l.index + 1);
            vec("L", l.L);
            vec(preset.brdf == BrdfModel::Phong ? "R" : "H", preset.brdf == BrdfModel::Phong ? l.R : l.H);
            ImGui::Text("N.L %+.4f  R.V %+.4f  N.H %+.4f  V.H %+.4f  N.V %+.4f", l.NoL, l.RoV, l.NoH, l.VoH, l.NoV);
            if (l.distance > 0.0f) {
                ImGui::Text("d %.3f  Att %.4f", l.distance, l.attenuation);
            } else {
                ImGui::Text("directional: Att %.4f", l.attenuation);
            }
            if (preset.brdf == BrdfModel::CookTorrance) {
                ImGui::Text("D %.4f  F %.4f  G %.4f", l.D, l.F, l.G);
            }
            ImGui::Text("S %.5f", l.specularFactor);
            rgb("ambient", l.ambient);
            rgb("diffuse", l.diffuse);
            rgb("specular", l.specular);
        }
        ImGui::Separator();
        rgb("colour (clamped)", probe.color);
        ImGui::ColorButton("##probecolor", ImVec4(probe.color.r, probe.color.g, probe.color.b, 1.0f));
    }
    mark("probe");
    ImGui::End();
}

} // namespace lab::ui
