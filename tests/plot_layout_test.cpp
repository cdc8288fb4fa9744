// plot_layout_test.cpp — the plots fit whatever area they get: height split, arrangement, the
// lobe's frame in its canvas, ring values and readout wrapping.
#include "core/plots/plot_layout.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lab {
namespace {

TEST(PlotLayout, TokensWrapWhenTheLineIsFull) {
    EXPECT_EQ(flowLines({}, 5, 100), 0);
    EXPECT_EQ(flowLines({40, 40}, 5, 100), 1);      // 40 + 5 + 40 = 85
    EXPECT_EQ(flowLines({40, 40, 40}, 5, 100), 2);  // the third does not fit
    EXPECT_EQ(flowLines({40, kLineBreak, 40}, 5, 100), 2);
    EXPECT_EQ(flowLines({150, 10}, 5, 100), 2);     // too wide: a line of its own
    EXPECT_EQ(flowLines({kLineBreak, kLineBreak}, 5, 100), 0);
    std::vector<FlowPlace> p = flowTokens({40, 40, 40, kLineBreak, 10}, 5, 100);
    ASSERT_EQ(p.size(), 5u);
    EXPECT_FLOAT_EQ(p[0].x, 0);
    EXPECT_FLOAT_EQ(p[1].x, 45);
    EXPECT_EQ(p[1].line, 0);
    EXPECT_FLOAT_EQ(p[2].x, 0);
    EXPECT_EQ(p[2].line, 1);
    EXPECT_EQ(p[4].line, 2); // after the break
}

TEST(PlotLayout, SplitGivesMinimumsThenSharesTheRestUpToTheMaximums) {
    std::vector<PlotNeeds> plots{{20, 0, 50, 150}, {10, 0, 30, 80}, {10, 0, 40, 40}};
    // Minimums: 20+50 + 10+30 + 10+40 = 160, plus two gaps of 5 = 170.
    EXPECT_TRUE(splitHeights(169, 5, plots).empty());
    std::vector<float> tight = splitHeights(170, 5, plots);
    ASSERT_EQ(tight.size(), 3u);
    EXPECT_FLOAT_EQ(tight[0], 50);
    EXPECT_FLOAT_EQ(tight[1], 30);
    EXPECT_FLOAT_EQ(tight[2], 40);
    // 75 more, shortfalls 100 and 50 (and 0): shared 2:1.
    std::vector<float> some = splitHeights(245, 5, plots);
    EXPECT_FLOAT_EQ(some[0], 100);
    EXPECT_FLOAT_EQ(some[1], 55);
    EXPECT_FLOAT_EQ(some[2], 40);
    // Plenty: every canvas at its maximum, the rest left empty.
    std::vector<float> plenty = splitHeights(2000, 5, plots);
    EXPECT_FLOAT_EQ(plenty[0], 150);
    EXPECT_FLOAT_EQ(plenty[1], 80);
    EXPECT_FLOAT_EQ(plenty[2], 40);
}

// A stand-in for the GUI's measurements: 2 rows of 20 fixed, at least 150 wide, a canvas from
// 60 to half the width + 40.
PlotNeeds measure(int, float width) { return {40.0f, 150.0f, 60.0f, width * 0.5f + 40.0f}; }

// Every plot's block lies inside the area and plots do not overlap.
void expectInside(const PlotsLayout& l, float w, float h) {
    for (int i = 0; i < kPlotCount; ++i) {
        const PlotBox& b = l.plots[std::size_t(i)];
        EXPECT_GE(b.x, 0) << i;
        EXPECT_GE(b.y, 0) << i;
        EXPECT_LE(b.x + b.w, w + 1e-3f) << i;
        EXPECT_LE(b.y + b.h, h + 1e-3f) << i;
        EXPECT_GE(b.canvas, 0) << i;
        EXPECT_LE(b.canvas, b.h) << i;
        if (l.arrangement == PlotArrangement::Tabs) {
            continue;
        }
        for (int j = 0; j < i; ++j) {
            const PlotBox& o = l.plots[std::size_t(j)];
            bool apart = b.x >= o.x + o.w || o.x >= b.x + b.w || b.y >= o.y + o.h || o.y >= b.y + b.h;
            EXPECT_TRUE(apart) << i << " overlaps " << j;
        }
    }
}

TEST(PlotLayout, ATallColumnStacksThePlots) {
    PlotsLayout l = arrangePlots(380, 700, 6, 30, measure);
    EXPECT_EQ(l.arrangement, PlotArrangement::OneColumn);
    EXPECT_FLOAT_EQ(l.plots[0].w, 380);
    EXPECT_LT(l.plots[0].y, l.plots[1].y);
    EXPECT_LT(l.plots[1].y, l.plots[2].y);
    expectInside(l, 380, 700);
}

TEST(PlotLayout, AWideBandPutsThePlotsSideBySide) {
    PlotsLayout l = arrangePlots(1150, 370, 6, 30, measure);
    EXPECT_NE(l.arrangement, PlotArrangement::OneColumn);
    EXPECT_NE(l.arrangement, PlotArrangement::Tabs);
    EXPECT_FLOAT_EQ(l.plots[0].y, 0);
    EXPECT_FLOAT_EQ(l.plots[1].y, 0);
    EXPECT_GT(l.plots[1].x, l.plots[0].x + l.plots[0].w);
    expectInside(l, 1150, 370);
}

TEST(PlotLayout, NoRoomForAllMeansTabsThatStillFit) {
    PlotsLayout l = arrangePlots(300, 120, 6, 30, measure);
    EXPECT_EQ(l.arrangement, PlotArrangement::Tabs);
    for (const PlotBox& b : l.plots) {
        EXPECT_FLOAT_EQ(b.y, 30);
        EXPECT_FLOAT_EQ(b.h, 90);
        EXPECT_FLOAT_EQ(b.canvas, 50); // 90 - 40 fixed
    }
    expectInside(l, 300, 120);
    // Not even the fixed rows fit: the canvas is 0, never negative.
    PlotsLayout none = arrangePlots(300, 50, 6, 30, measure);
    EXPECT_FLOAT_EQ(none.plots[0].canvas, 0);
    expectInside(none, 300, 50);
}

// Every window size and UI scale the app allows, as a right column or a band: the plots fit.
TEST(PlotLayout, EverySizeFits) {
    for (float scale : {1.0f, 1.5f, 2.0f, 2.5f}) {
        auto scaled = [scale](int plot, float width) {
            PlotNeeds n = measure(plot, width);
            return PlotNeeds{n.fixed * scale, n.minWidth * scale, n.minCanvas * scale, n.maxCanvas};
        };
        for (float w : {200.0f, 358.0f, 380.0f, 614.0f, 900.0f, 1152.0f}) {
            for (float h : {100.0f, 200.0f, 322.0f, 453.0f, 800.0f, 1080.0f}) {
                PlotsLayout l = arrangePlots(w, h, 6 * scale, 30 * scale, scaled);
                expectInside(l, w, h);
            }
        }
    }
}

TEST(PlotLayout, TheHalfDiscFitsItsCanvas) {
    PlotMargins m{20, 20, 15, 15};
    // Wide canvas: the height decides; the disc is centred horizontally.
    LobeFrame wide = lobeFrame(100, 50, 400, 130, m);
    EXPECT_FLOAT_EQ(wide.radius, 100);
    EXPECT_FLOAT_EQ(wide.originX, 300);
    EXPECT_FLOAT_EQ(wide.originY, 50 + 15 + 100);
    // Tall canvas: the width decides; the disc is centred in the spare height.
    LobeFrame tall = lobeFrame(0, 0, 240, 400, m);
    EXPECT_FLOAT_EQ(tall.radius, 100);
    EXPECT_FLOAT_EQ(tall.originX, 120);
    EXPECT_FLOAT_EQ(tall.originY, 15 + 100 + (370 - 100) / 2.0f);
    for (const LobeFrame& f : {wide, tall}) {
        EXPECT_GE(f.originY - f.radius, 15.0f - 1e-3f);
    }
    EXPECT_LE(tall.originY + m.bottom, 400);
    // No room: radius 0.
    EXPECT_FLOAT_EQ(lobeFrame(0, 0, 30, 20, m).radius, 0);
}

TEST(PlotAxes, ALockedScaleKeepsItsMaximum) {
    float held = 0.0f;
    EXPECT_FLOAT_EQ(scaleMaximum(0.8f, false, held), 0.8f); // unlocked: follows
    EXPECT_FLOAT_EQ(scaleMaximum(0.5f, false, held), 0.5f);
    EXPECT_FLOAT_EQ(scaleMaximum(3.0f, true, held), 0.5f);  // locked: what it was
    EXPECT_FLOAT_EQ(scaleMaximum(0.1f, true, held), 0.5f);
    EXPECT_FLOAT_EQ(scaleMaximum(3.0f, false, held), 3.0f); // unlocked again: follows
    float fresh = 0.0f;
    EXPECT_FLOAT_EQ(scaleMaximum(0.7f, true, fresh), 0.7f); // locked from the start: the first value
}

TEST(PlotAxes, NiceStepsAndLinearRings) {
    EXPECT_FLOAT_EQ(niceStep(0.234f), 0.25f);
    EXPECT_FLOAT_EQ(niceStep(0.3f), 0.5f);
    EXPECT_FLOAT_EQ(niceStep(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(niceStep(1.2f), 2.0f);
    EXPECT_FLOAT_EQ(niceStep(7.0f), 10.0f);
    std::vector<float> t = linearTicks(0.935f, 4);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_FLOAT_EQ(t[0], 0.25f);
    EXPECT_FLOAT_EQ(t[2], 0.75f);
    std::vector<float> one = linearTicks(1.0f, 4);
    ASSERT_EQ(one.size(), 4u);
    EXPECT_FLOAT_EQ(one.back(), 1.0f);
    for (float max : {0.003f, 0.07f, 1.3f, 42.0f, 980.0f}) {
        std::vector<float> ticks = linearTicks(max, 5);
        EXPECT_GE(ticks.size(), 1u) << max;
        EXPECT_LE(ticks.size(), 5u) << max;
        EXPECT_LE(ticks.back(), max * 1.0001f) << max;
    }
    EXPECT_TRUE(linearTicks(0.0f, 4).empty());
}

TEST(PlotAxes, DecadeRingsBelowTheOuterCircle) {
    std::vector<float> t = decadeTicks(0.935f, 3.0f);
    ASSERT_EQ(t.size(), 3u); // 0.1, 0.01, 0.001 (0.000935 is the innermost shown)
    EXPECT_FLOAT_EQ(t[0], 0.1f);
    EXPECT_FLOAT_EQ(t[2], 0.001f);
    std::vector<float> exact = decadeTicks(1.0f, 3.0f);
    ASSERT_EQ(exact.size(), 4u); // 1 down to 0.001, both ends included
    EXPECT_FLOAT_EQ(exact[0], 1.0f);
    EXPECT_TRUE(decadeTicks(0.0f, 3.0f).empty());
}

// The distance from p to the polyline `line`.
float distanceToPolyline(glm::vec2 p, const std::vector<glm::vec2>& line) {
    float best = 1e30f;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        glm::vec2 a = line[i], ab = line[i + 1] - a;
        float t = glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f) : 0.0f;
        best = std::min(best, glm::length(p - (a + t * ab)));
    }
    return best;
}

TEST(PlotCurves, ThinningKeepsTheLineWithinTheTolerance) {
    // A lobe like the plots draw: at the origin for half the angles, then out to a sharp tip and back.
    std::vector<glm::vec2> lobe;
    for (int deg = -90; deg <= 90; ++deg) {
        float t = glm::radians(float(deg)), r = deg < 0 ? 0.0f : 150.0f * std::pow(std::cos(t - 0.5f), 40.0f);
        lobe.emplace_back(200.0f + r * std::sin(t), 300.0f - r * std::cos(t));
    }
    std::vector<glm::vec2> thin = thinPolyline(lobe, 0.2f);
    EXPECT_LT(thin.size(), lobe.size() / 3);
    EXPECT_EQ(thin.front(), lobe.front());
    EXPECT_EQ(thin.back(), lobe.back());
    for (const glm::vec2& p : lobe) {
        EXPECT_LE(distanceToPolyline(p, thin), 0.2f + 1e-4f);
    }
    // The tip (the farthest point from the origin) is one of the points kept.
    auto far = [](glm::vec2 a, glm::vec2 b) { return glm::length(a - glm::vec2(200, 300)) < glm::length(b - glm::vec2(200, 300)); };
    EXPECT_EQ(*std::max_element(thin.begin(), thin.end(), far), *std::max_element(lobe.begin(), lobe.end(), far));
    // The points kept are points of the line, in order.
    std::size_t at = 0;
    for (const glm::vec2& p : thin) {
        while (at < lobe.size() && lobe[at] != p) {
            ++at;
        }
        EXPECT_LT(at, lobe.size());
    }
}

TEST(PlotCurves, ThinningEdgeCases) {
    EXPECT_TRUE(thinPolyline({}, 0.2f).empty());
    EXPECT_EQ(thinPolyline({{1, 2}}, 0.2f).size(), 1u);
    EXPECT_EQ(thinPolyline({{1, 2}, {3, 4}}, 0.2f).size(), 2u);
    // Collinear and repeated points go; a corner stays.
    std::vector<glm::vec2> corner{{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1}, {2, 2}};
    std::vector<glm::vec2> thin = thinPolyline(corner, 0.01f);
    ASSERT_EQ(thin.size(), 3u);
    EXPECT_EQ(thin[1], glm::vec2(2, 0));
    // A line that goes out and comes back keeps its far end.
    std::vector<glm::vec2> back = thinPolyline({{0, 0}, {1, 0}, {2, 0}, {1, 0}, {0, 0}}, 0.01f);
    ASSERT_EQ(back.size(), 3u);
    EXPECT_EQ(back[1], glm::vec2(2, 0));
}

} // namespace
} // namespace lab
