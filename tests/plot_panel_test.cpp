// plot_panel_test.cpp — the plots panel, drawn on the CPU (an ImGui context without a renderer)
// into the window the app gives it, at every window size and UI scale a class may use: nothing
// makes the window scroll, and every canvas lies inside the window.
#include "ui/layout.h"
#include "ui/plots.h"
#include "ui/widget_map.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

namespace lab {
namespace {

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

struct Outcome {
    float scrollX = 0, scrollY = 0;
    std::string widgets; // the widget map's text
};

// A few frames of the plots window at r, as screen.cpp opens it; what the last one left.
Outcome drawPlots(ui::Rect r, float displayW, float displayH, Preset& a, const Preset* b, ui::PlotSettings& settings) {
    ImGui::GetIO().DisplaySize = ImVec2(displayW, displayH);
    Outcome out;
    for (int frame = 0; frame < 3; ++frame) {
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
    return out;
}

// "name x y w h" lines of the widget map.
std::map<std::string, ui::Rect> rects(const std::string& text) {
    std::map<std::string, ui::Rect> m;
    std::istringstream in(text);
    std::string name;
    ui::Rect r;
    while (in >> name >> r.x >> r.y >> r.w >> r.h) {
        m[name] = r;
    }
    return m;
}

TEST(PlotPanel, FitsItsWindowAtEverySizeAndScale) {
    const std::pair<float, float> windows[] = {{1024, 768}, {1280, 800}, {1600, 900}, {1920, 1080}, {2560, 1440}};
    for (float s : {1.0f, 1.5f, 2.0f, 2.5f}) {
        CpuImGui imgui(s);
        const float uiScale = ImGui::GetIO().Fonts->Fonts[0]->FontSize / 13.0f; // as the app's uiScale()
        for (auto [W, H] : windows) {
            ui::LayoutInput in;
            in.width = W;
            in.height = H;
            in.uiScale = uiScale;
            ui::Layout layout = ui::computeLayout(in);
            // The app's rectangle, and both shapes it may take whatever the app decides:
            // a right column and a band below the model.
            const ui::Rect shapes[] = {layout.plots, {W - 0.3f * W, 0, 0.3f * W, H}, {0.35f * W, 0.58f * H, 0.65f * W, 0.42f * H}};
            for (const ui::Rect& r : shapes) {
                for (int variant = 0; variant < 4; ++variant) {
                    Preset a, b;
                    b.brdf = BrdfModel::CookTorrance;
                    a.lights.push_back(a.lights.front()); // two lights: the attenuation plot's light chooser
                    ui::PlotSettings settings;
                    settings.cartesian = variant == 1;
                    settings.scale = variant == 2 ? RadialScale::Log : RadialScale::Linear;
                    settings.lockScale = variant == 3;
                    Outcome out = drawPlots(r, W, H, a, variant >= 2 ? &b : nullptr, settings);
                    std::string where = "scale " + std::to_string(s) + ", window " + std::to_string(int(W)) + "x" +
                                        std::to_string(int(H)) + ", plots " + std::to_string(int(r.w)) + "x" +
                                        std::to_string(int(r.h)) + ", variant " + std::to_string(variant);
                    EXPECT_EQ(out.scrollY, 0.0f) << where;
                    EXPECT_EQ(out.scrollX, 0.0f) << where;
                    std::map<std::string, ui::Rect> m = rects(out.widgets);
                    ASSERT_TRUE(m.count("plot.lobe")) << where << "\n" << out.widgets; // the lobe is always shown
                    for (const auto& [name, w] : m) {
                        if (name.rfind("plot.", 0) != 0) {
                            continue;
                        }
                        EXPECT_GE(w.x, r.x) << name << ", " << where;
                        EXPECT_GE(w.y, r.y) << name << ", " << where;
                        EXPECT_LE(w.x + w.w, r.x + r.w + 0.5f) << name << ", " << where;
                        EXPECT_LE(w.y + w.h, r.y + r.h + 0.5f) << name << ", " << where;
                    }
                }
            }
        }
    }
}

} // namespace
} // namespace lab
