// plot_panel_kit.h — the plots panel drawn on the CPU for the tests (plot_panel_test.cpp,
// slice_view_test.cpp): a few frames of the window as screen.cpp opens it, what they drew, the
// widget map's rectangles, and every window a class may use.
#pragma once

#include "cpu_imgui.h"
#include "ui/layout.h"
#include "ui/plots/plots.h"
#include "ui/widget_map.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace lab::plotpanel {

struct Outcome {
    float scrollX = 0, scrollY = 0;
    std::string widgets;            // the widget map's text
    std::vector<ImDrawVert> vertices; // everything the last frame drew, in order
    std::vector<ImDrawIdx> indices;
};

inline bool sameDrawing(const Outcome& x, const Outcome& y) {
    return x.vertices.size() == y.vertices.size() && x.indices == y.indices &&
           std::memcmp(x.vertices.data(), y.vertices.data(), x.vertices.size() * sizeof(ImDrawVert)) == 0;
}

// A few frames of the plots window at r, as screen.cpp opens it; what the last one left.
inline Outcome drawPlots(ui::Rect r, float displayW, float displayH, Preset& a, const Preset* b, ui::PlotSettings& settings,
                  int frames = 3) {
    ImGui::GetIO().DisplaySize = ImVec2(displayW, displayH);
    Outcome out;
    for (int frame = 0; frame < frames; ++frame) {
        ui::widgets().clear();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
        ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
        ImGui::Begin("Reflected intensity###plots", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoSavedSettings);
        ui::plotsPanel(a, b, settings, nullptr);
        out.scrollX = ImGui::GetScrollMaxX();
        out.scrollY = ImGui::GetScrollMaxY();
        ImGui::End();
        ImGui::Render();
    }
    out.widgets = ui::widgets().text();
    const ImDrawData* drawn = ImGui::GetDrawData();
    for (int i = 0; i < drawn->CmdListsCount; ++i) {
        const ImDrawList* list = drawn->CmdLists[i];
        out.vertices.insert(out.vertices.end(), list->VtxBuffer.begin(), list->VtxBuffer.end());
        out.indices.insert(out.indices.end(), list->IdxBuffer.begin(), list->IdxBuffer.end());
    }
    return out;
}

// "name x y w h" lines of the widget map.
inline std::map<std::string, ui::Rect> rects(const std::string& text) {
    std::map<std::string, ui::Rect> m;
    std::istringstream in(text);
    std::string name;
    ui::Rect r;
    while (in >> name >> r.x >> r.y >> r.w >> r.h) {
        m[name] = r;
    }
    return m;
}

// Every window a class may use at each UI scale, and the plots' rectangle in it: the app's, and
// both shapes it may take whatever the app decides (a right column and a band below the model).
// check(r, W, H, where) draws and checks; `where` names the case for the messages.
using PlotsCheck = std::function<void(const ui::Rect& r, float W, float H, const std::string& where)>;
inline void forEachPlotsWindow(std::initializer_list<float> scales, std::initializer_list<std::pair<float, float>> windows,
                        const PlotsCheck& check) {
    for (float s : scales) {
        CpuImGui imgui(s);
        const float uiScale = ImGui::GetIO().Fonts->Fonts[0]->FontSize / 13.0f; // as the app's uiScale()
        for (auto [W, H] : windows) {
            ui::LayoutInput in;
            in.width = W;
            in.height = H;
            in.uiScale = uiScale;
            ui::Layout layout = ui::computeLayout(in);
            const ui::Rect shapes[] = {layout.plots, {W - 0.3f * W, 0, 0.3f * W, H}, {0.35f * W, 0.58f * H, 0.65f * W, 0.42f * H}};
            for (const ui::Rect& r : shapes) {
                if (r.w < 1.0f || r.h < 1.0f) {
                    continue;
                }
                check(r, W, H,
                      "scale " + std::to_string(s) + ", window " + std::to_string(int(W)) + "x" + std::to_string(int(H)) +
                          ", plots " + std::to_string(int(r.w)) + "x" + std::to_string(int(r.h)));
            }
        }
    }
}

// Nothing scrolls, and every plot widget lies inside the plots' rectangle.
inline void expectFits(const Outcome& out, const ui::Rect& r, const std::string& where) {
    EXPECT_EQ(out.scrollY, 0.0f) << where;
    EXPECT_EQ(out.scrollX, 0.0f) << where;
    for (const auto& [name, w] : rects(out.widgets)) {
        if (name.rfind("plot.", 0) != 0) {
            continue;
        }
        EXPECT_GE(w.x, r.x) << name << ", " << where;
        EXPECT_GE(w.y, r.y) << name << ", " << where;
        EXPECT_LE(w.x + w.w, r.x + r.w + 0.5f) << name << ", " << where;
        EXPECT_LE(w.y + w.h, r.y + r.h + 0.5f) << name << ", " << where;
    }
}

} // namespace lab::plotpanel
