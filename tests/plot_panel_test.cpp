// plot_panel_test.cpp — the plots panel, drawn on the CPU (an ImGui context without a renderer)
// into the window the app gives it, at every window size and UI scale a class may use: nothing
// makes the window scroll, and every canvas lies inside the window.
#include "plot_panel_kit.h"
#include "core/plots/energy.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace lab {
namespace {

using namespace plotpanel;

TEST(PlotPanel, FitsItsWindowAtEverySizeAndScale) {
    forEachPlotsWindow({1.0f, 1.5f, 2.0f, 2.5f}, {{1024, 768}, {1280, 800}, {1600, 900}, {1920, 1080}, {2560, 1440}},
                       [](const ui::Rect& r, float W, float H, const std::string& where) {
        for (int variant = 0; variant < 4; ++variant) {
            Preset a, b;
            b.brdf = BrdfModel::CookTorrance;
            a.lights.push_back(a.lights.front()); // two lights: the attenuation plot's light chooser
            ui::PlotSettings settings;
            settings.cartesian = variant == 1;
            settings.scale = variant == 2 ? RadialScale::Log : RadialScale::Linear;
            settings.lockScale = variant == 3;
            Outcome out = drawPlots(r, W, H, a, variant >= 2 ? &b : nullptr, settings);
            const std::string at = where + ", variant " + std::to_string(variant);
            ASSERT_TRUE(rects(out.widgets).count("plot.lobe")) << at << "\n" << out.widgets; // the lobe is always shown
            expectFits(out, r, at);
        }
    });
}

// The plots keep their samples and curves from frame to frame (PlotSettings::cache). A cached
// plot never shows stale data: after every kind of edit, what is drawn is exactly what a fresh
// cache draws; and a frame in which nothing changed computes nothing.
TEST(PlotPanel, TheCacheNeverShowsStaleData) {
    CpuImGui imgui(1.0f);
    ui::Rect r{900, 0, 380, 800};
    Preset a, b;
    b.brdf = BrdfModel::CookTorrance;
    a.lights.push_back(a.lights.front());
    const Preset* compare = &b;
    ui::PlotSettings warm;
    drawPlots(r, 1280, 800, a, compare, warm);
    const std::size_t computed = warm.cache.computed();
    EXPECT_GT(computed, 0u);
    drawPlots(r, 1280, 800, a, compare, warm);
    EXPECT_EQ(warm.cache.computed(), computed) << "nothing changed, yet something was computed again";

    // Each edit, whether it leads to something not drawn before (the others go back to what the
    // cache holds, or draw nothing it keeps), and the edit.
    struct Edit {
        std::string what;
        bool isNew;
        std::function<void()> apply;
    };
    const std::vector<Edit> edits{
        {"diffuse colour", true, [&] { a.material.diffuse = {0.2f, 0.6f, 0.3f}; }},
        {"specular colour", true, [&] { a.material.specular = {0.5f, 0.5f, 0.1f}; }},
        {"shininess", true, [&] { a.material.shininess = 7.0f; }},
        {"BRDF", true, [&] { a.brdf = BrdfModel::BlinnPhong; }},
        {"Cook-Torrance", true, [&] { a.brdf = BrdfModel::CookTorrance; }},
        {"roughness", true, [&] { a.cookTorrance.roughness = 0.6f; }},
        {"distribution", true, [&] { a.cookTorrance.distribution = Distribution::Ggx; }},
        {"Fresnel", true, [&] { a.cookTorrance.fresnel = FresnelMode::Full; }},
        {"ior", true, [&] { a.cookTorrance.ior = 2.5f; }},
        {"geometry term", true, [&] { a.cookTorrance.geometry = false; }},
        {"specular switched off", true, [&] { a.terms.specular = false; }},
        {"diffuse switched off", true, [&] { a.terms.diffuse = false; }},
        {"both back on", false, [&] { a.terms = {}; }},
        {"incident angle", true, [&] { a.plotIncidentDeg = 20.0f; }},
        {"B's shininess", true, [&] { b.material.shininess = 3.0f; }},
        {"no compare set", false, [&] { compare = nullptr; }},
        {"compare set again", false, [&] { compare = &b; }},
        {"an overlaid angle", true, [&] { warm.overlayDeg.y = 40.0f; }},
        {"log scale", true, [&] { warm.scale = RadialScale::Log; }},
        {"Cartesian", true, [&] { warm.cartesian = true; }},
        {"polar again", false, [&] { warm.cartesian = false; }},
        {"lock scale, then a change", true, [&] { warm.lockScale = true; }},
        {"shininess while locked", true, [&] { a.material.shininess = 90.0f; }},
        {"attenuation", true, [&] { a.lights[0].attenuation = {1.0f, 0.7f, 0.2f}; }},
        {"light distance", true, [&] { a.lights[0].position = {4.0f, 5.0f, 1.0f}; }},
        {"other light", false, [&] { warm.attenuationLight = 1; }},
        {"directional light", false, [&] { a.lights[1].type = LightType::Directional; }},
        {"window size", true, [&] { r = {700, 0, 580, 700}; }},
        {"a band below the model", true, [&] { r = {300, 500, 980, 300}; }},
    };
    for (const auto& [what, isNew, edit] : edits) {
        edit();
        const std::size_t before = warm.cache.computed();
        Outcome cached = drawPlots(r, 1280, 800, a, compare, warm);
        ui::PlotSettings cold = warm;
        cold.cache = ui::PlotCache{};
        Outcome fresh = drawPlots(r, 1280, 800, a, compare, cold);
        EXPECT_TRUE(sameDrawing(cached, fresh)) << "after an edit of the " << what;
        EXPECT_FALSE(cached.vertices.empty()) << what;
        if (isNew) {
            EXPECT_GT(warm.cache.computed(), before) << "the " << what << " changed nothing the cache keys on";
        } else {
            EXPECT_EQ(warm.cache.computed(), before) << "the " << what << " should have found what it drew before";
        }
    }
}

// What the plots keep as painted (PaintedLines: long lines, whole figures such as grids, arrows and
// axes, readouts) is a copy of what painting afresh draws: after each edit, the last of a few frames
// (which copies them) is byte for byte one frame that paints everything again, in compare mode.
TEST(PlotPanel, KeptPaintingsAreWhatPaintingAfreshDraws) {
    CpuImGui imgui(1.0f);
    for (ui::PlotTab view : {ui::PlotTab::Plane, ui::PlotTab::Lobe3d}) {
        ui::Rect r{800, 0, 480, 800};
        Preset a, b;
        b.brdf = BrdfModel::CookTorrance;
        ui::PlotSettings warm;
        warm.view = view;
        const std::vector<std::pair<std::string, std::function<void()>>> edits{
            {"nothing", [] {}},
            {"shininess", [&] { a.material.shininess = 12.0f; }},
            {"B's BRDF", [&] { b.brdf = BrdfModel::Phong; }},
            {"log scale", [&] { warm.scale = RadialScale::Log; }},
            {"Cartesian", [&] { warm.cartesian = true; }},
            {"incident angle", [&] { a.plotIncidentDeg = 25.0f; }},
            {"V", [&] { warm.viewerDeg = -30.0f; }},
            {"attenuation", [&] { a.lights[0].attenuation = {1.0f, 0.7f, 0.2f}; }},
            {"a band below the model", [&] { r = {300, 500, 980, 300}; }},
            {"back to the column", [&] { r = {800, 0, 480, 800}; }},
        };
        for (const auto& [what, edit] : edits) {
            edit();
            const Outcome kept = drawPlots(r, 1280, 800, a, &b, warm);
            ui::PlotSettings afresh = warm;
            afresh.cache.painted() = ui::PaintedLines{};
            const Outcome painted = drawPlots(r, 1280, 800, a, &b, afresh, 1);
            EXPECT_TRUE(sameDrawing(kept, painted)) << "view " << static_cast<int>(view) << ", after an edit of the " << what;
        }
    }
}

// The 3D lobe view (ui/plots/plots_3d.h) fits the same windows: its canvases and controls inside the
// window, nothing scrolled, the surface and the map drawn (more vertices than the grid has) and
// ImGui's 16-bit indices never overflowed (under 65536 vertices in the window's list).
TEST(PlotPanel, TheLobe3dViewFitsItsWindowAtEverySizeAndScale) {
    // (A phone's compact layout gives the plots the page's width: the browser tests' 390x844.)
    forEachPlotsWindow({1.0f, 2.0f, 2.5f}, {{1024, 768}, {1280, 800}, {1920, 1080}},
                       [](const ui::Rect& r, float W, float H, const std::string& where) {
        Preset a, b;
        b.brdf = BrdfModel::CookTorrance;
        ui::PlotSettings settings;
        settings.view = ui::PlotTab::Lobe3d;
        Outcome out = drawPlots(r, W, H, a, &b, settings);
        std::map<std::string, ui::Rect> m = rects(out.widgets);
        ASSERT_TRUE(m.count("plot.lobe3d") && m.count("plot.lobe3d.map")) << where << "\n" << out.widgets;
        EXPECT_FALSE(m.count("plot.lobe")) << "the plane plots are not drawn under the 3D view, " << where;
        expectFits(out, r, where);
        // The surface and the map are drawn wherever the lobe's canvas has room for a lobe
        // (a band 322 pixels low at UI scale 2.5 leaves it 3 lines: there it is left out).
        if (m["plot.lobe3d"].h >= 5.0f * ImGui::GetFontSize()) {
            EXPECT_GT(out.vertices.size(), std::size_t(kLobeRings * kLobeMeridians)) << where << "\n" << out.widgets;
        }
        EXPECT_LT(out.vertices.size(), std::size_t(65536)) << where;
    });
}

// The 3D view keeps its grids and meshes: a frame in which nothing changed computes nothing, and
// after each edit what is drawn is what a fresh state draws.
TEST(PlotPanel, TheLobe3dViewNeverShowsStaleData) {
    CpuImGui imgui(1.0f);
    ui::Rect r{800, 0, 480, 800};
    Preset a, b;
    b.brdf = BrdfModel::BlinnPhong;
    const Preset* compare = nullptr;
    ui::PlotSettings warm;
    warm.view = ui::PlotTab::Lobe3d;
    drawPlots(r, 1280, 800, a, compare, warm);
    const std::size_t computed = warm.lobe3d.computed();
    EXPECT_GT(computed, 0u);
    drawPlots(r, 1280, 800, a, compare, warm);
    EXPECT_EQ(warm.lobe3d.computed(), computed) << "nothing changed, yet something was computed again";
    const std::vector<std::pair<std::string, std::function<void()>>> edits{
        {"shininess", [&] { a.material.shininess = 7.0f; }},
        {"incident angle", [&] { a.plotIncidentDeg = -55.0f; }},
        {"BRDF", [&] { a.brdf = BrdfModel::CookTorrance; }},
        {"compare set", [&] { compare = &b; }},
        {"B's shininess", [&] { b.material.shininess = 90.0f; }},
        {"component", [&] { warm.lobe3d.component = PlotComponent::Specular; }},
        {"log scale", [&] { warm.scale = RadialScale::Log; }},
        {"orbit", [&] { warm.lobe3d.yawDeg = 80.0f; warm.lobe3d.pitchDeg = 60.0f; }},
        {"window", [&] { r = {300, 500, 980, 300}; }},
    };
    for (const auto& [what, edit] : edits) {
        edit();
        const std::size_t before = warm.lobe3d.computed();
        Outcome cached = drawPlots(r, 1280, 800, a, compare, warm);
        EXPECT_GT(warm.lobe3d.computed(), before) << "the " << what << " changed nothing the cache keys on";
        ui::PlotSettings cold = warm;
        cold.cache = ui::PlotCache{}; // the lines painted afresh too (PaintedLines)
        cold.lobe3d = ui::Lobe3dState{};
        cold.lobe3d.component = warm.lobe3d.component;
        cold.lobe3d.yawDeg = warm.lobe3d.yawDeg;
        cold.lobe3d.pitchDeg = warm.lobe3d.pitchDeg;
        Outcome fresh = drawPlots(r, 1280, 800, a, compare, cold);
        EXPECT_TRUE(sameDrawing(cached, fresh)) << "after an edit of the " << what;
    }
}

// The Energy view at every window and UI scale: it fits, shows its canvas, and never scrolls.
TEST(PlotPanel, TheEnergyViewFitsItsWindowAtEverySizeAndScale) {
    ui::PlotSettings settings; // one for all: the curves (35 ms each) are computed once, the layout every time
    settings.view = ui::PlotTab::Energy;
    forEachPlotsWindow({1.0f, 2.0f, 2.5f}, {{1024, 768}, {1280, 800}, {1920, 1080}, {390, 844}},
                       [&](const ui::Rect& r, float W, float H, const std::string& where) {
        Preset a, b;
        b.material.shininess = 5.0f;
        settings.shownView = -1; // a new ImGui context opens its first tab: select the Energy view again
        Outcome out = drawPlots(r, W, H, a, &b, settings);
        std::map<std::string, ui::Rect> m = rects(out.widgets);
        ASSERT_TRUE(m.count("plot.energy")) << where << "\n" << out.widgets;
        EXPECT_FALSE(m.count("plot.lobe")) << "the plane plots are not drawn under the Energy view, " << where;
        expectFits(out, r, where);
    });
}

// The albedo curve is computed once per material (about 90 albedos), not once a frame; an edit of
// the material computes it again and what is drawn is what a fresh cache draws; a click in the
// plot sets the incident angle from where it lands (the x axis is θi from 0° to 90°), keeping its side.
TEST(PlotPanel, TheEnergyViewKeepsItsCurveAndAClickSetsTheIncidentAngle) {
    CpuImGui imgui(1.0f);
    ui::Rect r{800, 0, 480, 800};
    Preset a;
    ui::PlotSettings warm;
    warm.view = ui::PlotTab::Energy;
    drawPlots(r, 1280, 800, a, nullptr, warm);
    const std::size_t computed = warm.cache.computed();
    EXPECT_GT(computed, 0u);
    drawPlots(r, 1280, 800, a, nullptr, warm);
    EXPECT_EQ(warm.cache.computed(), computed) << "nothing changed, yet something was computed again";
    a.plotIncidentDeg = 70.0f; // the marker moves; the curve stays
    Outcome moved = drawPlots(r, 1280, 800, a, nullptr, warm);
    EXPECT_EQ(warm.cache.computed(), computed + 1)
        << "the incident angle is not part of the curve: only the albedo at the new angle (the readout's) is computed";
    a.material.shininess = 3.0f;
    Outcome cached = drawPlots(r, 1280, 800, a, nullptr, warm);
    EXPECT_GT(warm.cache.computed(), computed) << "a new shininess must give a new curve";
    EXPECT_FALSE(sameDrawing(moved, cached)) << "the curve did not change with the shininess";
    ui::PlotSettings cold;
    cold.view = ui::PlotTab::Energy;
    EXPECT_TRUE(sameDrawing(cached, drawPlots(r, 1280, 800, a, nullptr, cold)));

    // A click at 1/3 of the plot's width from its left axis... found from the canvas's rectangle:
    // the axis starts after the labels, so click at two points and check the angles grow and
    // the side of the angle (negative: L on the other side) is kept.
    std::map<std::string, ui::Rect> m = rects(cached.widgets);
    ASSERT_TRUE(m.count("plot.energy"));
    const ui::Rect c = m["plot.energy"];
    auto clickAt = [&](float u) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(c.x + u * c.w, c.y + c.h * 0.5f);
        io.MouseDown[0] = true;
        drawPlots(r, 1280, 800, a, nullptr, warm);
        io.MouseDown[0] = false;
        drawPlots(r, 1280, 800, a, nullptr, warm);
        return a.plotIncidentDeg;
    };
    a.plotIncidentDeg = -10.0f;
    const float left = clickAt(0.3f);
    const float right = clickAt(0.8f);
    EXPECT_LT(left, 0.0f) << "the side of the incident angle is kept";
    EXPECT_LT(right, left) << "further right is a larger angle";
    EXPECT_GT(-left, 10.0f);
    EXPECT_LE(-right, 90.0f);
    EXPECT_EQ(std::round(right), right) << "whole degrees, as dragging L gives";
}

// A change is inputs other than the previous frame's, and goes on while the pointer holds the
// widget (a paused drag); inputs with a NaN (equal to nothing) are never a change, so that a
// lagging readout does not owe frames for ever.
TEST(PlotPanel, AChangeIsOtherInputsThanThePreviousFramesAndLastsWhileHeld) {
    using ui::Change;
    ui::ChangeWatch watch;
    LobeInputs in = lobeInputs(Preset{}, 30.0f);
    EXPECT_EQ(watch.observe(in, 1, false), Change::Still) << "the first frame";
    EXPECT_EQ(watch.observe(in, 2, true), Change::Still) << "the same inputs, held: no change was going on";
    in.material.shininess += 1.0f;
    EXPECT_EQ(watch.observe(in, 3, true), Change::Changed);
    EXPECT_EQ(watch.observe(in, 4, true), Change::Held) << "the drag paused, the slider still held";
    EXPECT_EQ(watch.observe(in, 5, true), Change::Held);
    EXPECT_EQ(watch.observe(in, 6, false), Change::Still) << "released";
    in.material.shininess += 1.0f;
    EXPECT_EQ(watch.observe(in, 7, false), Change::Changed) << "a key or a typed value";
    EXPECT_EQ(watch.observe(in, 8, false), Change::Still);
    in.material.shininess += 1.0f;
    EXPECT_EQ(watch.observe(in, 10, false), Change::Still) << "a frame without the view in between";
    in.incidentDeg = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(watch.observe(in, 11, true), Change::Still);
    EXPECT_EQ(watch.observe(in, 12, true), Change::Still);
}

TEST(PlotPanel, RecentlyUsedReplacesTheOldestAndKeepsWhatWasHandedOut) {
    ui::RecentlyUsed<int, std::string> cache(2);
    int made = 0;
    auto make = [&](const char* text) {
        return [&made, text] {
            ++made;
            return std::string(text);
        };
    };
    std::shared_ptr<const std::string> one = cache.get(1, make("one"));
    cache.get(2, make("two"));
    EXPECT_EQ(*cache.get(1, make("not made")), "one"); // found: 1 is now the most recent
    EXPECT_EQ(made, 2);
    cache.get(3, make("three")); // replaces 2, the least recently used
    EXPECT_EQ(*cache.get(1, make("not made")), "one");
    EXPECT_EQ(*cache.get(2, make("two again")), "two again");
    EXPECT_EQ(made, 4);
    EXPECT_EQ(cache.made(), 4u);
    cache.get(4, make("four"));
    cache.get(5, make("five")); // 1 is long gone from the cache, but what was handed out stays valid
    EXPECT_EQ(*one, "one");
}

// Issue 28: the albedo and ρ(θi) lag while their inputs change frame after frame (a drag), and
// are exact in the first frame after the change ends; meanwhile the cache is owed() a frame.
TEST(PlotPanel, TheAlbedoLagsDuringAChangeAndIsExactTheFrameAfterIt) {
    using Slot = ui::PlotCache::Slot;
    ui::PlotCache cache;
    Preset a;
    a.brdf = BrdfModel::CookTorrance;
    double now = 10.0;
    const LobeInputs inB = lobeInputs(Preset{}, 30.0f);
    auto frame = [&](float shininess, bool held = false) {
        cache.beginFrame(held);
        a.material.shininess = shininess;
        a.cookTorrance.roughness = 0.1f + shininess / 1000.0f; // the BRDF in use changes too
        const ui::Lagged<std::optional<Albedo>> shown = cache.laggingAlbedo(Slot::PlaneA, lobeInputs(a, 30.0f), now);
        // B's readout has its own slot: A's change does not keep it waiting.
        EXPECT_FALSE(cache.laggingAlbedo(Slot::PlaneB, inB, now).stale);
        return shown;
    };
    const ui::Lagged<std::optional<Albedo>> first = frame(10.0f);
    EXPECT_FALSE(first.stale) << "nothing to show yet: computed at once";
    EXPECT_FALSE(cache.owed());
    // A drag: a new value every 1/60 s. The first frames show the first value and owe a frame.
    int computedDuring = 0;
    const int perLag = static_cast<int>(ui::PlotCache::kAlbedoLagSeconds * 60.0); // frames between two computations
    const double start = now;
    for (int i = 1; i <= perLag * 5 / 2; ++i) {
        now = start + i / 60.0;
        const ui::Lagged<std::optional<Albedo>> shown = frame(10.0f + float(i));
        if (shown.stale) {
            EXPECT_TRUE(cache.owed());
        } else {
            ++computedDuring;
            EXPECT_EQ(shown.value->value().total(), lab::albedo(lobeInputs(a, 30.0f))->total());
        }
        if (i < perLag) {
            EXPECT_TRUE(shown.stale) << "frame " << i << " of the drag, " << i / 60.0 << " s after the last computation";
            EXPECT_EQ(shown.value, first.value) << "the latest value computed is shown";
        }
    }
    EXPECT_EQ(computedDuring, 2) << "at most every " << ui::PlotCache::kAlbedoLagSeconds << " s during the change";
    // The change ends: the next frame has the last frame's inputs and shows their exact value.
    now += 1.0 / 60.0;
    const ui::Lagged<std::optional<Albedo>> after = frame(10.0f + float(perLag * 5 / 2));
    EXPECT_FALSE(after.stale);
    EXPECT_FALSE(cache.owed()) << "exact: no further frame is owed";
    EXPECT_EQ(after.value->value().total(), lab::albedo(lobeInputs(a, 30.0f))->total());
    // A drag that pauses with the slider held: still stale, and no frame owed (the release is an
    // input and draws one); released, exact.
    frame(200.0f, true);
    const ui::Lagged<std::optional<Albedo>> paused = frame(200.0f, true);
    EXPECT_TRUE(paused.stale) << "the change is not over while the slider is held";
    EXPECT_FALSE(cache.owed()) << "no frames while the pointer holds still";
    const ui::Lagged<std::optional<Albedo>> released = frame(200.0f, false);
    EXPECT_FALSE(released.stale);
    EXPECT_EQ(released.value->value().total(), lab::albedo(lobeInputs(a, 30.0f))->total());

    // ρ(θi) (90 albedos) is never computed during the change, only once it holds still.
    ui::PlotCache curves;
    auto curveFrame = [&](float shininess) {
        curves.beginFrame();
        a.material.shininess = shininess;
        return curves.laggingAlbedoCurve(Slot::EnergyA, lobeInputs(a, 0.0f), now);
    };
    const auto firstCurve = curveFrame(10.0f);
    EXPECT_FALSE(firstCurve.stale);
    for (int i = 1; i <= 60; ++i) {
        now += 1.0 / 60.0;
        const auto shown = curveFrame(10.0f + float(i));
        EXPECT_TRUE(shown.stale) << "frame " << i;
        EXPECT_EQ(shown.value, firstCurve.value);
        EXPECT_TRUE(curves.owed());
    }
    const auto exact = curveFrame(70.0f);
    EXPECT_FALSE(exact.stale);
    EXPECT_FALSE(curves.owed());
    EXPECT_EQ(exact.value->size(), lab::albedoCurve(lobeInputs(a, 0.0f)).size());
    EXPECT_EQ(exact.value->back().albedo.total(), lab::albedoCurve(lobeInputs(a, 0.0f)).back().albedo.total());
    // Dragging θi by whole degrees with the curve kept (the Energy view): the numbers come from the
    // curve, never stale, exactly the albedo at that angle.
    for (int deg = 10; deg <= 40; ++deg) {
        curves.beginFrame(true);
        const float signedDeg = deg % 2 == 0 ? float(deg) : -float(deg);
        const auto at = curves.laggingAlbedo(Slot::EnergyA, lobeInputs(a, signedDeg), now);
        ASSERT_FALSE(at.stale) << deg;
        EXPECT_EQ(at.value->value().total(), lab::albedo(lobeInputs(a, signedDeg))->total()) << deg;
    }
    EXPECT_FALSE(curves.owed());
}

// The panel during a drag, one frame per change as the app draws it: each view owes a frame while
// its readouts lag (the 3D lobe draws its coarse grid), and the frame after the change ends draws
// exactly what a cold cache draws.
TEST(PlotPanel, AfterADragTheNextFrameDrawsWhatAColdCacheDraws) {
    CpuImGui imgui(1.0f);
    ui::Rect r{900, 0, 380, 800};
    for (ui::PlotTab view : {ui::PlotTab::Plane, ui::PlotTab::Lobe3d, ui::PlotTab::Energy, ui::PlotTab::Slice}) {
        Preset a;
        ui::PlotSettings warm;
        warm.view = view;
        drawPlots(r, 1280, 800, a, nullptr, warm);
        bool owed = false;
        for (int i = 1; i <= 5; ++i) {
            a.material.shininess = 20.0f + float(i);
            const Outcome during = drawPlots(r, 1280, 800, a, nullptr, warm, 1);
            owed = owed || warm.cache.owed();
            if (view == ui::PlotTab::Lobe3d && i > 1) {
                // The coarse grid: fewer vertices than the full grid's surface alone.
                EXPECT_LT(during.vertices.size(), std::size_t(kLobeRings * kLobeMeridians)) << "frame " << i << " of the drag";
            }
            if (view == ui::PlotTab::Slice && i > 1) {
                // The coarse image (19 × 19): fewer vertices than the full image alone.
                EXPECT_LT(during.vertices.size(), std::size_t(kSliceSide * kSliceSide)) << "frame " << i << " of the drag";
            }
        }
        EXPECT_TRUE(owed) << "view " << int(view) << ": a drag's readouts lag, and ask for a frame";
        Outcome next = drawPlots(r, 1280, 800, a, nullptr, warm, 1);
        EXPECT_FALSE(warm.cache.owed()) << "view " << int(view);
        if (view == ui::PlotTab::Lobe3d) {
            EXPECT_GT(next.vertices.size(), std::size_t(2 * kLobeRings * kLobeMeridians)) << "the full surface and map";
        }
        if (view == ui::PlotTab::Slice) {
            EXPECT_GT(next.vertices.size(), std::size_t(kSliceSide * kSliceSide)) << "the full image";
        }
        ui::PlotSettings cold;
        cold.view = view;
        EXPECT_TRUE(sameDrawing(next, drawPlots(r, 1280, 800, a, nullptr, cold))) << "view " << int(view);
    }
}

// Issue 40: during a change the 3D lobe's and the slice's coarse plots lag like the albedo: drafted
// again at most every kAlbedoLagSeconds (a frame here is 1/60 s), the frames between drawing the same
// draft without computing anything; the frame after the change draws what a cold cache draws.
TEST(PlotPanel, TheCoarsePlotsLagDuringAChangeLikeTheAlbedo) {
    CpuImGui imgui(1.0f);
    ui::Rect r{900, 0, 380, 800};
    for (ui::PlotTab view : {ui::PlotTab::Lobe3d, ui::PlotTab::Slice}) {
        Preset a, b;
        b.brdf = BrdfModel::BlinnPhong;
        ui::PlotSettings s;
        s.view = view;
        drawPlots(r, 1280, 800, a, &b, s);
        auto computed = [&] { return view == ui::PlotTab::Lobe3d ? s.lobe3d.computed() : s.slice.computed(); };
        // The slice lags as the albedo does; the 3D lobe, its tab's picture, is drafted ten times a second.
        const double lag = view == ui::PlotTab::Lobe3d ? ui::Lobe3dState::kDraftSeconds : ui::PlotCache::kAlbedoLagSeconds;
        const int perLag = static_cast<int>(lag * 60.0);
        std::size_t drafted = computed();
        Outcome first;
        for (int i = 1; i <= 2 * perLag + 1; ++i) { // a drag: a new shininess every frame
            a.material.shininess = 40.0f + float(i); // never the preset's 32, which the cache holds in full
            const Outcome during = drawPlots(r, 1280, 800, a, &b, s, 1);
            if (i == 1) {
                EXPECT_GT(computed(), drafted) << "view " << int(view) << ": the change's first frame drafts";
                drafted = computed();
                first = during;
            } else if (i < perLag) {
                EXPECT_EQ(computed(), drafted) << "view " << int(view) << ", frame " << i << ": the draft is kept";
                EXPECT_TRUE(sameDrawing(during, first)) << "view " << int(view) << ", frame " << i;
            }
        }
        EXPECT_GT(computed(), drafted) << "view " << int(view) << ": drafted again after " << lag << " s";
        EXPECT_TRUE(s.cache.owed()) << "view " << int(view);
        const Outcome next = drawPlots(r, 1280, 800, a, &b, s, 1);
        EXPECT_FALSE(s.cache.owed()) << "view " << int(view);
        ui::PlotSettings cold;
        cold.view = view;
        EXPECT_TRUE(sameDrawing(next, drawPlots(r, 1280, 800, a, &b, cold))) << "view " << int(view);
    }
}

} // namespace
} // namespace lab
