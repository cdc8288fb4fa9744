// share_code.cpp — the QR code window.
#include "ui/tools/share_code.h"

#include "ui/widget_map.h"
#include "ui/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace lab::ui {

void shareCodeWindow(const ShareCodeModel& m, std::vector<Request>& requests) {
    const ImGuiViewport* screen = ImGui::GetMainViewport();
    const float side = std::min(screen->Size.x, screen->Size.y);
    ImGui::SetNextWindowPos(ImVec2(screen->Pos.x + screen->Size.x * 0.5f, screen->Pos.y + screen->Size.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(screen->Size.x * 0.96f, std::max(side * 0.9f, 320.0f)), side * 0.96f));
    ImGui::SetNextWindowBgAlpha(1.0f); // nothing shows through around the code
    ImGui::Begin("Open this scene on your phone###share-code", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoMove);
    if (!m.title.empty()) {
        ImGui::TextUnformatted(m.title.c_str());
    }
    const float lines = ImGui::GetTextLineHeightWithSpacing() * (m.address ? 7.0f : 4.0f);
    ImVec2 room = ImGui::GetContentRegionAvail();
    float codeSide = std::max(0.0f, std::min(room.x, room.y - lines));
    if (m.code && m.code->size > 0) {
        const int modules = m.code->size + 8; // with the quiet zone
        float module = std::floor(codeSide / static_cast<float>(modules));
        module = std::max(module, 1.0f);
        float drawn = module * static_cast<float>(modules);
        ImVec2 at = ImGui::GetCursorScreenPos();
        at.x += std::floor((room.x - drawn) * 0.5f);
        ImDrawList* dl = ImGui::GetWindowDrawList();
        dl->AddRectFilled(at, ImVec2(at.x + drawn, at.y + drawn), IM_COL32(255, 255, 255, 255));
        for (int y = 0; y < m.code->size; ++y) {
            for (int x = 0; x < m.code->size; ++x) {
                if (m.code->dark(x, y)) {
                    ImVec2 a(at.x + (x + 4) * module, at.y + (y + 4) * module);
                    dl->AddRectFilled(a, ImVec2(a.x + module, a.y + module), IM_COL32(0, 0, 0, 255));
                }
            }
        }
        ImGui::Dummy(ImVec2(room.x, drawn));
        widgets().set("share.qr", {at.x, at.y, drawn, drawn});
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", m.link.c_str());
        ImGui::PopTextWrapPos();
    } else {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(m.problem.c_str());
        ImGui::PopTextWrapPos();
        mark("share.problem");
    }
    if (m.address) {
        ImGui::TextDisabled("The course page's address (remembered):");
        pathField("##share-address", "https://your-course.example.org/lab/", *m.address, Command::SetShareBase, requests,
                  "share.address");
        if (!m.addressProblem.empty()) {
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.45f, 1.0f), "%s", m.addressProblem.c_str());
            ImGui::PopTextWrapPos();
            mark("share.address-problem");
        }
    }
    if (ImGui::Button("Close (Q)")) {
        requests.push_back({Command::ToggleShareCode});
    }
    mark("share.close");
    ImGui::End();
}

} // namespace lab::ui
