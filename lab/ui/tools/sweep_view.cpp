// sweep_view.cpp — the sweep window: two rows of key and values, the cell size, Save PNG, the grid.
#include "ui/tools/sweep_view.h"

#include "core/io/safe_text.h"
#include "core/scene/sweep.h"
#include "ui/widgets.h"

#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdint>

namespace lab::ui {

std::vector<std::string> sweepArguments(const SweepViewState& s) {
    std::vector<std::string> arguments;
    for (int i = 0; i < 2; ++i) {
        if (!s.key[i].empty()) {
            arguments.push_back(s.key[i] + "=" + s.values[i]);
        }
    }
    return arguments;
}

void followPresetSweep(SweepViewState& s, const Preset& preset) {
    if (preset.sweep == s.fromPreset) {
        return;
    }
    s.fromPreset = preset.sweep;
    if (preset.sweep.empty()) {
        return; // a preset without one leaves the window's choices as they were
    }
    for (std::size_t i = 0; i < 2; ++i) {
        std::string_view axis = i < preset.sweep.size() ? std::string_view(preset.sweep[i]) : std::string_view();
        std::size_t equals = axis.find('='); // the reader checked there is one
        s.key[i] = equals == std::string_view::npos ? std::string() : std::string(axis.substr(0, equals));
        s.values[i] = equals == std::string_view::npos ? std::string() : std::string(axis.substr(equals + 1));
    }
}

namespace {

// One axis: its key typed, or picked from the suggestions beside it (the second may be none), and
// its values typed.
void axisRow(SweepViewState& s, int i, const std::vector<SweepKeySuggestion>& keys) {
    ImGui::PushID(i);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(i == 0 ? "Columns" : "Rows   ");
    ImGui::SameLine();
    const float avail = ImGui::GetContentRegionAvail().x;
    ImGui::SetNextItemWidth(std::max(avail * 0.48f - ImGui::GetFrameHeight(), ImGui::GetFontSize() * 6));
    ImGui::InputTextWithHint("##key", i == 0 ? "key, e.g. material.shininess" : "(none)", &s.key[i]);
    s.editing = s.editing || ImGui::IsItemActive();
    mark(i == 0 ? "sweep.key1" : "sweep.key2");
    ImGui::SameLine(0.0f, 0.0f);
    if (ImGui::ArrowButton("##keys", ImGuiDir_Down)) {
        ImGui::OpenPopup("keys");
    }
    mark(i == 0 ? "sweep.keys1" : "sweep.keys2");
    if (ImGui::BeginPopup("keys")) {
        if (i == 1 && ImGui::Selectable("(none)", s.key[i].empty())) {
            s.key[i].clear();
        }
        for (const SweepKeySuggestion& k : keys) {
            if (ImGui::Selectable(k.key.c_str(), k.key == s.key[i]) && k.key != s.key[i]) {
                s.key[i] = k.key;
                s.values[i] = k.values; // a useful range to start from
            }
        }
        ImGui::EndPopup();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (s.key[i].empty()) {
        ImGui::BeginDisabled();
    }
    ImGui::InputTextWithHint("##values", "V1,V2,...", &s.values[i]);
    s.editing = s.editing || ImGui::IsItemActive();
    if (s.key[i].empty()) {
        ImGui::EndDisabled();
    }
    mark(i == 0 ? "sweep.values1" : "sweep.values2");
    ImGui::PopID();
}

} // namespace

void sweepWindow(SweepViewState& s, const Preset& preset, std::vector<Request>& requests) {
    followPresetSweep(s, preset);
    s.editing = false;
    if (!s.open) {
        return;
    }
    nextToolWindow(46, 34, 0.96f); // nearly the whole window on a phone
    if (ImGui::Begin("Sweep", &s.open)) {
        std::vector<SweepKeySuggestion> keys = sweepKeySuggestions(preset);
        axisRow(s, 0, keys);
        axisRow(s, 1, keys);
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted("Cells");
        for (int size : kSweepCellSizes) {
            ImGui::SameLine();
            std::string label = std::to_string(size) + "##cell";
            if (ImGui::RadioButton(label.c_str(), s.cellSize == size)) {
                s.cellSize = size;
            }
        }
        mark("sweep.cells");
        sameLineIfFits(commandRow(Command::SaveSweep).label);
        commandButton(Command::SaveSweep, requests, s.texture != 0 && s.error.empty());
        mark("sweep.save");
        ImGui::SameLine();
        std::string command = "lab render PRESET";
        for (const std::string& a : sweepArguments(s)) {
            command += " --sweep " + a;
        }
        command += " --size " + std::to_string(s.cellSize) + "x" + std::to_string(s.cellSize) + " --out grid.png";
        helpMarker(("The first key's values run along the columns, the second's down the rows: type a key (a "
                    "path into the preset file, such as lights[0].attenuation[2]) or pick one with the arrow; "
                    "the grid follows when you press Enter or click away. A single number for a colour sets "
                    "r = g = b; [r,g,b] sets each. Save PNG writes what\n\n" +
                    printable(command) + "\n\nwrites for the saved preset.")
                       .c_str());
        if (!s.error.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextUnformatted(printable(s.error, true).c_str());
            ImGui::PopTextWrapPos();
            ImGui::PopStyleColor();
            mark("sweep.error");
        }
        // The grid, as large as fits, its shape kept.
        ImVec2 avail = ImGui::GetContentRegionAvail();
        if (s.texture != 0 && s.textureWidth > 0 && s.textureHeight > 0 && avail.x > 1 && avail.y > 1) {
            float scale = std::min(avail.x / static_cast<float>(s.textureWidth), avail.y / static_cast<float>(s.textureHeight));
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(s.texture)),
                         ImVec2(static_cast<float>(s.textureWidth) * scale, static_cast<float>(s.textureHeight) * scale));
            mark("sweep.grid");
        }
    }
    mark("sweep");
    ImGui::End();
}

} // namespace lab::ui
