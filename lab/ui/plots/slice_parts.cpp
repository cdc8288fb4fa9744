// slice_parts.cpp — the Slice view's layout, readout, axes, marker and legends (slice_parts.h).
#include "ui/plots/slice_parts.h"
#include "ui/widget_map.h"

#include "core/lighting/lighting.h"
#include "core/plots/legend.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lab::ui::slice {

using namespace plotkit;

namespace {

constexpr const char* kThetaH = "\xce\xb8h";
constexpr const char* kThetaD = "\xce\xb8" "d";
constexpr const char* kMinus = "\xe2\x88\x92"; // −

// The room around an image's square: its y values and name at the left and top, x values under it,
// x's name at the right.
struct Margins {
    float left, right, top, bottom;
};
Margins marginsOf(const Pens& p) {
    const float text = p.font, pad = 6.0f * p.font / 14.0f, tick = textSize("90\xc2\xb0").x;
    return {tick + 2.0f * pad, 0.5f * tick + 2.0f * pad + textSize(kThetaH).x, 1.6f * text, text + 2.0f * pad};
}

float legendHeight(const Pens& p) { return 2.0f * p.line + 0.8f * p.font + p.pad; }
float legendMinWidth(const Pens& p) { return 14.0f * p.font; }

int imageCount(Shown shown) { return shown == Shown::A || shown == Shown::Difference ? 1 : shown == Shown::AB ? 2 : 3; }

// The images' grid at the top of the region: the largest side over the arrangements that hold `count`.
struct Grid {
    int columns = 1, rows = 1;
    float side = 0.0f;
};
Grid bestGrid(float width, float height, int count, const Pens& p) {
    const Margins m = marginsOf(p);
    static const int shapes[][2] = {{1, 1}, {2, 1}, {1, 2}, {3, 1}, {1, 3}, {2, 2}};
    Grid best;
    for (const auto& shape : shapes) {
        const int columns = shape[0], rows = shape[1];
        if (columns * rows < count || (columns * rows > count && !(columns == 2 && rows == 2 && count == 3))) {
            continue;
        }
        const float cellW = (width - static_cast<float>(columns - 1) * p.gapX) / static_cast<float>(columns);
        const float cellH = (height - static_cast<float>(rows - 1) * p.gap) / static_cast<float>(rows);
        const float side = std::floor(std::min(cellW - m.left - m.right, cellH - m.top - m.bottom));
        if (side > best.side) {
            best = {columns, rows, side};
        }
    }
    return best;
}

// The legends' total height in a region `width` wide: side by side where both fit, else stacked.
bool legendsSideBySide(float width, const Pens& p) { return width >= 2.0f * legendMinWidth(p) + p.gapX; }

float legendsHeight(Shown shown, float width, const Pens& p) {
    const int count = (showsValueLegend(shown) ? 1 : 0) + (showsDifferenceLegend(shown) ? 1 : 0);
    if (count == 2 && !legendsSideBySide(width, p)) {
        return 2.0f * legendHeight(p) + p.gap;
    }
    return legendHeight(p);
}

} // namespace

bool showsImage(Shown shown, int i) {
    return shown == Shown::All || (shown == Shown::A && i == 0) || (shown == Shown::AB && i < 2) ||
           (shown == Shown::Difference && i == 2);
}
bool showsValueLegend(Shown shown) { return shown != Shown::Difference; }
bool showsDifferenceLegend(Shown shown) { return shown == Shown::All || shown == Shown::Difference; }

const char* componentName(PlotComponent c) {
    return c == PlotComponent::Diffuse ? "diffuse" : c == PlotComponent::Specular ? "specular" : "total";
}

Ink componentInk(PlotComponent c) {
    return c == PlotComponent::Diffuse ? Ink::Diffuse : c == PlotComponent::Specular ? Ink::Specular : Ink::Total;
}

//----------------------------------------------------------------------------------------
// Layout
//----------------------------------------------------------------------------------------

Layout arrangeImages(const ImVec4& region, Shown shown, const Pens& p) {
    Layout l;
    const float legendsH = legendsHeight(shown, region.z, p);
    const float imagesH = region.w - legendsH - p.gap;
    const int count = imageCount(shown);
    const Grid g = bestGrid(region.z, imagesH, count, p);
    if (g.side < 2.0f * p.font) {
        return l; // no room for an image worth reading: the readout alone
    }
    const Margins m = marginsOf(p);
    const float cellW = (region.z - static_cast<float>(g.columns - 1) * p.gapX) / static_cast<float>(g.columns);
    const float blockH = g.side + m.top + m.bottom;
    const float usedH = static_cast<float>(g.rows) * blockH + static_cast<float>(g.rows - 1) * p.gap;
    l.area = ImVec4(region.x, region.y, region.z, usedH);
    int k = 0;
    for (int i = 0; i < 3; ++i) {
        if (!showsImage(shown, i)) {
            continue;
        }
        const int column = k % g.columns, row = k / g.columns;
        ++k;
        const float cellX = region.x + static_cast<float>(column) * (cellW + p.gapX);
        const float x = cellX + std::max((cellW - g.side - m.left - m.right) * 0.5f, 0.0f) + m.left;
        const float y = region.y + static_cast<float>(row) * (blockH + p.gap) + m.top;
        l.images[static_cast<std::size_t>(i)] = ImVec4(std::floor(x), std::floor(y), g.side, g.side);
    }
    // The legends under the images, side by side where both fit, else one above the other.
    const float legendY = region.y + usedH + p.gap, h = legendHeight(p);
    const bool both = showsValueLegend(shown) && showsDifferenceLegend(shown);
    if (both && legendsSideBySide(region.z, p)) {
        const float w = (region.z - p.gapX) * 0.5f;
        l.valueLegend = ImVec4(region.x, legendY, w, h);
        l.differenceLegend = ImVec4(region.x + w + p.gapX, legendY, w, h);
    } else {
        const ImVec4 first(region.x, legendY, region.z, h), second(region.x, legendY + h + p.gap, region.z, h);
        l.valueLegend = showsValueLegend(shown) ? first : ImVec4(0, 0, 0, 0);
        l.differenceLegend = showsDifferenceLegend(shown) ? (both ? second : first) : ImVec4(0, 0, 0, 0);
    }
    return l;
}

bool threeFit(const ImVec4& region, const Pens& p) {
    const float imagesH = region.w - legendsHeight(Shown::All, region.z, p) - p.gap;
    return bestGrid(region.z, imagesH, 3, p).side >= 6.0f * p.font;
}

//----------------------------------------------------------------------------------------
// Readout
//----------------------------------------------------------------------------------------

Hover hoverOf(const Layout& layout) {
    Hover h;
    if (!ImGui::IsWindowHovered()) {
        return h;
    }
    const ImVec2 m = ImGui::GetIO().MousePos;
    for (std::size_t i = 0; i < layout.images.size(); ++i) {
        const ImVec4& r = layout.images[i];
        if (r.z > 0.0f && m.x >= r.x && m.x <= r.x + r.z && m.y >= r.y && m.y <= r.y + r.w) {
            h.image = static_cast<int>(i);
            h.thetaHDeg = std::round(std::clamp((m.x - r.x) / r.z, 0.0f, 1.0f) * 900.0f) / 10.0f;
            h.thetaDDeg = std::round(std::clamp((r.y + r.w - m.y) / r.w, 0.0f, 1.0f) * 900.0f) / 10.0f;
        }
    }
    return h;
}

namespace {

// Under the pointer: the angles, the values there (A's, B's and A − B in compare mode), L and V.
void hoverTokens(Readout& r, const Frame& f, const Hover& h) {
    const PlotComponent c = f.component;
    r.add(format("%s %.1f%s, %s %.1f%s:", kThetaH, double(h.thetaHDeg), kDeg, kThetaD, double(h.thetaDDeg), kDeg), Ink::Text);
    const float a = sliceValue(f.images.inA, h.thetaHDeg, h.thetaDDeg).component(c);
    if (!f.images.b) {
        r.add(format("%s %.3f", componentName(c), double(a)), componentInk(c));
    } else {
        const float b = sliceValue(f.images.inB, h.thetaHDeg, h.thetaDDeg).component(c);
        r.add(format("A %.3f", double(a)), componentInk(c));
        r.add(format("B %.3f", double(b)), Ink::Compare);
        r.add(format("A %s B %+.3f", kMinus, double(a - b)), Ink::Text);
    }
    r.lineBreak();
    const SliceVectors v = sliceVectors(h.thetaHDeg, h.thetaDDeg);
    r.add(format("L (%.2f, %.2f, %.2f)", double(v.L.x), double(v.L.y), double(v.L.z)), Ink::Light);
    r.add(format("V (%.2f, %.2f, %.2f)", double(v.V.x), double(v.V.y), double(v.V.z)), Ink::Viewer);
}

} // namespace

Readout readout(const Frame& f, const Hover& hover, const Pens& p) {
    Readout r;
    if (hover.image >= 0) {
        hoverTokens(r, f, hover);
    } else {
        r.add(format("over an image: %s, %s, the value there, its L and V", kThetaH, kThetaD), Ink::Muted);
        if (!f.brief) {
            r.lineBreak();
            r.add(format("%s: from N to H; %s: from H to L and V; \xcf\x86" "d = 90%s", kThetaH, kThetaD, kDeg), Ink::Muted);
        }
    }
    r.lineBreak();
    const SliceMarker& m = f.marker;
    r.add(format("plane plot (%si %.0f%s, V %+.0f%s): %s %.1f%s, %s %.1f%s", kTheta, double(std::fabs(f.incidentDeg)), kDeg,
                 double(f.viewerDeg), kDeg, kThetaH, double(m.thetaHDeg), kDeg, kThetaD, double(m.thetaDDeg), kDeg),
          Ink::Viewer);
    r.add(m.onSlice ? "on this slice"
                    : f.brief ? "off this slice"
                              : "off this slice (in the plane, \xcf\x86" "d is 0\xc2\xb0 or 180\xc2\xb0)",
          Ink::Muted);
    r.measure(p);
    return r;
}

float readoutHeight(const Frame& f, const Pens& p, float width) {
    const Hover over{0, 88.8f, 88.8f};
    auto measured = [&] { return std::max(readout(f, over, p).height(p, width), readout(f, Hover{}, p).height(p, width)); };
    if (!f.state) {
        return measured();
    }
    // What the readouts' text depends on (the value at `over` too: the surfaces).
    const Images& im = f.images;
    SliceState::ReadoutHeight now{true, im.b != nullptr, f.brief, im.inA, im.b ? im.inB : LobeInputs{}, f.component,
                                  f.marker.thetaHDeg, f.marker.thetaDDeg, f.marker.onSlice, f.incidentDeg, f.viewerDeg,
                                  p.font, width, 0.0f};
    auto same = [&](const SliceState::ReadoutHeight& k) {
        return k.made && k.hasB == now.hasB && k.brief == now.brief && k.a == now.a && k.b == now.b && k.component == now.component &&
               k.markerH == now.markerH && k.markerD == now.markerD && k.onSlice == now.onSlice &&
               k.incidentDeg == now.incidentDeg && k.viewerDeg == now.viewerDeg && k.font == now.font && k.width == now.width;
    };
    std::array<SliceState::ReadoutHeight, 4>& kept = f.state->readoutHeights;
    for (const SliceState::ReadoutHeight& k : kept) {
        if (same(k)) {
            return k.height;
        }
    }
    now.height = measured();
    std::move_backward(kept.begin(), kept.end() - 1, kept.end()); // the oldest goes
    kept[0] = now;
    return now.height;
}

Placement placeReadout(const Frame& f, ImVec2 origin, ImVec2 room, const Pens& p) {
    Placement at;
    auto lines = [&](float h) { return static_cast<int>(std::lround(h / p.line)); }; // a readout is whole lines high
    auto briefLines = [&](float w) {
        Frame brief = f;
        brief.brief = at.brief = true;
        return lines(readoutHeight(brief, p, w));
    };
    if (room.x > 1.6f * room.y) { // a low band: the readout beside the images
        const float w = std::clamp(0.35f * room.x, std::min(14.0f * p.font, 0.5f * room.x), 0.5f * room.x);
        const int most = static_cast<int>(std::floor(room.y / p.line));
        int n = lines(readoutHeight(f, p, w));
        n = n > most ? briefLines(w) : n;
        at.cut = n > most;
        at.strip = ImVec4(origin.x + room.x - w, origin.y, w, static_cast<float>(std::min(n, most)) * p.line);
        at.images = ImVec4(origin.x, origin.y, room.x - w - p.gapX, room.y);
        return at;
    }
    // Whether a strip of n lines leaves the images their room.
    auto roomy = [&](int n) {
        const float top = n > 0 ? static_cast<float>(n) * p.line + p.gap : 0.0f;
        if (room.y - top < 12.0f * p.line) {
            return false;
        }
        const Layout l = arrangeImages(ImVec4(origin.x, origin.y + top, room.x, room.y - top), f.shown, p);
        return l.area.z > 0.0f && std::any_of(l.images.begin(), l.images.end(), [&](const ImVec4& r) { return r.z >= 3.0f * p.font; });
    };
    int n = lines(readoutHeight(f, p, room.x));
    if (!roomy(n) && roomy(0)) { // the images can have their room: the brief readout, then fewer lines
        n = briefLines(room.x);
        for (; n > 0 && !roomy(n); --n) {
            at.cut = true;
        }
    } else if (!roomy(n)) { // no strip gives images worth reading (a narrow column): the lines that leave 12
        const int most = std::max(static_cast<int>(std::floor((room.y - p.gap - 12.0f * p.line) / p.line)), 0);
        at.cut = n > most;
        n = std::min(n, most);
    }
    const float h = static_cast<float>(n) * p.line;
    at.strip = ImVec4(origin.x, origin.y, room.x, h);
    const float top = h > 0.0f ? h + p.gap : 0.0f;
    at.images = ImVec4(origin.x, origin.y + top, room.x, room.y - top);
    return at;
}

//----------------------------------------------------------------------------------------
// An image's axes and marker
//----------------------------------------------------------------------------------------

void imageAxes(ScreenPlot& plot, const ImVec4& r, const std::string& title) {
    const PlotStyle& style = plot.style;
    const float text = style.text();
    const Box box{{r.x, r.y + r.w}, {r.x + r.z, r.y}};
    std::vector<AxisTick> ticks;
    const int step = r.z > 12.0f * text ? 15 : 30;
    for (int deg = 0; deg <= 90; deg += step) {
        const float fd = static_cast<float>(deg);
        ticks.push_back({fd / 90.0f, fd, degrees(fd)});
    }
    axes(plot.canvas, box, ticks, ticks, "", "", false);
    const float tick = style.width(degrees(90.0f), text);
    plot.canvas.text({box.lo.x, box.hi.y - text}, kThetaD, text, Ink::Text, TextAnchor::Middle);
    plot.canvas.text({box.hi.x + 0.5f * tick + style.pad(), box.lo.y + style.pad() + text * 0.5f}, kThetaH, text, Ink::Text);
    plot.canvas.text({0.5f * (box.lo.x + box.hi.x), box.hi.y - text}, title, text, Ink::Text, TextAnchor::Middle, true);
}

void drawMarker(ImDrawList* dl, const Pens& p, const ImVec4& r, const SliceMarker& marker) {
    const ImVec2 at(r.x + r.z * marker.thetaHDeg / 90.0f, r.y + r.w * (1.0f - marker.thetaDDeg / 90.0f));
    const float radius = 4.5f * p.s;
    const ImU32 light = IM_COL32(255, 255, 255, 255), dark = IM_COL32(0, 0, 0, 255);
    if (marker.onSlice) {
        dl->AddCircleFilled(at, radius + p.thin, dark);
        dl->AddCircleFilled(at, radius, light);
        return;
    }
    dl->AddCircle(at, radius, dark, 0, p.stroke + 2.0f * p.thin);
    dl->AddCircle(at, radius, light, 0, p.stroke);
    // "off this slice" beside it, on the side with room, outlined so that it reads on any colour.
    const char* label = "off this slice";
    const ImVec2 size = textSize(label);
    float x = at.x + radius + p.pad;
    if (x + size.x > r.x + r.z) {
        x = at.x - radius - p.pad - size.x;
    }
    const float y = std::clamp(at.y - size.y * 0.5f, r.y, std::max(r.y + r.w - size.y, r.y));
    for (const ImVec2 d : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1)}) {
        dl->AddText(ImVec2(x + d.x, y + d.y), dark, label);
    }
    dl->AddText(ImVec2(x, y), light, label);
}

//----------------------------------------------------------------------------------------
// Legends
//----------------------------------------------------------------------------------------

namespace {

struct LegendText {
    std::string left, right; // above the bar, at its ends
    std::string numbers[3];   // under the bar: its low end, middle and high end
};

// A legend in `r`: the words above the bar, the bar (`color` of t in [0, 1]) and its three numbers.
template <class Color>
void legend(ImDrawList* dl, const Pens& p, const ImVec4& r, const LegendText& t, Color&& color, bool muted) {
    if (r.z < 2.0f * p.font) {
        return;
    }
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.z, r.y + r.w), true);
    const ImU32 text = ink(muted ? Ink::Muted : Ink::Text);
    const float x0 = r.x + p.pad, x1 = r.x + r.z - p.pad;
    dl->AddText(ImVec2(x0, r.y), ink(Ink::Text), t.left.c_str());
    if (!t.right.empty()) {
        dl->AddText(ImVec2(x1 - textSize(t.right).x, r.y), ink(Ink::Text), t.right.c_str());
    }
    const float y0 = r.y + p.line + 0.2f * p.pad, y1 = y0 + 0.8f * p.font;
    constexpr int kSteps = 48;
    for (int i = 0; i < kSteps; ++i) {
        const float t0 = static_cast<float>(i) / kSteps, t1 = static_cast<float>(i + 1) / kSteps;
        const ImU32 c0 = color(t0), c1 = color(t1);
        dl->AddRectFilledMultiColor(ImVec2(x0 + (x1 - x0) * t0, y0), ImVec2(x0 + (x1 - x0) * t1 + 0.5f, y1), c0, c1, c1, c0);
    }
    dl->AddRect(ImVec2(x0, y0), ImVec2(x1, y1), ink(Ink::Axis), 0.0f, 0, p.thin);
    const float mid = 0.5f * (x0 + x1), ny = y1 + 0.2f * p.pad;
    dl->AddLine(ImVec2(mid, y1), ImVec2(mid, ny), ink(Ink::Axis), p.thin);
    dl->AddText(ImVec2(x0, ny), text, t.numbers[0].c_str());
    dl->AddText(ImVec2(mid - 0.5f * textSize(t.numbers[1]).x, ny), text, t.numbers[1].c_str());
    dl->AddText(ImVec2(x1 - textSize(t.numbers[2]).x, ny), text, t.numbers[2].c_str());
    dl->PopClipRect();
}

ImU32 toColor(const glm::vec3& c) {
    const glm::vec3 k = glm::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f;
    return IM_COL32(static_cast<int>(k.r), static_cast<int>(k.g), static_cast<int>(k.b), 255);
}

} // namespace

void drawLegends(ImDrawList* dl, const Pens& p, const Frame& f, RadialScale scale, ValuePalette palette) {
    const Images& im = f.images;
    if (f.layout.valueLegend.z > 0.0f) {
        widgets().set("plot.slice.legend", {f.layout.valueLegend.x, f.layout.valueLegend.y, f.layout.valueLegend.z,
                                            f.layout.valueLegend.w});
        const float outer = outerRing(im.largest);
        LegendText t;
        const std::string which = im.b ? std::string("A and B: ") + componentName(f.component) : componentName(f.component);
        t.left = im.largest > kNothingLit ? which + (scale == RadialScale::Log ? ", log (3 decades)" : ", linear")
                                          : which + ": 0 everywhere (term switched off?)";
        const float lo = scale == RadialScale::Log ? outer * std::pow(10.0f, -kLogDecades) : 0.0f;
        const float mid = scale == RadialScale::Log ? outer * std::pow(10.0f, -0.5f * kLogDecades) : 0.5f * outer;
        const int digits = legendDigits(ValueRange{lo, outer});
        t.numbers[0] = lo == 0.0f ? "0" : legendNumber(lo, digits);
        t.numbers[1] = legendNumber(mid, digits);
        t.numbers[2] = legendNumber(outer, digits);
        legend(dl, p, f.layout.valueLegend, t, [&](float u) { return toColor(paletteColor(palette, u)); }, im.coarse);
    }
    if (f.layout.differenceLegend.z > 0.0f) {
        const ImVec4& r = f.layout.differenceLegend;
        widgets().set("plot.slice.difference-legend", {r.x, r.y, r.z, r.w});
        const float m = im.largestDifference;
        LegendText t;
        if (m > kNothingLit) {
            const bool roomy = textSize("B reflects more").x + textSize("A reflects more").x + 2.0f * p.font <= r.z;
            t.left = roomy ? "\xe2\x86\x90 B reflects more" : "B more";
            t.right = roomy ? "A reflects more \xe2\x86\x92" : "A more";
            t.numbers[0] = kMinus + legendNumber(m);
            t.numbers[2] = "+" + legendNumber(m);
        } else {
            t.left = std::string("A ") + kMinus + " B: A and B reflect alike here";
            t.numbers[0] = t.numbers[2] = "0";
        }
        t.numbers[1] = "0";
        legend(dl, p, r, t, [](float u) { return toColor(divergingColor(2.0f * u - 1.0f)); }, im.coarse);
    }
}

} // namespace lab::ui::slice
