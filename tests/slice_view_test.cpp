// slice_view_test.cpp — the plots window's Slice view (ui/plots/plots_slice.h), drawn on the CPU: its
// colours follow the image (pure functions, then the vertices the panel draws), the readout under
// the pointer is the exact value with L and V, it fits every window, compare mode shows B and A − B
// (or a choice between them where three do not fit), and its kept images are never stale.
#include "plot_panel_kit.h"
#include "ui/plots/slice_parts.h"

#include "core/lighting/lighting.h"
#include "app/figure_export.h"
#include "core/plots/describe.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace lab {
namespace {

using namespace plotpanel;

ImU32 rgbOf(const glm::vec3& c) {
    const glm::vec3 k = glm::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f;
    return IM_COL32(static_cast<int>(k.r), static_cast<int>(k.g), static_cast<int>(k.b), 255);
}
int red(ImU32 c) { return static_cast<int>((c >> IM_COL32_R_SHIFT) & 0xFF); }
int green(ImU32 c) { return static_cast<int>((c >> IM_COL32_G_SHIFT) & 0xFF); }
int blue(ImU32 c) { return static_cast<int>((c >> IM_COL32_B_SHIFT) & 0xFF); }

Preset blinnPhong() {
    Preset p;
    p.brdf = BrdfModel::BlinnPhong;
    p.material.shininess = 32.0f;
    return p;
}

TEST(SliceView, EachSampleIsThePaletteAtItsPlaceOnTheScale) {
    const std::vector<float> values{0.0f, 0.25f, 0.5f, 1.0f, 2.0f, 0.002f, 0.0005f};
    const std::vector<ImU32> linear = ui::sliceColors(values, 2.0f, RadialScale::Linear, ValuePalette::Viridis);
    ASSERT_EQ(linear.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(linear[i], rgbOf(paletteColor(ValuePalette::Viridis, values[i] / 2.0f))) << values[i];
    }
    EXPECT_NE(linear[0], linear[4]) << "0 and the largest value are the palette's two ends";
    // Log: the plots' three decades below the largest (plotRadius), 0 below them.
    const std::vector<ImU32> log = ui::sliceColors(values, 2.0f, RadialScale::Log, ValuePalette::Grey);
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(log[i], rgbOf(paletteColor(ValuePalette::Grey, plotRadius(values[i], 2.0f, RadialScale::Log)))) << values[i];
    }
    EXPECT_EQ(log[6], log[0]) << "below three decades: the palette's first colour";
    EXPECT_GT(green(log[3]), green(rgbOf(paletteColor(ValuePalette::Grey, 0.5f)))) << "1 is 0.1 decades below 2";
    // Nothing lit: all 0 is the first colour, never a division by 0.
    for (ImU32 c : ui::sliceColors({0.0f, 0.0f}, 0.0f, RadialScale::Linear, ValuePalette::Viridis)) {
        EXPECT_EQ(c, rgbOf(paletteColor(ValuePalette::Viridis, 0.0f)));
    }
}

TEST(SliceView, TheDifferenceIsSignedAboutNearWhite) {
    const std::vector<ImU32> c = ui::differenceColors({-0.5f, 0.0f, 0.5f, 0.25f}, 0.5f);
    EXPECT_EQ(c[0], rgbOf(divergingColor(-1.0f)));
    EXPECT_EQ(c[2], rgbOf(divergingColor(1.0f)));
    EXPECT_EQ(c[3], rgbOf(divergingColor(0.5f)));
    EXPECT_GT(blue(c[0]), red(c[0])) << "B reflects more: purple";
    EXPECT_GT(red(c[2]), blue(c[2])) << "A reflects more: orange";
    EXPECT_GT(std::min({red(c[1]), green(c[1]), blue(c[1])}), 240) << "equal: near-white";
    for (ImU32 same : ui::differenceColors({0.0f, 0.0f}, 0.0f)) {
        EXPECT_EQ(same, c[1]) << "A and B alike: near-white everywhere";
    }
    EXPECT_EQ(ui::largestMagnitude({0.1f, -0.7f, 0.3f}), 0.7f);
}

// The panel's vertices: one per sample, where the sample lies in its image (θh across, θd up), in
// sliceColors' colour of that sample.
TEST(SliceView, TheDrawnVerticesAreTheImagesSamplesInTheirColours) {
    CpuImGui imgui(1.0f);
    Preset a = blinnPhong();
    ui::PlotSettings settings;
    settings.view = ui::PlotTab::Slice;
    settings.palette = ValuePalette::Viridis;
    const ui::Rect r{880, 0, 400, 800};
    const Outcome out = drawPlots(r, 1280, 800, a, nullptr, settings);
    std::map<std::string, ui::Rect> m = rects(out.widgets);
    ASSERT_TRUE(m.count("plot.slice.a")) << out.widgets;
    EXPECT_FALSE(m.count("plot.slice.b"));
    const ui::Rect img = m["plot.slice.a"];
    EXPECT_GT(img.w, 100.0f);
    const SliceImage image = sampleSlice(lobeInputs(a, 0.0f));
    const PlotComponent c = settings.slice.component;
    EXPECT_EQ(c, PlotComponent::Specular) << "the view opens on the specular term";
    const std::vector<ImU32> colors = ui::sliceColors(image.component(c), image.largest(c), settings.scale, settings.palette);
    int found = 0;
    for (auto [column, row] : {std::pair{0, 0}, {0, 45}, {10, 40}, {12, 80}, {45, 45}, {90, 0}, {89, 89}}) {
        const ImVec2 at(img.x + img.w * column / 90.0f, img.y + img.h * (1.0f - row / 90.0f));
        const ImU32 want = colors[static_cast<std::size_t>(image.index(column, row))];
        bool here = false;
        for (const ImDrawVert& v : out.vertices) {
            if (v.pos.x == at.x && v.pos.y == at.y && v.col == want) {
                here = true;
                break;
            }
        }
        EXPECT_TRUE(here) << "no vertex at (" << column << ", " << row << ") in the sample's colour";
        found += here;
    }
    EXPECT_EQ(found, 7);
    // Blinn-Phong's specular depends on θh alone: bright at θh 0 whatever θd, dark far from it.
    EXPECT_EQ(colors[static_cast<std::size_t>(image.index(0, 10))], colors[static_cast<std::size_t>(image.index(0, 70))]);
    EXPECT_GT(green(colors[static_cast<std::size_t>(image.index(0, 45))]), 200);
    EXPECT_LT(green(colors[static_cast<std::size_t>(image.index(60, 45))]), 40);
}

// The figure's CSV is the GUI's image: what the Slice tab keeps and draws, written by Export figures.
TEST(SliceView, ExportFiguresWritesTheImageTheTabShows) {
    CpuImGui imgui(1.0f);
    Preset a = blinnPhong();
    ui::PlotSettings settings;
    settings.view = ui::PlotTab::Slice;
    drawPlots({880, 0, 400, 800}, 1280, 800, a, nullptr, settings);
    const std::shared_ptr<const SliceImage> shown = settings.slice.images.find({lobeInputs(a, 0.0f), false});
    ASSERT_TRUE(shown) << "the tab keeps A's full image";
    std::string csv;
    for (const Download& d : exportFigures(a, nullptr, settings, 1.0f, Theme::Light)) {
        csv = d.name == "slice.csv" ? d.bytes : csv;
    }
    ASSERT_FALSE(csv.empty());
    EXPECT_EQ(csv, sliceCsv(*shown));
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 91 * 91);
}

// The readout under the pointer: the angles, the exact value there (sliceValue, not the image's
// samples), and L and V from sliceVectors; in compare mode A's, B's and A − B.
TEST(SliceView, TheReadoutUnderThePointerIsTheExactValueWithLAndV) {
    CpuImGui imgui(1.0f);
    ImGui::GetIO().DisplaySize = ImVec2(800, 600);
    ImGui::NewFrame();
    Preset a = blinnPhong(), b = blinnPhong();
    b.material.shininess = 8.0f;
    ui::slice::Frame f;
    f.images.inA = lobeInputs(a, 0.0f);
    f.images.inB = lobeInputs(b, 0.0f);
    f.images.b = std::make_shared<const SliceImage>(sampleSlice(f.images.inB));
    f.marker = planeToSlice(30.0f, 20.0f);
    const ui::slice::Hover hover{0, 12.3f, 40.1f};
    const ui::plotkit::Readout r = ui::slice::readout(f, hover, ui::plotkit::pens());
    std::string text;
    for (const ui::plotkit::Token& t : r.tokens) {
        text += t.text + "|";
    }
    const float va = sliceValue(f.images.inA, 12.3f, 40.1f).specular, vb = sliceValue(f.images.inB, 12.3f, 40.1f).specular;
    const SliceVectors v = sliceVectors(12.3f, 40.1f);
    for (const std::string& want :
         {format("A %.3f", double(va)), format("B %.3f", double(vb)), format("B %+.3f", double(va - vb)),
          format("L (%.2f, %.2f, %.2f)", double(v.L.x), double(v.L.y), double(v.L.z)),
          format("V (%.2f, %.2f, %.2f)", double(v.V.x), double(v.V.y), double(v.V.z)), std::string("12.3"),
          std::string("40.1")}) {
        EXPECT_NE(text.find(want), std::string::npos) << want << " in " << text;
    }
    EXPECT_NE(va, vb);
    EXPECT_NE(text.find("off this slice"), std::string::npos) << "θo 20° is not θi 30°: " << text;
    ImGui::EndFrame();
}

// Where the images need the room, the readout is brief (no explanations), then cut to whole lines,
// and a cut is named in the widget map; where there is room it is whole. Its words wrap, so none
// runs past the plots' side.
TEST(SliceView, TheReadoutGivesWayToTheImagesAndSaysWhenItIsCut) {
    CpuImGui imgui(2.5f);
    ImGui::GetIO().DisplaySize = ImVec2(1920, 1080);
    ImGui::NewFrame();
    const ui::plotkit::Pens p = ui::plotkit::pens();
    ui::slice::Frame f;
    f.images.inA = lobeInputs(blinnPhong(), 0.0f);
    f.marker = planeToSlice(30.0f, 20.0f);
    f.shown = ui::slice::Shown::A;
    auto text = [&](const ui::slice::Frame& at) {
        std::string t;
        for (const ui::plotkit::Token& k : ui::slice::readout(at, ui::slice::Hover{}, p).tokens) {
            t += k.text + "|";
        }
        return t;
    };
    const ui::slice::Placement roomy = ui::slice::placeReadout(f, ImVec2(0, 0), ImVec2(560, 1400), p);
    EXPECT_FALSE(roomy.brief || roomy.cut);
    EXPECT_NE(text(f).find("from N to H"), std::string::npos) << text(f);
    const float whole = roomy.strip.w;
    EXPECT_GE(whole, 5.0f * p.line) << "its long tokens wrap at 560 px and 2.5x";

    const ui::slice::Placement tight = ui::slice::placeReadout(f, ImVec2(0, 0), ImVec2(560, whole + p.gap + 12.0f * p.line - 1.0f), p);
    EXPECT_TRUE(tight.brief);
    EXPECT_FALSE(tight.cut) << "the brief readout fits whole";
    EXPECT_LT(tight.strip.w, whole);
    EXPECT_GE(tight.images.w, 12.0f * p.line);
    ui::slice::Frame brief = f;
    brief.brief = true;
    EXPECT_EQ(text(brief).find("from N to H"), std::string::npos) << text(brief);
    EXPECT_NE(text(brief).find("off this slice|"), std::string::npos) << text(brief);

    const ui::slice::Placement cut = ui::slice::placeReadout(f, ImVec2(0, 0), ImVec2(560, 13.0f * p.line), p);
    EXPECT_TRUE(cut.brief && cut.cut);
    EXPECT_NEAR(std::fmod(cut.strip.w, p.line), 0.0f, 0.01f) << "whole lines";
    EXPECT_GE(cut.images.w, 12.0f * p.line);
    ImGui::EndFrame();

    // Drawn in such a window, the cut is in the widget map; in a roomy one nothing is.
    ui::PlotSettings settings;
    settings.view = ui::PlotTab::Slice;
    Preset a = blinnPhong();
    const Outcome small = drawPlots({1360, 600, 560, 480}, 1920, 1080, a, nullptr, settings);
    EXPECT_TRUE(rects(small.widgets).count("clipped:plot.slice.readout")) << small.widgets;
    settings.shownView = -1;
    const Outcome large = drawPlots({1360, 0, 560, 1080}, 1920, 1080, a, nullptr, settings);
    EXPECT_TRUE(rects(large.widgets).count("plot.slice.readout") && rects(large.widgets).count("plot.slice.a")) << large.widgets;
    for (const auto& [name, r] : rects(large.widgets)) {
        EXPECT_NE(name.rfind("clipped:", 0), 0u) << name;
    }
}

// The Slice view at every window and UI scale, alone and in compare mode: it fits and never scrolls;
// compare mode shows A, B and A − B, or, where three do not fit, the choice between A | B and A − B.
TEST(SliceView, FitsItsWindowAtEverySizeAndScale) {
    ui::PlotSettings settings;
    settings.view = ui::PlotTab::Slice;
    forEachPlotsWindow({1.0f, 2.0f, 2.5f}, {{1024, 768}, {1280, 800}, {1920, 1080}, {390, 844}},
                       [&](const ui::Rect& r, float W, float H, const std::string& where) {
        Preset a = blinnPhong(), b;
        for (const Preset* compare : {static_cast<const Preset*>(nullptr), static_cast<const Preset*>(&b)}) {
            settings.shownView = -1; // a new ImGui context opens its first tab: select the Slice view again
            const Outcome out = drawPlots(r, W, H, a, compare, settings);
            std::map<std::string, ui::Rect> m = rects(out.widgets);
            const std::string at = where + (compare ? ", compare" : "");
            EXPECT_FALSE(m.count("plot.lobe")) << at;
            expectFits(out, r, at);
            EXPECT_LT(out.vertices.size(), std::size_t(65536)) << at;
            if (r.h >= 20.0f * ImGui::GetFontSize() && r.w >= 14.0f * ImGui::GetFontSize()) {
                EXPECT_TRUE(m.count("plot.slice.a") || m.count("plot.slice.difference-image")) << at << "\n" << out.widgets;
            }
            if (compare && m.count("plot.slice.a")) {
                const bool all = m.count("plot.slice.b") && m.count("plot.slice.difference-image");
                EXPECT_TRUE(all || m.count("plot.slice.difference") || m.count("plot.slice.options")) << "three images or the choice, " << at << "\n" << out.widgets;
                EXPECT_EQ(all, m.count("plot.slice.difference-legend") == 1) << at;
            }
        }
    });
}

// Compare mode in a column: A, B and A − B with both legends; in a low band, the choice, and choosing
// A − B shows the difference alone with its legend.
TEST(SliceView, CompareModeShowsBAndTheDifferenceOrAChoice) {
    CpuImGui imgui(1.0f);
    Preset a = blinnPhong(), b = blinnPhong();
    b.material.shininess = 4.0f;
    ui::PlotSettings settings;
    settings.view = ui::PlotTab::Slice;
    std::map<std::string, ui::Rect> m = rects(drawPlots({880, 0, 400, 800}, 1280, 800, a, &b, settings).widgets);
    for (const char* name : {"plot.slice.a", "plot.slice.b", "plot.slice.difference-image", "plot.slice.legend",
                             "plot.slice.difference-legend"}) {
        EXPECT_TRUE(m.count(name)) << name;
    }
    EXPECT_FALSE(m.count("plot.slice.difference")) << "three fit: no choice offered";
    EXPECT_EQ(m["plot.slice.a"].w, m["plot.slice.b"].w) << "A and B alike";

    // A band below the model, lowered until three no longer fit: then A | B, with the choice.
    ui::Rect band{300, 0, 980, 0};
    for (float h = 320.0f; h >= 150.0f && !m.count("plot.slice.difference"); h -= 10.0f) {
        band = {300, 800 - h, 980, h};
        m = rects(drawPlots(band, 1280, 800, a, &b, settings).widgets);
    }
    ASSERT_TRUE(m.count("plot.slice.difference")) << "no band offers the choice";
    EXPECT_TRUE(m.count("plot.slice.a") && m.count("plot.slice.b")) << band.h;
    EXPECT_FALSE(m.count("plot.slice.difference-image")) << band.h;
    settings.slice.compare = ui::SliceCompare::Difference;
    m = rects(drawPlots(band, 1280, 800, a, &b, settings).widgets);
    EXPECT_TRUE(m.count("plot.slice.difference-image") && m.count("plot.slice.difference-legend"));
    EXPECT_FALSE(m.count("plot.slice.a") || m.count("plot.slice.legend"));
}

// The images are kept: a frame with nothing new computes nothing, the incident angle moves only the
// marker, and after each edit what is drawn is what a fresh state draws.
TEST(SliceView, TheKeptImagesNeverShowStaleData) {
    CpuImGui imgui(1.0f);
    ui::Rect r{880, 0, 400, 800};
    Preset a = blinnPhong(), b;
    const Preset* compare = nullptr;
    ui::PlotSettings warm;
    warm.view = ui::PlotTab::Slice;
    drawPlots(r, 1280, 800, a, compare, warm);
    const std::size_t computed = warm.slice.computed();
    EXPECT_GT(computed, 0u);
    drawPlots(r, 1280, 800, a, compare, warm);
    EXPECT_EQ(warm.slice.computed(), computed) << "nothing changed, yet something was computed again";
    a.plotIncidentDeg = 50.0f;
    drawPlots(r, 1280, 800, a, compare, warm);
    EXPECT_EQ(warm.slice.computed(), computed) << "the image does not depend on the incident angle";
    const std::vector<std::pair<std::string, std::function<void()>>> edits{
        {"shininess", [&] { a.material.shininess = 7.0f; }},
        {"BRDF", [&] { a.brdf = BrdfModel::CookTorrance; }},
        {"specular switched off", [&] { a.terms.specular = false; }},
        {"compare set", [&] { compare = &b; }},
        {"B's shininess", [&] { b.material.shininess = 90.0f; }},
        {"component", [&] { warm.slice.component = PlotComponent::Total; }},
        {"log scale", [&] { warm.scale = RadialScale::Log; }},
        {"palette", [&] { warm.palette = ValuePalette::Grey; }},
        {"window", [&] { r = {300, 500, 980, 300}; }},
    };
    for (const auto& [what, edit] : edits) {
        edit();
        const std::size_t before = warm.slice.computed();
        const Outcome cached = drawPlots(r, 1280, 800, a, compare, warm);
        EXPECT_GT(warm.slice.computed(), before) << "the " << what << " changed nothing the cache keys on";
        ui::PlotSettings cold = warm;
        cold.slice = ui::SliceState{};
        cold.slice.component = warm.slice.component;
        cold.slice.compare = warm.slice.compare;
        EXPECT_TRUE(sameDrawing(cached, drawPlots(r, 1280, 800, a, compare, cold))) << "after an edit of the " << what;
    }
}

// The page's words for the slice (core/plots/describe.h), computed from the image: Blinn-Phong's specular
// is Ks cos^n θh, the same at every θd, above half its peak while cos^32 θh > 0.5 (θh ≤ 11°); Phong's
// depends on θd too; a switched-off term says so.
TEST(SliceView, TheWordsForTheSliceComeFromItsImage) {
    Preset blinn = blinnPhong();
    const std::string b = describeSlice(blinn);
    for (const char* want : {"largest 1.000 at theta h 0", "up to theta h 11 degrees", "vertical stripes"}) {
        EXPECT_NE(b.find(want), std::string::npos) << want << " in: " << b;
    }
    Preset phong = blinn;
    phong.brdf = BrdfModel::Phong;
    EXPECT_NE(describeSlice(phong).find("changes with theta d"), std::string::npos) << describeSlice(phong);
    blinn.terms.specular = false;
    EXPECT_NE(describeSlice(blinn).find("0 everywhere"), std::string::npos) << describeSlice(blinn);
}

} // namespace
} // namespace lab
