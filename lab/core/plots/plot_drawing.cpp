// plot_drawing.cpp — the curves' dashes, the text helpers, and the frames, grids, axes and arrows every
// plot and figure is drawn with.
#include "core/plots/plot_drawing.h"

#include "core/plots/text_raster.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace lab {

//----------------------------------------------------------------------------------------
// Colours, sizes, text
//----------------------------------------------------------------------------------------

std::vector<float> dashOf(Ink ink, float scale) {
    std::vector<float> d;
    switch (ink) {
    case Ink::Diffuse:
    case Ink::Overlay2: d = {7.0f, 5.0f}; break;
    case Ink::Specular:
    case Ink::Overlay3: d = {0.0f, 5.0f}; break;
    case Ink::Compare: d = {12.0f, 5.0f, 0.0f, 5.0f}; break;
    default: break;
    }
    for (float& v : d) {
        v *= scale;
    }
    return d;
}

float printedWidth(std::string_view text, float size) {
    const TextFont& font = sharedTextFont();
    return font.measure(text, size * font.lineHeightPerEm()).width;
}

std::string format(const char* f, ...) {
    char text[96];
    va_list args;
    va_start(args, f);
    std::vsnprintf(text, sizeof text, f, args);
    va_end(args);
    return text;
}

// The plots write the same few ring values and angles on every frame (a screen plot is drawn 60
// times a second): the latest ones are kept, each thread its own, so that printf runs only for new
// numbers. Keyed on the float's bits, so that equal keys print equally (−0 apart from 0).
namespace {

template <std::size_t N> class RecentTexts {
public:
    template <class Print> const std::string& get(float v, Print&& print) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        Entry& e = entries_[(bits ^ (bits >> 13) ^ (bits >> 23)) % N];
        if (!e.used || e.bits != bits) {
            e = {bits, true, print(v)};
        }
        return e.text;
    }

private:
    struct Entry {
        std::uint32_t bits = 0;
        bool used = false;
        std::string text;
    };
    std::array<Entry, N> entries_;
};

} // namespace

std::string tickText(float v) {
    thread_local RecentTexts<64> kept;
    return kept.get(v, [](float x) { return format("%.3g", double(x)); });
}

std::string degrees(float deg) {
    thread_local RecentTexts<64> kept;
    return kept.get(deg, [](float x) { return format("%.0f", double(x)) + kDeg; });
}

namespace {

// degrees(60) and degrees(90), which margins and grids measure on every frame.
constexpr const char* kSixtyDegrees = "60\xc2\xb0";
constexpr const char* kNinetyDegrees = "90\xc2\xb0";

} // namespace

//----------------------------------------------------------------------------------------
// A plot being drawn
//----------------------------------------------------------------------------------------

void PlotCanvas::line(std::vector<glm::vec2> points, float width, Ink ink, std::string id) {
    figure_.shapes.emplace_back(std::in_place_type<FigureLine>, FigureLine{std::move(points), width, style_.color(ink),
                                                                           std::move(id), dashOf(ink, style_.scale)});
}

void PlotCanvas::text(glm::vec2 at, std::string text, float size, Ink ink, TextAnchor anchor, bool bold) {
    figure_.shapes.emplace_back(std::in_place_type<FigureText>,
                                FigureText{{at.x, at.y + 0.365f * size}, std::move(text), size, style_.color(ink), anchor, bold});
}

void PlotCanvas::disc(glm::vec2 centre, float radius, Ink ink) {
    figure_.shapes.emplace_back(std::in_place_type<FigureDisc>, FigureDisc{centre, radius, style_.color(ink)});
}

void PlotCanvas::polygon(std::vector<glm::vec2> points, Ink ink) {
    figure_.shapes.emplace_back(std::in_place_type<FigurePolygon>, FigurePolygon{std::move(points), style_.color(ink)});
}

void PlotCanvas::arrow(glm::vec2 from, glm::vec2 to, Ink ink, float width, const std::string& label) {
    glm::vec2 d = to - from;
    const float len = glm::length(d);
    if (len < 1.0f) {
        disc(from, 1.5f * style_.stroke(), ink);
    } else {
        d /= len;
        const glm::vec2 n(-d.y, d.x);
        const float head = std::min(style_.head(), len * 0.5f);
        const glm::vec2 base = to - d * head;
        line({from, base}, width, ink);
        polygon({to, base + n * head * 0.45f, base - n * head * 0.45f}, ink);
    }
    if (!label.empty()) {
        // Beside the tip, on the side away from the arrow's own line.
        const float x = d.x >= 0.0f ? to.x + style_.pad() : to.x - style_.pad();
        text({x, to.y - style_.text() * 0.6f}, label, style_.text(), ink, d.x >= 0.0f ? TextAnchor::Start : TextAnchor::End,
             true);
    }
}

//----------------------------------------------------------------------------------------
// Polar plots
//----------------------------------------------------------------------------------------

glm::vec2 Polar::unitAt(glm::vec2 point) const {
    const float r = std::max(radius, 1.0f);
    return {(point.x - origin.x) / r, (origin.y - point.y) / r};
}

glm::vec2 dirFromDeg(float deg, float side) {
    const float r = glm::radians(deg);
    return {side * std::sin(r), std::cos(r)};
}

PlotMargins polarMargins(const PlotStyle& s, bool caption) {
    if (!caption) {
        // Compact, for a plot among others in a window: the spoke labels beside the rim may reach
        // into the corners the half-disc leaves free.
        const float side = 0.75f * s.width(kSixtyDegrees, s.text()) + s.pad();
        return {side, side, s.text() + s.pad(), s.text() + s.pad()};
    }
    const float side = s.width(kNinetyDegrees, s.text()) + s.pad();
    return {side, side, s.text() + 2.0f * s.pad(), 2.0f * (s.text() + s.pad()) + s.pad()};
}

Polar polarFrame(glm::vec2 corner, float width, float height, const PlotStyle& style, bool caption) {
    const LobeFrame f = lobeFrame(corner.x, corner.y, width, height, polarMargins(style, caption));
    return {{f.originX, f.originY}, f.radius};
}

float polarMaxHeight(const PlotStyle& style, float width, bool caption) {
    const PlotMargins m = polarMargins(style, caption);
    return std::max((width - m.left - m.right) * 0.5f, 0.0f) + m.top + m.bottom;
}

namespace {

// (-cos a, sin a) for a = π·i/120, i = 0…120: the half circle every arc is drawn along.
const std::array<glm::vec2, 121>& halfCircle() {
    static const std::array<glm::vec2, 121> table = [] {
        std::array<glm::vec2, 121> t{};
        for (int i = 0; i <= 120; ++i) {
            const float a = glm::pi<float>() * static_cast<float>(i) / 120;
            t[static_cast<std::size_t>(i)] = {-std::cos(a), std::sin(a)};
        }
        return t;
    }();
    return table;
}

// A ring of radius r (unit) as a polyline, from the surface on the left over the top: 120
// segments, or on screen (arcStep > 0) about one per arcStep pixels, 24 at the least.
std::vector<glm::vec2> arc(const Polar& p, float r, const PlotStyle& style) {
    int every = 1; // every 1st, 2nd, 3rd, 4th or 5th point of the table: 120, 60, 40, 30 or 24 segments
    if (style.arcStep > 0.0f) {
        const float segments = std::max(r * p.radius / style.arcStep, 1.0f);
        every = std::clamp(static_cast<int>(120.0f / segments), 1, 5);
        while (120 % every != 0) {
            --every;
        }
    }
    std::vector<glm::vec2> pts;
    pts.reserve(static_cast<std::size_t>(120 / every + 1));
    for (std::size_t i = 0; i <= 120; i += static_cast<std::size_t>(every)) {
        pts.push_back(p.at(halfCircle()[i] * r));
    }
    return pts;
}

} // namespace

std::vector<DecadeMark> decadeMarks(float outer, const PlotStyle& style) {
    std::vector<DecadeMark> marks;
    for (float decade : decadeTicks(outer * 10.0f, kLogDecades + 1.0f)) {
        for (int k = 2; k <= 9; ++k) {
            const float r = plotRadius(decade * 0.1f * static_cast<float>(k), outer, RadialScale::Log);
            if (r > 0.0f && r < 1.0f) {
                marks.push_back({r, (k == 5 ? 8.0f : 5.0f) * style.scale});
            }
        }
    }
    return marks;
}

void polarGrid(PlotCanvas& canvas, const Polar& p, float outer, RadialScale scale, bool caption) {
    const PlotStyle& s = canvas.style();
    if (p.radius < 2.0f * s.text()) {
        canvas.line({p.at({-1.05f, 0}), p.at({1.05f, 0})}, s.stroke(), Ink::Axis);
        return;
    }
    const float below = p.origin.y + s.pad() + s.text() * 0.5f;
    for (float side : {-1.0f, 1.0f}) {
        canvas.text({p.origin.x + side * (p.radius + s.pad()), below}, kNinetyDegrees, s.text(), Ink::Text, TextAnchor::Middle);
    }
    // Ring values stop short of the 90° label, and skip one that would crowd the last.
    const float limit = p.origin.x + p.radius + s.pad() - s.width(kNinetyDegrees, s.text()) * 0.5f - s.pad();
    float labelsEnd = p.origin.x;
    for (auto [v, r] : radialRings(outer, scale)) {
        if (r < 0.999f) {
            canvas.line(arc(p, r, s), s.thin(), Ink::Grid);
        }
        const std::string t = tickText(v);
        const float w = s.width(t, s.small()), x = p.origin.x + r * p.radius;
        if (x - w * 0.5f > labelsEnd + s.pad() && x + w * 0.5f < limit) {
            canvas.text({x, below}, t, s.small(), Ink::Muted, TextAnchor::Middle);
            labelsEnd = x + w * 0.5f;
        }
    }
    for (int deg = -60; deg <= 60; deg += 30) {
        const glm::vec2 d = dirFromDeg(static_cast<float>(deg), 1.0f);
        canvas.line({p.at({0, 0}), p.at(d)}, s.thin(), Ink::Grid);
        const std::string t = degrees(static_cast<float>(std::abs(deg)));
        const glm::vec2 rim = p.at(d);
        const float out = s.pad() + 0.5f * (std::abs(d.x) * s.width(t, s.text()) + std::abs(d.y) * s.text());
        canvas.text({rim.x + d.x * out, rim.y - d.y * out}, t, s.text(), Ink::Text, TextAnchor::Middle);
    }
    canvas.line(arc(p, 1.0f, s), s.thin(), Ink::Axis);
    if (scale == RadialScale::Log) {
        for (const DecadeMark& mark : decadeMarks(outer, s)) {
            for (float side : {-1.0f, 1.0f}) {
                const glm::vec2 m = p.at({side * mark.radius, 0});
                canvas.line({{m.x, m.y - mark.length}, m}, s.thin(), Ink::Axis);
            }
        }
    }
    canvas.line({p.at({-1.02f, 0}), p.at({1.02f, 0})}, s.stroke(), Ink::Axis);
    if (caption) {
        const std::string text = "radius: reflected intensity, " +
                                 std::string(scale == RadialScale::Linear ? "linear" : "logarithmic (3 decades)") +
                                 "; outer circle " + tickText(outer);
        canvas.text({p.origin.x, below + s.text() + s.pad()}, text, s.small(), Ink::Muted, TextAnchor::Middle);
    }
}

//----------------------------------------------------------------------------------------
// Cartesian plots
//----------------------------------------------------------------------------------------

void axes(PlotCanvas& canvas, const Box& b, const std::vector<AxisTick>& xTicks, const std::vector<AxisTick>& yTicks,
          const std::string& xName, const std::string& yName, bool outside) {
    const PlotStyle& s = canvas.style();
    auto label = [](const AxisTick& t) { return t.text.empty() ? tickText(t.value) : t.text; };
    for (const AxisTick& t : yTicks) {
        const glm::vec2 y = b.at(0, t.at);
        if (t.at > 0.0f) {
            canvas.line({y, b.at(1, t.at)}, s.thin(), Ink::Grid);
        }
        canvas.text({b.lo.x - s.pad(), y.y}, label(t), s.text(), Ink::Text, TextAnchor::End);
    }
    for (const AxisTick& t : xTicks) {
        const glm::vec2 x = b.at(t.at, 0);
        if (t.at > 0.0f) {
            canvas.line({x, b.at(t.at, 1)}, s.thin(), Ink::Grid);
        }
        canvas.text({x.x, b.lo.y + s.pad() + s.text() * 0.5f}, label(t), s.text(), Ink::Text, TextAnchor::Middle);
    }
    canvas.line({b.at(0, 0), b.at(1.0f, 0)}, s.stroke(), Ink::Axis);
    canvas.line({b.at(0, 0), b.at(0, 1.0f)}, s.stroke(), Ink::Axis);
    if (outside) {
        canvas.text({b.lo.x, b.hi.y - s.text() - s.pad()}, yName, s.text(), Ink::Text, TextAnchor::Middle, true);
        canvas.text({b.at(0.5f, 0).x, b.lo.y + 2.0f * s.pad() + s.text() * 1.5f}, xName, s.text(), Ink::Text,
                    TextAnchor::Middle, true);
    } else if (!xName.empty()) {
        canvas.text({b.hi.x, b.lo.y - s.pad() - s.text() * 0.5f}, xName, s.text(), Ink::Text, TextAnchor::End);
    }
}

} // namespace lab
