// plot_layout.cpp — the plots' arithmetic on screen.
#include "core/plots/plot_layout.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace lab {

std::vector<FlowPlace> flowTokens(const std::vector<float>& tokenWidths, float gap, float width) {
    std::vector<FlowPlace> places;
    places.reserve(tokenWidths.size());
    int line = -1;    // no line yet
    float x = 0.0f;   // the current line's width so far
    bool open = false; // whether a token is on the current line
    for (float w : tokenWidths) {
        if (w == kLineBreak) {
            open = false;
            places.push_back({x, std::max(line, 0)});
            continue;
        }
        if (open && x + gap + w <= width) {
            places.push_back({x + gap, line});
            x += gap + w;
        } else {
            ++line;
            places.push_back({0.0f, line});
            x = w;
            open = true;
        }
    }
    return places;
}

int flowLines(const std::vector<float>& tokenWidths, float gap, float width) {
    int lines = 0;
    std::vector<FlowPlace> places = flowTokens(tokenWidths, gap, width);
    for (std::size_t i = 0; i < places.size(); ++i) {
        if (tokenWidths[i] != kLineBreak) {
            lines = std::max(lines, places[i].line + 1);
        }
    }
    return lines;
}

std::vector<float> splitHeights(float height, float gap, const std::vector<PlotNeeds>& plots) {
    if (plots.empty()) {
        return {};
    }
    float used = gap * static_cast<float>(plots.size() - 1);
    float shortfall = 0.0f;
    for (const PlotNeeds& p : plots) {
        used += p.fixed + p.minCanvas;
        shortfall += std::max(p.maxCanvas - p.minCanvas, 0.0f);
    }
    if (used > height) {
        return {};
    }
    float share = shortfall > 0.0f ? std::min((height - used) / shortfall, 1.0f) : 0.0f;
    std::vector<float> canvas;
    canvas.reserve(plots.size());
    for (const PlotNeeds& p : plots) {
        canvas.push_back(p.minCanvas + share * std::max(p.maxCanvas - p.minCanvas, 0.0f));
    }
    return canvas;
}

namespace {

// The plots of each column, in order, for 1, 2 or 3 columns; and the columns' shares of the width.
const std::vector<std::vector<int>>& columnsOf(int count) {
    static const std::vector<std::vector<int>> one{{0, 1, 2}}, two{{0}, {1, 2}}, three{{0}, {1}, {2}};
    return count == 1 ? one : count == 2 ? two : three;
}

// How much of a plot's canvas is of use (up to its maximum); the lobe counts double.
float usefulness(int plot, const PlotNeeds& needs, float canvas) {
    float useful = std::min(canvas, needs.maxCanvas);
    return plot == 0 ? 2.0f * useful : useful;
}

} // namespace

PlotsLayout arrangePlots(float width, float height, float gap, float tabBar, const PlotMeasure& measure) {
    PlotsLayout best;
    float bestScore = -1.0f;
    for (int count = 1; count <= 3; ++count) {
        const std::vector<std::vector<int>>& columns = columnsOf(count);
        float columnWidth = (width - gap * static_cast<float>(count - 1)) / static_cast<float>(count);
        if (columnWidth <= 0.0f) {
            continue;
        }
        PlotsLayout candidate;
        candidate.arrangement = static_cast<PlotArrangement>(count - 1);
        float score = 0.0f;
        bool fits = true;
        for (std::size_t c = 0; c < columns.size() && fits; ++c) {
            std::vector<PlotNeeds> needs;
            for (int plot : columns[c]) {
                needs.push_back(measure(plot, columnWidth));
                fits = fits && columnWidth >= needs.back().minWidth;
            }
            std::vector<float> canvas = fits ? splitHeights(height, gap, needs) : std::vector<float>{};
            fits = !canvas.empty();
            float y = 0.0f;
            for (std::size_t i = 0; i < canvas.size(); ++i) {
                int plot = columns[c][i];
                float h = needs[i].fixed + canvas[i];
                candidate.plots[static_cast<std::size_t>(plot)] = {
                    static_cast<float>(c) * (columnWidth + gap), y, columnWidth, h, canvas[i]};
                y += h + gap;
                score += usefulness(plot, needs[i], canvas[i]);
            }
        }
        if (fits && score > bestScore) {
            best = candidate;
            bestScore = score;
        }
    }
    if (bestScore >= 0.0f) {
        return best;
    }
    best.arrangement = PlotArrangement::Tabs;
    float room = std::max(height - tabBar, 0.0f);
    for (int plot = 0; plot < kPlotCount; ++plot) {
        PlotNeeds needs = measure(plot, width);
        float canvas = std::clamp(room - needs.fixed, 0.0f, std::max(needs.maxCanvas, 0.0f));
        best.plots[static_cast<std::size_t>(plot)] = {0.0f, tabBar, width, room, canvas};
    }
    return best;
}

LobeFrame lobeFrame(float x, float y, float w, float h, const PlotMargins& m) {
    float roomW = w - m.left - m.right, roomH = h - m.top - m.bottom;
    LobeFrame f;
    f.radius = std::max(std::min(roomW * 0.5f, roomH), 0.0f);
    f.originX = x + m.left + roomW * 0.5f;
    f.originY = y + m.top + f.radius + std::max(roomH - f.radius, 0.0f) * 0.5f;
    return f;
}

namespace {

// The squared distance of each of points[first + 1 … last − 1] to the segment from `a` along `ab`
// into d2 (at the same indices): the span's farthest point is then one pass over numbers. Two points
// at a time (GCC's and Clang's vector extension: GCC 12 at -O2 leaves the plain loop scalar), with the
// arithmetic of one at a time in the same order (glm's dot is x·x' + y·y'; std::clamp's comparisons),
// so the numbers are the same, bit for bit.
void spanDistances(const std::vector<glm::vec2>& points, std::size_t first, std::size_t last, glm::vec2 a, glm::vec2 ab,
                   float inverse, std::vector<float>& d2) {
    using Pair = float __attribute__((vector_size(16)));  // x, y of two points
    using Mask = int __attribute__((vector_size(16)));
    const Pair A{a.x, a.y, a.x, a.y}, AB{ab.x, ab.y, ab.x, ab.y};
    const Pair zero{0.0f, 0.0f, 0.0f, 0.0f}, one{1.0f, 1.0f, 1.0f, 1.0f};
    std::size_t i = first + 1;
    for (; i + 1 < last; i += 2) {
        Pair p;
        std::memcpy(&p, &points[i], sizeof p);
        const Pair ap = p - A;
        const Pair prod = ap * AB;
        Pair t = (prod + __builtin_shufflevector(prod, prod, 1, 0, 3, 2)) * inverse;
        const Mask below = t < zero, above = one < t; // std::clamp(t, 0, 1): a NaN stays NaN
        t = reinterpret_cast<Pair>((reinterpret_cast<Mask>(t) & ~below) | (reinterpret_cast<Mask>(zero) & below));
        t = reinterpret_cast<Pair>((reinterpret_cast<Mask>(t) & ~above) | (reinterpret_cast<Mask>(one) & above));
        const Pair off = ap - t * AB;
        const Pair sq = off * off;
        const Pair d = sq + __builtin_shufflevector(sq, sq, 1, 0, 3, 2);
        d2[i] = d[0];
        d2[i + 1] = d[2];
    }
    for (; i < last; ++i) {
        const glm::vec2 ap = points[i] - a;
        const float t = std::clamp(glm::dot(ap, ab) * inverse, 0.0f, 1.0f);
        const glm::vec2 off = ap - t * ab;
        d2[i] = glm::dot(off, off);
    }
}

// The first index in (first, last) of the largest d2 when that is more than `least`, else 0: as
// one loop keeping the farthest so far would find it, but with four maxima apart, so that no
// comparison waits for the one before (the span's numbers are then found again by equality).
std::size_t farthestBeyond(const std::vector<float>& d2, std::size_t first, std::size_t last, float least) {
    float m[4] = {least, least, least, least};
    std::size_t i = first + 1;
    for (; i + 3 < last; i += 4) {
        for (std::size_t k = 0; k < 4; ++k) {
            m[k] = d2[i + k] > m[k] ? d2[i + k] : m[k]; // a NaN is never the farthest
        }
    }
    for (; i < last; ++i) {
        m[0] = d2[i] > m[0] ? d2[i] : m[0];
    }
    float most = least;
    for (float v : m) {
        most = v > most ? v : most;
    }
    if (!(most > least)) {
        return 0;
    }
    for (i = first + 1; d2[i] != most; ++i) {
    }
    return i;
}

} // namespace

std::vector<glm::vec2> thinPolyline(const std::vector<glm::vec2>& points, float tolerance) {
    if (points.size() < 3) {
        return points;
    }
    std::vector<char> keep(points.size(), 0);
    keep.front() = keep.back() = 1;
    std::vector<float> d2(points.size(), 0.0f);
    // Each span (first, last) keeps its farthest point when that lies beyond the tolerance, and
    // is split there; an explicit stack, so no curve is deep enough to matter. Squared distances
    // to the segment, so the loop has no square root.
    std::vector<std::pair<std::size_t, std::size_t>> spans{{0, points.size() - 1}};
    while (!spans.empty()) {
        auto [first, last] = spans.back();
        spans.pop_back();
        const glm::vec2 a = points[first], ab = points[last] - a;
        const float length2 = glm::dot(ab, ab);
        const float inverse = length2 > 0.0f ? 1.0f / length2 : 0.0f;
        spanDistances(points, first, last, a, ab, inverse, d2);
        const std::size_t at = farthestBeyond(d2, first, last, tolerance * tolerance);
        if (at != 0) {
            keep[at] = 1;
            spans.push_back({first, at});
            spans.push_back({at, last});
        }
    }
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (keep[i]) {
            out.push_back(points[i]);
        }
    }
    return out;
}

float scaleMaximum(float current, bool locked, float& held) {
    if (!locked || !(held > 0.0f)) {
        held = current;
    }
    return held;
}

float niceStep(float rough) {
    if (!(rough > 0.0f) || !std::isfinite(rough)) {
        return 1.0f;
    }
    float power = std::pow(10.0f, std::floor(std::log10(rough)));
    for (float m : {1.0f, 2.0f, 2.5f, 5.0f, 10.0f}) {
        if (m * power >= rough * (1.0f - 1e-5f)) {
            return m * power;
        }
    }
    return 10.0f * power;
}

std::vector<float> linearTicks(float maxValue, int maxCount) {
    if (!(maxValue > 0.0f) || !std::isfinite(maxValue) || maxCount < 1) {
        return {};
    }
    float step = niceStep(maxValue / static_cast<float>(maxCount));
    std::vector<float> ticks;
    for (int i = 1; i <= maxCount; ++i) {
        float v = step * static_cast<float>(i);
        if (v > maxValue * (1.0f + 1e-5f)) {
            break;
        }
        ticks.push_back(v);
    }
    if (ticks.empty()) {
        ticks.push_back(maxValue);
    }
    return ticks;
}

std::vector<float> decadeTicks(float maxValue, float decades) {
    std::vector<float> ticks;
    if (!(maxValue > 0.0f) || !std::isfinite(maxValue)) {
        return ticks;
    }
    float top = std::floor(std::log10(maxValue) + 1e-5f);
    float lowest = std::log10(maxValue) - decades - 1e-5f;
    for (float e = top; e >= lowest; e -= 1.0f) {
        ticks.push_back(std::pow(10.0f, e));
    }
    return ticks;
}

} // namespace lab
