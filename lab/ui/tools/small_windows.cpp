// small_windows.cpp — probe and help windows.
#include "ui/tools/small_windows.h"

#include "core/io/safe_text.h"

#include "ui/widgets.h"

#include <imgui_stdlib.h>

#include <algorithm>

namespace lab::ui {

void helpWindow(bool& open) {
    if (!open) {
        return;
    }
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.92f);
    // Never taller than the screen (a projector's 768 lines): the rows scroll instead; never wider
    // either (presenter mode's font on 1024 columns): the text wraps.
    const float width = std::min(io.DisplaySize.x * 0.95f, ImGui::GetFontSize() * 64.0f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, io.DisplaySize.y * 0.95f));
    if (ImGui::Begin("Keyboard shortcuts (F1)", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted("Letters, digits and the arrows act on the model. Tab or Enter takes the keyboard into the panel (a ring "
                               "marks the widget that has it); Esc or a click gives it back.\nWhile a field is being typed "
                               "in, only the function keys and the Ctrl shortcuts that do not edit text work.");
        ImGui::PopTextWrapPos();
        if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed); // as wide as its widest keys
            ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
            const std::vector<HelpRow> rows = helpRows();
            for (std::size_t i = 0; i < rows.size(); ++i) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                // A row the keyboard can stop at (Tab into this window, then Down), so it reads and
                // scrolls the list without a mouse.
                ImGui::PushID(static_cast<int>(i));
                ImGui::Selectable(rows[i].keys.c_str(), false, ImGuiSelectableFlags_SpanAllColumns);
                ImGui::PopID();
                ImGui::TableNextColumn();
                ImGui::PushTextWrapPos(0.0f);
                ImGui::TextUnformatted(rows[i].help.c_str());
                ImGui::PopTextWrapPos();
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

// "plots at this point": the plots take this point's geometry and light (core/plots/probe_lobe.h),
// for one light, the factor views' (view.light); the preset is not changed.
void plotsHere(const Preset& preset, DisplaySettings& view) {
    ImGui::Checkbox("plots at this point", &view.plotsAtProbe);
    mark("probe.plots-here");
    itemTooltip("The plots use this point: its angle of incidence (from N and L), the light that "
                "arrives here (colour x Att x spot) and its V, and a small lobe is drawn on the "
                "model. Drag the marker to move the point. The preset's plot settings stay.");
    if (!view.plotsAtProbe) {
        return;
    }
    const int lights = static_cast<int>(preset.lights.size());
    view.light = std::clamp(view.light, 0, std::max(lights - 1, 0));
    if (lights > 1) {
        int shown = view.light + 1;
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
        if (ImGui::SliderInt("light##probe", &shown, 1, lights, "Light %d")) {
            view.light = shown - 1;
        }
        mark("probe.light");
    }
    if (lights == 0) {
        ImGui::TextDisabled("No lights: the plots show the preset's angle.");
    } else if (packedLightIndex(preset, view.light) < 0) {
        ImGui::TextDisabled("Light %d is off: the plots show the preset's angle.", view.light + 1);
    }
}

} // namespace

void probeWindow(const ProbeResult& probe, const Preset& preset, DisplaySettings& view, bool& open, float x, float y) {
    if (!open) {
        return;
    }
    // Inside the window whatever its size: at most the display, wide enough for the rows, and
    // pushed back in when it would hang over an edge.
    ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing); // where the layout has room each time it opens
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(ImGui::GetFontSize() * 22, display.x), 0), display);
    ImGui::SetNextWindowBgAlpha(0.92f);
    if (ImGui::Begin("Pixel probe", &open, ImGuiWindowFlags_AlwaysAutoResize)) {
        // Numbers for the instructor, not the room: at most 16 pixels, so that in presenter mode
        // the probe covers a corner of the model, not all of it.
        ImGui::SetWindowFontScale(std::min(1.0f, 16.0f / ImGui::GetFontSize()));
        ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        ImVec2 inside(std::clamp(at.x, 0.0f, std::max(display.x - size.x, 0.0f)), std::clamp(at.y, 0.0f, std::max(display.y - size.y, 0.0f)));
        if (inside.x != at.x || inside.y != at.y) {
            ImGui::SetWindowPos(inside);
        }
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 22);
        ImGui::TextDisabled("Eye space. Shading: %s%s", std::string(toString(preset.shading)).c_str(),
                            preset.shading == Shading::Gouraud ? " (the pixel interpolates vertex colours; this is the per-pixel value)" : "");
        ImGui::PopTextWrapPos();
        plotsHere(preset, view);
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
            ImGui::Text("N.L %+.4f  R.V %+.4f  N.V %+.4f", l.NoL, l.RoV, l.NoV);
            ImGui::Text("N.H %+.4f  V.H %+.4f", l.NoH, l.VoH);
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
