// control_panel_test.cpp — the control panel drawn on the CPU (tests/cpu_imgui.h): what it shows
// for a preset and a list of files.
#include "cpu_imgui.h"
#include "core/scene/field_table.h"
#include "ui/panel/panel.h"
#include "ui/widget_map.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <filesystem>
#include <string>
#include <vector>

namespace lab {
namespace {

struct Drawn {
    std::string widgets;   // the widget map's text
    std::size_t vertices = 0; // everything the last frame drew
};

// A few frames of the panel in a tall window, as screen.cpp opens it.
Drawn drawPanel(Preset& preset, const std::vector<std::filesystem::path>& files) {
    CpuImGui imgui(1.0f);
    ImGui::GetIO().DisplaySize = ImVec2(400, 1600);
    DisplaySettings view;
    ui::PanelInfo info;
    for (const std::filesystem::path& f : files) {
        info.presetNames.push_back(f.stem().string());
    }
    info.documentName = "x.json";
    ui::PanelState state;
    std::vector<Request> requests;
    Drawn out;
    for (int frame = 0; frame < 3; ++frame) {
        ui::widgets().clear();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 1600));
        ImGui::Begin("Lighting Lab###panel", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
        ui::controlPanel(preset, view, info, state, requests);
        ImGui::End();
        ImGui::Render();
    }
    out.widgets = ui::widgets().text();
    const ImDrawData* drawn = ImGui::GetDrawData();
    for (int i = 0; i < drawn->CmdListsCount; ++i) {
        out.vertices += static_cast<std::size_t>(drawn->CmdLists[i]->VtxBuffer.Size);
    }
    return out;
}

bool hasWidget(const Drawn& d, const std::string& name) { return d.widgets.find("\n" + name + " ") != std::string::npos || d.widgets.rfind(name + " ", 0) == 0; }

// ImGui reads "##" in a label as the start of a hidden ID: a file named "a##b.json" showed as "a".
// The list draws the whole name: as many glyphs as a name of the same length without "##".
TEST(ControlPanel, APresetFileNameWithHashesShowsWhole) {
    Preset p;
    Drawn hashes = drawPanel(p, {"/presets/a##hidden.json"});
    Drawn plain = drawPanel(p, {"/presets/a__hidden.json"});
    EXPECT_EQ(hashes.vertices, plain.vertices) << "the list should draw every character of a##hidden";
    Drawn shorter = drawPanel(p, {"/presets/a.json"});
    EXPECT_GT(plain.vertices, shorter.vertices) << "(the count can tell a name's length)";
}

// The shininess n shapes Phong's and Blinn-Phong's lobes and has no effect on Cook-Torrance's,
// whose roughness m is shown instead (and m is hidden for the other two).
TEST(ControlPanel, TheShininessSliderIsShownOnlyWhereItHasAnEffect) {
    for (BrdfModel brdf : {BrdfModel::Phong, BrdfModel::BlinnPhong, BrdfModel::CookTorrance}) {
        Preset p;
        p.brdf = brdf;
        Drawn d = drawPanel(p, {});
        bool cookTorrance = brdf == BrdfModel::CookTorrance;
        EXPECT_EQ(hasWidget(d, "material.shininess"), !cookTorrance) << static_cast<int>(brdf);
        EXPECT_EQ(hasWidget(d, "cook_torrance.roughness"), cookTorrance) << static_cast<int>(brdf);
    }
}

} // namespace
} // namespace lab

namespace lab {
namespace {

// Every field of the table that applies to the preset has its widget, named by its path, in the
// sections the panel opens (the model and camera sections start closed): the panel draws the
// table's rows, and none goes missing (the BRDF's and the shading's radio buttons once did).
TEST(ControlPanel, EveryFieldThatAppliesHasItsWidget) {
    for (BrdfModel brdf : {BrdfModel::Phong, BrdfModel::CookTorrance}) {
        Preset p;
        p.brdf = brdf;
        p.lights[0].type = LightType::Spot;
        p.lights[0].orbit.on = true;
        Drawn d = drawPanel(p, {});
        int checked = 0;
        for (const FieldRow& row : fieldRows()) {
            bool opened = row.group != FieldGroup::Model && row.group != FieldGroup::Camera && row.group != FieldGroup::Plot;
            if (!opened || (row.style & kStyleHidden) || row.custom || !applies(row, p, isLightRow(row) ? &p.lights[0] : nullptr)) {
                continue;
            }
            std::string name = fieldPath(row, 0) + ((row.style & kStyleRadios) ? "." + std::string(row.choices[0].label) : "");
            EXPECT_TRUE(hasWidget(d, name)) << name << " (" << toString(brdf) << ") is not in the panel:\n" << d.widgets;
            ++checked;
        }
        EXPECT_GT(checked, 25);
    }
}

} // namespace
} // namespace lab
