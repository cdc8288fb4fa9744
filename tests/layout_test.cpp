// layout_test.cpp — the window's arithmetic: three columns when there is room, plots below the
// view when not, compare halves that never crop the model, nothing outside the window.
#include "ui/layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

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
    EXPECT_FLOAT_EQ(l.viewport.x, l.panel.w);
    EXPECT_FLOAT_EQ(l.plots.x, l.viewport.x + l.viewport.w);
    EXPECT_FLOAT_EQ(l.plots.x + l.plots.w, 1600.0f);
    EXPECT_FLOAT_EQ(l.viewport.h, 900.0f);
}

// The projectors' sizes, at every presenter scale: three columns, all inside the window.
TEST(Layout, ProjectorScreensKeepThePlotsBesideTheModelAtEveryScale) {
    for (auto [w, h] : {std::pair{1024.0f, 768.0f}, {1280.0f, 800.0f}, {1920.0f, 1080.0f}}) {
        for (float scale : {1.0f, 1.5f, 2.0f, 2.5f}) {
            Layout l = computeLayout({w, h, scale, true, true});
            EXPECT_FALSE(l.plotsBelow) << w << "x" << h << " at " << scale;
            EXPECT_GE(l.viewport.w, 240.0f);
            for (const Rect* r : {&l.panel, &l.viewport, &l.plots}) {
                expectInside(*r, w, h, "projector");
            }
        }
    }
}

// Phones and portrait tablets (issue 13): the model on top across the whole width, the tab row,
// then the chosen tab's contents; nothing outside the window and nothing overlapping.
TEST(Layout, PortraitAndNarrowWindowsAreCompactWithTheModelFirst) {
    for (auto [w, h] : {std::pair{360.0f, 640.0f}, {390.0f, 844.0f}, {768.0f, 1024.0f}, {600.0f, 500.0f}}) {
        for (float scale : {1.0f, 1.25f, 2.0f}) {
            for (PanelTab tab : kPanelTabs) {
                std::string where = std::to_string(int(w)) + "x" + std::to_string(int(h)) + " at " +
                                    std::to_string(scale) + ", " + toString(tab);
                const Layout l = computeLayout({w, h, scale, true, true, tab});
                EXPECT_TRUE(l.compact) << where;
                EXPECT_FLOAT_EQ(l.viewport.x, 0.0f) << where;
                EXPECT_FLOAT_EQ(l.viewport.y, 0.0f) << where;
                EXPECT_FLOAT_EQ(l.viewport.w, w) << where;
                EXPECT_GE(l.viewport.h, 0.3f * h) << where;
                EXPECT_LE(l.viewport.h, 0.6f * h) << where;
                EXPECT_FLOAT_EQ(l.tabs.y, l.viewport.h) << where;
                EXPECT_FLOAT_EQ(l.tabs.w, w) << where;
                const Rect& contents = tab == PanelTab::Plots ? l.plots : l.panel;
                const Rect& other = tab == PanelTab::Plots ? l.panel : l.plots;
                EXPECT_FLOAT_EQ(other.w, 0.0f) << where;
                EXPECT_FLOAT_EQ(contents.y, l.tabs.y + l.tabs.h) << where;
                EXPECT_FLOAT_EQ(contents.y + contents.h, h) << where;
                EXPECT_FLOAT_EQ(contents.w, w) << where;
                for (const Rect* r : {&l.viewport, &l.tabs, &contents}) {
                    expectInside(*r, w, h, where.c_str());
                }
            }
        }
    }
}

TEST(Layout, CompactWithoutTheControlPanelShowsThePlotsBelowWithoutTabs) {
    Layout l = computeLayout({390, 844, 1.0f, false, true, PanelTab::Material});
    EXPECT_TRUE(l.compact);
    EXPECT_EQ(l.tab, PanelTab::Plots);
    EXPECT_FLOAT_EQ(l.tabs.h, 0.0f);
    EXPECT_FLOAT_EQ(l.plots.y, l.viewport.h);
    Layout none = computeLayout({390, 844, 1.0f, false, false});
    EXPECT_FLOAT_EQ(none.viewport.h, 844.0f);
}

TEST(Layout, ProjectorsAndLandscapeTabletsKeepTheirColumns) {
    for (auto [w, h] : {std::pair{1024.0f, 768.0f}, {1280.0f, 800.0f}, {844.0f, 390.0f}}) {
        EXPECT_FALSE(computeLayout({w, h, 2.5f, true, true}).compact) << w << "x" << h;
    }
}

TEST(Layout, PresenterScaleGrowsThePanelsAndTheViewKeepsTheRest) {
    Layout normal = computeLayout({1920, 1080, 1.0f, true, true});
    Layout large = computeLayout({1920, 1080, 2.0f, true, true});
    EXPECT_GT(large.panel.w, normal.panel.w);
    EXPECT_FLOAT_EQ(large.panel.w + large.viewport.w + large.plots.w, 1920.0f);
}

TEST(Layout, HidingTheControlPanelGivesItsRoomToTheModel) {
    Layout all = computeLayout({1024, 768, 1.0f, true, true});
    Layout plots = computeLayout({1024, 768, 1.0f, false, true});
    EXPECT_FLOAT_EQ(plots.panel.w, 0.0f);
    EXPECT_FLOAT_EQ(plots.viewport.x, 0.0f);
    EXPECT_GE(plots.plots.w, all.plots.w); // the plots may widen too (presenter mode on a projector)
    EXPECT_GT(plots.viewport.w, all.viewport.w);
    EXPECT_GE(plots.viewport.w, 0.5f * 1024);
}

TEST(Layout, HiddenPanelsGiveTheViewTheWholeWindow) {
    Layout l = computeLayout({800, 600, 1.0f, false, false});
    EXPECT_FLOAT_EQ(l.viewport.w, 800.0f);
    EXPECT_FLOAT_EQ(l.viewport.h, 600.0f);
    EXPECT_FLOAT_EQ(l.panel.w, 0.0f);
}

TEST(Layout, CompareHalvesSplitTheViewAndStackWhenSideBySideWouldBeNarrow) {
    Layout wide = computeLayout({1600, 600, 1.0f, false, false});
    EXPECT_FALSE(wide.compareStacked);
    EXPECT_FLOAT_EQ(wide.halves[0].w + wide.halves[1].w, wide.viewport.w);
    EXPECT_FLOAT_EQ(wide.halves[1].x, wide.halves[0].x + wide.halves[0].w);
    Layout tall = computeLayout({600, 900, 1.0f, false, false});
    EXPECT_TRUE(tall.compareStacked);
    EXPECT_FLOAT_EQ(tall.halves[0].h + tall.halves[1].h, tall.viewport.h);
    EXPECT_FLOAT_EQ(tall.halves[1].y, tall.halves[0].y + tall.halves[0].h);
}

TEST(Layout, ATinyWindowStillHasAView) {
    Layout l = computeLayout({1, 1, 1.0f, true, true});
    EXPECT_GE(l.viewport.w, 1.0f);
    EXPECT_GE(l.viewport.h, 1.0f);
}

//----------------------------------------------------------------------------------------
// placeText: the view's text beside the model, never over it
//----------------------------------------------------------------------------------------

bool intersects(const Rect& a, const Rect& b) {
    return a.w > 0.0f && a.h > 0.0f && b.w > 0.0f && b.h > 0.0f && a.x < b.x + b.w - 0.01f && b.x < a.x + a.w - 0.01f &&
           a.y < b.y + b.h - 0.01f && b.y < a.y + a.h - 0.01f;
}

bool inside(const Rect& r, const Rect& in) {
    return r.x >= in.x - 0.01f && r.y >= in.y - 0.01f && r.x + r.w <= in.x + in.w + 0.01f && r.y + r.h <= in.y + in.h + 0.01f;
}

// A caption of `lines` lines of 20 units at any width, however wide: a stand-in for the font's.
TextRoom room(float lines, bool compare = false) {
    TextRoom t;
    t.header = 30.0f;
    t.footer = 28.0f;
    t.label = compare ? 26.0f : 0.0f;
    if (lines > 0.0f) {
        t.captionHeight = [lines](float width) { return 20.0f * lines * std::max(1.0f, 300.0f / width); };
        t.captionWidth = 470.0f;
        t.sideWidth = 240.0f;
    }
    return t;
}

void expectApart(const Layout& l, const std::string& where) {
    std::vector<std::pair<const char*, const Rect*>> text = {
        {"header", &l.header}, {"caption", &l.captionBand}, {"footer", &l.footer}, {"label A", &l.labels[0]}, {"label B", &l.labels[1]}};
    for (std::size_t i = 0; i < text.size(); ++i) {
        EXPECT_TRUE(text[i].second->w == 0.0f || inside(*text[i].second, l.view)) << where << ": " << text[i].first;
        EXPECT_FALSE(intersects(*text[i].second, l.viewport) && text[i].second != &l.labels[0] && text[i].second != &l.labels[1])
            << where << ": " << text[i].first << " over the model";
        for (const Rect& half : l.halves) {
            EXPECT_FALSE(intersects(*text[i].second, half)) << where << ": " << text[i].first << " over a half";
        }
        for (std::size_t j = i + 1; j < text.size(); ++j) {
            EXPECT_FALSE(intersects(*text[i].second, *text[j].second)) << where << ": " << text[i].first << " / " << text[j].first;
        }
    }
    EXPECT_TRUE(inside(l.viewport, l.view)) << where;
    EXPECT_TRUE(inside(l.caption, l.captionBand)) << where;
}

TEST(LayoutText, HeaderFooterAndCaptionTakeStripsOfTheViewAndTheModelTheRest) {
    for (auto [w, h] : {std::pair{1024.0f, 768.0f}, {1280.0f, 800.0f}, {1920.0f, 1080.0f}, {390.0f, 844.0f}, {768.0f, 1024.0f}}) {
        for (bool panel : {true, false}) {
            for (float lines : {0.0f, 3.0f}) {
                for (bool compare : {false, true}) {
                    std::string where = std::to_string(int(w)) + "x" + std::to_string(int(h)) + (panel ? " panel" : "") +
                                        " caption " + std::to_string(int(lines)) + (compare ? " compare" : "");
                    Layout l = computeLayout({w, h, 1.0f, panel, true});
                    const Rect view = l.view;
                    placeText(l, room(lines, compare));
                    EXPECT_EQ(l.view.x, view.x) << where;
                    EXPECT_EQ(l.view.h, view.h) << where;
                    EXPECT_FLOAT_EQ(l.header.h, 30.0f) << where;
                    EXPECT_FLOAT_EQ(l.header.y, view.y) << where;
                    EXPECT_FLOAT_EQ(l.footer.y + l.footer.h, view.y + view.h) << where;
                    EXPECT_EQ(l.caption.w > 0.0f, lines > 0.0f) << where;
                    if (compare) {
                        for (int i = 0; i < 2; ++i) {
                            EXPECT_FLOAT_EQ(l.labels[i].y + l.labels[i].h, l.halves[i].y) << where << ": a label above its half";
                            EXPECT_TRUE(inside(l.halves[i], l.viewport)) << where;
                        }
                    }
                    expectApart(l, where);
                }
            }
        }
    }
}

// A wide view (a projector without the panel) takes the caption as a column at its left: the
// model keeps more of its height. A tall one takes it across the top.
TEST(LayoutText, TheCaptionGoesWhereTheModelKeepsTheLargerNarrowerSide) {
    Layout wide = computeLayout({1920.0f, 1080.0f, 1.0f, false, false});
    placeText(wide, room(4.0f));
    EXPECT_FLOAT_EQ(wide.caption.w, 240.0f);
    EXPECT_FLOAT_EQ(wide.viewport.x, wide.view.x + 240.0f);
    EXPECT_FLOAT_EQ(wide.viewport.h, 1080.0f - 30.0f - 28.0f);
    Layout tall = computeLayout({1024.0f, 768.0f, 1.0f, false, true});
    ASSERT_LT(tall.view.w, tall.view.h);
    placeText(tall, room(4.0f));
    EXPECT_FLOAT_EQ(tall.caption.y, tall.view.y + 30.0f);
    EXPECT_FLOAT_EQ(tall.viewport.y, tall.caption.y + tall.caption.h);
    EXPECT_FLOAT_EQ(tall.viewport.w, tall.view.w);
}

TEST(LayoutText, ATinyViewStillHasAModelViewport) {
    Layout l = computeLayout({100.0f, 60.0f, 1.0f, false, false});
    placeText(l, room(20.0f, true));
    EXPECT_GE(l.viewport.w, 1.0f);
    EXPECT_GE(l.viewport.h, 1.0f);
    for (const Rect& half : l.halves) {
        EXPECT_GE(half.h, 1.0f);
    }
}

// A value view's legend strip (issue 26) is carved from the model's room, above the footer.
TEST(LayoutText, TheLegendStripTakesRoomFromTheModelNotFromTheText) {
    Layout l = computeLayout({1280.0f, 800.0f, 1.0f, true, true});
    TextRoom room;
    room.header = 30.0f;
    room.footer = 28.0f;
    room.legend = 48.0f;
    placeText(l, room);
    EXPECT_FLOAT_EQ(l.legend.h, 48.0f);
    EXPECT_FLOAT_EQ(l.legend.y + l.legend.h, l.footer.y) << "right above the footer";
    EXPECT_FLOAT_EQ(l.viewport.y + l.viewport.h, l.legend.y) << "the model ends where the legend starts";
    room.legend = 0.0f;
    placeText(l, room);
    EXPECT_FLOAT_EQ(l.legend.h, 0.0f);
    EXPECT_FLOAT_EQ(l.viewport.y + l.viewport.h, l.footer.y);
}

} // namespace
} // namespace lab::ui
