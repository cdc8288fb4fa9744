// layout_test.cpp — the window's arithmetic: three columns when there is room, plots below the
// view when not, compare halves that never crop the model, nothing outside the window.
#include "ui/layout.h"

#include <gtest/gtest.h>

namespace lab::ui {
namespace {

void expectInside(const Rect& r, float w, float h, const char* what) {
    EXPECT_GE(r.x, 0.0f) << what;
    EXPECT_GE(r.y, 0.0f) << what;
    EXPECT_LE(r.x + r.w, w + 0.01f) << what;
    EXPECT_LE(r.y + r.h, h + 0.01f) << what;
}

TEST(Layout, WideWindowHasThreeColumnsThatTileIt) {
    Layout l = computeLayout({1600, 900, 1.0f, true, true});
    EXPECT_FALSE(l.plotsBelow);
    EXPECT_FLOAT_EQ(l.panel.x, 0.0f);
    EXPECT_FLOAT_EQ(l.view.x, l.panel.w);
    EXPECT_FLOAT_EQ(l.plots.x, l.view.x + l.view.w);
    EXPECT_FLOAT_EQ(l.plots.x + l.plots.w, 1600.0f);
    EXPECT_FLOAT_EQ(l.view.h, 900.0f);
}

// The projectors' sizes, at every presenter scale: three columns, all inside the window.
TEST(Layout, ProjectorScreensKeepThePlotsBesideTheModelAtEveryScale) {
    for (auto [w, h] : {std::pair{1024.0f, 768.0f}, {1280.0f, 800.0f}, {1920.0f, 1080.0f}}) {
        for (float scale : {1.0f, 1.5f, 2.0f, 2.5f}) {
            Layout l = computeLayout({w, h, scale, true, true});
            EXPECT_FALSE(l.plotsBelow) << w << "x" << h << " at " << scale;
            EXPECT_GE(l.view.w, 240.0f);
            for (const Rect* r : {&l.panel, &l.view, &l.plots}) {
                expectInside(*r, w, h, "projector");
            }
        }
    }
}

TEST(Layout, PortraitWindowPutsThePlotsBelowTheView) {
    Layout l = computeLayout({768, 1024, 1.0f, true, true});
    EXPECT_TRUE(l.plotsBelow);
    EXPECT_FLOAT_EQ(l.plots.y, l.view.y + l.view.h);
    EXPECT_FLOAT_EQ(l.plots.x, l.view.x);
    for (const Rect* r : {&l.panel, &l.view, &l.plots}) {
        expectInside(*r, 768, 1024, "768x1024");
    }
}

TEST(Layout, PresenterScaleGrowsThePanelsAndTheViewKeepsTheRest) {
    Layout normal = computeLayout({1920, 1080, 1.0f, true, true});
    Layout large = computeLayout({1920, 1080, 2.0f, true, true});
    EXPECT_GT(large.panel.w, normal.panel.w);
    EXPECT_FLOAT_EQ(large.panel.w + large.view.w + large.plots.w, 1920.0f);
}

TEST(Layout, HidingTheControlPanelGivesItsRoomToTheModel) {
    Layout all = computeLayout({1024, 768, 1.0f, true, true});
    Layout plots = computeLayout({1024, 768, 1.0f, false, true});
    EXPECT_FLOAT_EQ(plots.panel.w, 0.0f);
    EXPECT_FLOAT_EQ(plots.view.x, 0.0f);
    EXPECT_GE(plots.plots.w, all.plots.w); // the plots may widen too (presenter mode on a projector)
    EXPECT_GT(plots.view.w, all.view.w);
    EXPECT_GE(plots.view.w, 0.5f * 1024);
}

TEST(Layout, HiddenPanelsGiveTheViewTheWholeWindow) {
    Layout l = computeLayout({800, 600, 1.0f, false, false});
    EXPECT_FLOAT_EQ(l.view.w, 800.0f);
    EXPECT_FLOAT_EQ(l.view.h, 600.0f);
    EXPECT_FLOAT_EQ(l.panel.w, 0.0f);
}

TEST(Layout, CompareHalvesSplitTheViewAndStackWhenSideBySideWouldBeNarrow) {
    Layout wide = computeLayout({1600, 600, 1.0f, false, false});
    EXPECT_FALSE(wide.compareStacked);
    EXPECT_FLOAT_EQ(wide.viewA.w + wide.viewB.w, wide.view.w);
    EXPECT_FLOAT_EQ(wide.viewB.x, wide.viewA.x + wide.viewA.w);
    Layout tall = computeLayout({600, 900, 1.0f, false, false});
    EXPECT_TRUE(tall.compareStacked);
    EXPECT_FLOAT_EQ(tall.viewA.h + tall.viewB.h, tall.view.h);
    EXPECT_FLOAT_EQ(tall.viewB.y, tall.viewA.y + tall.viewA.h);
}

TEST(Layout, ATinyWindowStillHasAView) {
    Layout l = computeLayout({1, 1, 1.0f, true, true});
    EXPECT_GE(l.view.w, 1.0f);
    EXPECT_GE(l.view.h, 1.0f);
}

} // namespace
} // namespace lab::ui
