// slice_tab_test.cpp — the plots window's Slice tab in the real lab (ui/plots/plots_slice.h): it opens,
// draws the BRDF over (θh, θd) where the lighting model says it is bright and dark, answers the
// pointer, and in compare mode shows B beside A and their difference in its diverging palette.
#include "gui_harness.h"

#include <algorithm>
#include <cmath>

namespace lab::test {
namespace {

// The mean colour of a small patch of a captured image at (θh, θd) in degrees: θh across from the
// left, θd up from the bottom.
struct Rgb {
    double r = 0, g = 0, b = 0;
};
Rgb patchAt(const Image& image, float thetaHDeg, float thetaDDeg) {
    const int cx = static_cast<int>(std::lround(thetaHDeg / 90.0f * static_cast<float>(image.width - 1)));
    const int cy = static_cast<int>(std::lround((1.0f - thetaDDeg / 90.0f) * static_cast<float>(image.height - 1)));
    Rgb sum;
    int n = 0;
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, image.height - 1); ++y) {
        for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, image.width - 1); ++x) {
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x));
            sum.r += image.rgb[i];
            sum.g += image.rgb[i + 1];
            sum.b += image.rgb[i + 2];
            ++n;
        }
    }
    return {sum.r / n, sum.g / n, sum.b / n};
}

TEST(GuiSlice, TheSliceTabShowsTheBrdfAndInCompareModeBAndTheDifference) {
    START_LAB(lab, "--preset", preset("12-blinn-phong")); // Blinn-Phong, n = 32: half its peak at θh 11.8°
    Rect tab = lab.widget("plot.view.slice");
    lab.click(tab.cx(), tab.cy());
    ASSERT_TRUE(lab.has("plot.slice.a")) << "the Slice tab shows A's image";
    EXPECT_FALSE(lab.has("plot.lobe")) << "the plane plots give way to the slice";
    const Rect a = lab.widget("plot.slice.a"), plots = lab.widget("plots");
    EXPECT_TRUE(a.x >= plots.x && a.y >= plots.y && a.x + a.w <= plots.x + plots.w && a.y + a.h <= plots.y + plots.h);
    EXPECT_GT(a.w, 100);
    // Viridis: the specular band at θh near 0 is yellow-green at every θd, far from it dark purple.
    const Image image = lab.capture(a);
    for (float thetaD : {15.0f, 60.0f}) {
        const Rgb band = patchAt(image, 3.0f, thetaD), far = patchAt(image, 60.0f, thetaD);
        EXPECT_GT(band.g, 170.0) << "bright at θh 3°, θd " << thetaD;
        EXPECT_LT(far.g, 60.0) << "dark at θh 60°, θd " << thetaD;
        EXPECT_GT(far.b, far.g) << "viridis's low end is purple";
    }
    // The readout answers the pointer (its strip changes as the pointer comes onto the image).
    const Rect strip = lab.widget("plot.slice.readout");
    const Image before = lab.capture(strip);
    lab.moveTo(a.x + a.w / 3, a.y + a.h / 3);
    EXPECT_GT(changedShare(before, lab.capture(strip)), 0.01) << "θh, θd and the value under the pointer";

    // Compare mode, B with a broader lobe (n = 4): B's image differs from A's, and A − B is near-white
    // where both are Ks (θh 0) and purple (B reflects more) on B's broader flanks.
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("c");
    ASSERT_TRUE(lab.has("view.b"));
    Rect editB = lab.widget("compare.edit-b");
    lab.click(editB.cx(), editB.cy());
    Rect shininess = lab.widget("material.shininess");
    lab.moveTo(shininess.x + 20, shininess.cy());
    lab.x().key("Control_L", true);
    lab.click(shininess.x + 20, shininess.cy());
    lab.x().key("Control_L", false);
    lab.type("4");
    lab.press("Return");
    lab.moveTo(view.cx(), view.cy());
    ASSERT_TRUE(lab.has("plot.slice.b")) << "B's image beside A's";
    if (!lab.has("plot.slice.difference-image")) { // three do not fit: the choice
        ASSERT_TRUE(lab.has("plot.slice.difference"));
        const Image imageA = lab.capture(lab.widget("plot.slice.a")), imageB = lab.capture(lab.widget("plot.slice.b"));
        EXPECT_GT(changedShare(imageA, imageB), 0.05);
        Rect choose = lab.widget("plot.slice.difference");
        lab.click(choose.cx(), choose.cy());
        lab.moveTo(view.cx(), view.cy());
    } else {
        const Image imageA = lab.capture(lab.widget("plot.slice.a")), imageB = lab.capture(lab.widget("plot.slice.b"));
        EXPECT_GT(changedShare(imageA, imageB), 0.05) << "A (n = 32) and B (n = 4) differ";
    }
    ASSERT_TRUE(lab.has("plot.slice.difference-image") && lab.has("plot.slice.difference-legend"));
    const Image difference = lab.capture(lab.widget("plot.slice.difference-image"));
    const Rgb same = patchAt(difference, 1.0f, 45.0f), flank = patchAt(difference, 30.0f, 45.0f);
    EXPECT_GT(std::min({same.r, same.g, same.b}), 200.0) << "A − B near 0 at θh 1°: near-white";
    EXPECT_GT(flank.b, flank.r + 20.0) << "B reflects more at θh 30°: purple";
    EXPECT_GT(flank.b, flank.g + 20.0);
}

// The keyboard alone reaches the Slice tab as it reaches the others: with the panel hidden, Tab goes
// into the plots window, the arrows walk its tabs, Space opens the one with the ring.
TEST(GuiSlice, TheKeyboardReachesTheSliceTab) {
    START_LAB(lab, "--preset", preset("12-blinn-phong"));
    Rect view = lab.widget("view");
    lab.moveTo(view.cx(), view.cy());
    lab.press("h"); // the panels' key: all -> plots and model
    ASSERT_FALSE(lab.has("panel"));
    lab.press("Tab");
    ASSERT_TRUE(lab.has("focus"));
    bool reached = false;
    for (int i = 0; i < 12 && !reached; ++i) {
        const Rect focus = lab.widget("focus"), tab = lab.widget("plot.view.slice");
        reached = std::abs(focus.x - tab.x) <= 4 && std::abs(focus.y - tab.y) <= 4;
        if (!reached) {
            lab.press("Right");
        }
    }
    ASSERT_TRUE(reached) << "the arrows never reached the Slice tab";
    EXPECT_FALSE(lab.has("plot.slice.a"));
    lab.press("space");
    EXPECT_TRUE(lab.has("plot.slice.a")) << "Space opens the Slice tab";
}

} // namespace
} // namespace lab::test
