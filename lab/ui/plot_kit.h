// plot_kit.h — the plots' drawing kit, shared by the plot files of lab/ui (not a public API):
// colours and pens that grow with the font (presenter mode), number formatting, readouts of
// coloured tokens that wrap into strips of their own, canvases, the polar frame, grid and axes.
// ImGui's draw lists only; the numbers come from core/plots/plot_data.h and core/plots/plot_layout.h.
#pragma once

#include "ui/plot_cache.h"
#include "ui/plots.h"
#include "ui/widgets.h"

#include "core/plots/plot_layout.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

namespace lab::ui::plotkit {

//----------------------------------------------------------------------------------------
// Colours and pens
//----------------------------------------------------------------------------------------

constexpr ImU32 kDiffuse = IM_COL32(90, 160, 255, 255);
constexpr ImU32 kSpecular = IM_COL32(255, 160, 60, 255);
constexpr ImU32 kTotal = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kCompare = IM_COL32(240, 100, 230, 255);
constexpr ImU32 kBackground = IM_COL32(16, 16, 20, 255);
// Grid and axes bright enough to survive a projector: light grey on near black, not dark grey.
constexpr ImU32 kGrid = IM_COL32(135, 135, 150, 255);
constexpr ImU32 kAxis = IM_COL32(215, 215, 225, 255);
constexpr ImU32 kLabel = IM_COL32(225, 225, 232, 255);
constexpr ImU32 kLight = IM_COL32(255, 230, 90, 255);
constexpr ImU32 kMirror = IM_COL32(120, 220, 120, 255);
constexpr ImU32 kViewer = IM_COL32(90, 220, 230, 255);
constexpr ImU32 kHalf = IM_COL32(255, 110, 110, 255);
constexpr ImU32 kProbe = IM_COL32(255, 255, 255, 170);
constexpr ImU32 kWarning = IM_COL32(255, 120, 100, 255);
constexpr ImU32 kOverlay[3] = {IM_COL32(255, 110, 110, 255), IM_COL32(120, 230, 120, 255), IM_COL32(120, 170, 255, 255)};
constexpr const char* kDeg = "\xc2\xb0"; // the degree sign, UTF-8

// Sizes for this frame, all from the font size so that they grow with presenter mode.
struct Pens {
    float s;      // UI scale: font size / 13
    float font;   // font size
    float line;   // text line height
    float frame;  // a slider's height
    float gap;    // vertical space between rows (ImGui's item spacing)
    float gapX;   // horizontal space between items
    float inner;  // between a widget and its label
    float pad;    // text offset from what it labels
    float thin;   // grid
    float stroke; // curves and arrows
    float bold;   // the total and L
    float head;   // arrowhead length
};

inline Pens pens() {
    const ImGuiStyle& style = ImGui::GetStyle();
    Pens p;
    p.font = ImGui::GetFontSize();
    p.s = p.font / 13.0f;
    p.line = ImGui::GetTextLineHeight();
    p.frame = ImGui::GetFrameHeight();
    p.gap = style.ItemSpacing.y;
    p.gapX = style.ItemSpacing.x;
    p.inner = style.ItemInnerSpacing.x;
    p.pad = 4.0f * p.s;
    p.thin = std::max(1.0f, 1.0f * p.s);
    p.stroke = 2.0f * p.s;
    p.bold = 3.0f * p.s;
    p.head = 9.0f * p.s;
    return p;
}

inline std::string format(const char* f, ...) {
    char text[96];
    va_list args;
    va_start(args, f);
    std::vsnprintf(text, sizeof text, f, args);
    va_end(args);
    return text;
}

// A value on an axis: 3 significant digits, no trailing zeros.
inline std::string tickText(float v) { return format("%.3g", double(v)); }

inline std::string degrees(float deg) { return format("%.0f%s", double(deg), kDeg); }

inline ImVec2 textSize(const std::string& t) { return ImGui::CalcTextSize(t.c_str(), t.c_str() + t.size()); }

// Text centred on c.
inline void centredText(ImDrawList* dl, ImVec2 c, ImU32 color, const std::string& t) {
    ImVec2 size = textSize(t);
    dl->AddText(ImVec2(std::round(c.x - size.x * 0.5f), std::round(c.y - size.y * 0.5f)), color, t.c_str(),
                t.c_str() + t.size());
}

//----------------------------------------------------------------------------------------
// Readouts: coloured tokens that wrap, in a strip of their own above a canvas
//----------------------------------------------------------------------------------------

struct Token {
    std::string text;
    ImU32 color = kLabel;
    bool swatch = false; // a short line in the colour before the text: the curve it names
    float width = kLineBreak;
};

struct Readout {
    std::vector<Token> tokens;
    std::vector<float> widths;

    void add(std::string text, ImU32 color, bool swatch = false) {
        tokens.push_back({std::move(text), color, swatch, 0.0f});
    }
    void lineBreak() { tokens.push_back({}); }
    void measure(const Pens& p) {
        widths.clear();
        for (Token& t : tokens) {
            if (t.text.empty()) {
                t.width = kLineBreak;
            } else {
                t.width = textSize(t.text).x + (t.swatch ? 1.4f * p.font + p.pad : 0.0f);
            }
            widths.push_back(t.width);
        }
    }
    float height(const Pens& p, float width) const {
        return static_cast<float>(flowLines(widths, p.font * 0.5f, width)) * p.line;
    }
    void draw(ImDrawList* dl, const Pens& p, ImVec2 at, float width) const {
        std::vector<FlowPlace> places = flowTokens(widths, p.font * 0.5f, width);
        for (std::size_t i = 0; i < tokens.size(); ++i) {
            const Token& t = tokens[i];
            if (t.width == kLineBreak) {
                continue;
            }
            ImVec2 c(at.x + places[i].x, at.y + static_cast<float>(places[i].line) * p.line);
            if (t.swatch) {
                float y = c.y + p.line * 0.5f;
                dl->AddLine(ImVec2(c.x, y), ImVec2(c.x + 1.4f * p.font, y), t.color, p.bold);
                c.x += 1.4f * p.font + p.pad;
            }
            dl->AddText(c, t.color, t.text.c_str(), t.text.c_str() + t.text.size());
        }
    }
};

// maxTotal()'s floor: below it there is nothing to plot, and the scale shows 0 to 1.

// What the outer circle stands for, in words (in tokens that can wrap), with a warning when a
// locked scale cuts a lobe.
inline void scaleTokens(Readout& r, float outer, float largest, bool locked, const char* what) {
    if (!locked && !(largest > kNothingLit)) {
        r.add("all 0 (terms switched off?)", kLabel);
        return;
    }
    r.add(format("outer ring %s", tickText(outer).c_str()), kLabel);
    if (locked) {
        r.add("(locked)", kLabel);
        if (largest > outer * 1.001f) {
            r.add(format("peak %s beyond it", tickText(largest).c_str()), kWarning);
        }
    } else {
        r.add(format("= %s", what), kLabel);
    }
}

//----------------------------------------------------------------------------------------
// Canvases and the polar frame
//----------------------------------------------------------------------------------------

// Maps the plot's unit half-disc (x right, y up along N) to screen pixels.
struct Frame {
    ImVec2 origin;
    float radius;
    ImVec2 at(glm::vec2 p) const { return ImVec2(origin.x + p.x * radius, origin.y - p.y * radius); }
    glm::vec2 from(ImVec2 s) const {
        float r = std::max(radius, 1.0f);
        return {(s.x - origin.x) / r, (origin.y - s.y) / r};
    }
    CurvePlacement placement() const { return {true, {origin.x, origin.y}, {radius, -radius}}; }
};

struct Canvas {
    ImVec2 corner;
    float width = 0, height = 0;
    ImDrawList* dl = nullptr;
    bool shown() const { return dl != nullptr; }
};

// A plot's area at the cursor: an invisible button (for the mouse), filled with the plot
// background, registered in the widget map as `name`. Not drawn when it has no room.
inline Canvas beginCanvas(const char* id, const char* name, float width, float height) {
    Canvas c;
    if (width < 1.0f || height < 1.0f) {
        return c;
    }
    c.width = width;
    c.height = height;
    c.corner = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton(id, ImVec2(width, height));
    mark(name);
    c.dl = ImGui::GetWindowDrawList();
    c.dl->AddRectFilled(c.corner, ImVec2(c.corner.x + width, c.corner.y + height), kBackground);
    return c;
}

inline glm::vec2 dirFromDeg(float deg, float side) {
    float r = glm::radians(deg);
    return {side * std::sin(r), std::cos(r)};
}

// The room a polar plot keeps for its labels: angle labels above and beside the rim, ring
// values and the 90° labels under the surface line.
inline PlotMargins polarMargins(const Pens& p) {
    float side = textSize("60" + std::string(kDeg)).x * 0.75f + p.pad;
    return {side, side, p.line + p.pad, p.line + p.pad};
}

inline Frame polarFrame(const Canvas& c, const Pens& p) {
    LobeFrame f = lobeFrame(c.corner.x, c.corner.y, c.width, c.height, polarMargins(p));
    return {ImVec2(f.originX, f.originY), f.radius};
}

// The tallest a polar canvas is worth at `width`: the half-disc as wide as it can be.
inline float polarMaxHeight(const Pens& p, float width) {
    PlotMargins m = polarMargins(p);
    return std::max((width - m.left - m.right) * 0.5f, 0.0f) + m.top + m.bottom;
}

// An arrow on screen from `a` to `b` with its name beside the tip; one too short to point
// anywhere (a 3D vector seen end on) is a dot with its name.
inline void arrowBetween(ImDrawList* dl, const Pens& p, ImVec2 a, ImVec2 b, ImU32 color, const char* label, float thickness) {
    glm::vec2 d(b.x - a.x, b.y - a.y);
    const float len = glm::length(d);
    if (len < 1e-3f) {
        dl->AddCircleFilled(a, 3.0f * p.s, color);
    } else {
        d /= len;
        const glm::vec2 n(-d.y, d.x);
        const float h = std::min(p.head, len * 0.5f);
        const ImVec2 base(b.x - d.x * h, b.y - d.y * h);
        dl->AddLine(a, base, color, thickness);
        dl->AddTriangleFilled(b, ImVec2(base.x + n.x * h * 0.5f, base.y + n.y * h * 0.5f),
                              ImVec2(base.x - n.x * h * 0.5f, base.y - n.y * h * 0.5f), color);
    }
    if (label && *label) {
        // Beside the tip, on the side away from the arrow's own line.
        const ImVec2 size = ImGui::CalcTextSize(label);
        const float x = d.x >= 0.0f ? b.x + p.pad : b.x - p.pad - size.x;
        dl->AddText(ImVec2(x, b.y - size.y - p.pad * 0.5f), color, label);
    }
}

inline void arrow(ImDrawList* dl, const Pens& p, const Frame& f, glm::vec2 dir, float length, ImU32 color, const char* label,
           float thickness) {
    arrowBetween(dl, p, f.at({0, 0}), f.at(dir * length), color, label, thickness);
}

inline void polyline(ImDrawList* dl, const std::vector<ImVec2>& points, ImU32 color, float thickness) {
    dl->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, thickness);
}

// The polar grid: rings with their intensities under the surface line (right of N), the outer
// circle, spokes every 30° with their angles outside the rim (90° under the surface line's
// ends), and on a log scale the marks of 2…9 within each decade along the surface.
inline void polarGrid(ImDrawList* dl, const Pens& p, const Frame& f, float maxI, RadialScale scale) {
    if (f.radius < 2.0f * p.font) {
        dl->AddLine(f.at({-1.05f, 0}), f.at({1.05f, 0}), kAxis, p.stroke);
        return;
    }
    const float pi = glm::pi<float>();
    int segments = std::clamp(static_cast<int>(f.radius / 4.0f), 24, 96);
    // The 90° labels sit under the ends of the surface line; ring labels stop short of them.
    const std::string ninety = degrees(90.0f);
    const float ninetyW = textSize(ninety).x;
    const float below = f.origin.y + p.pad + p.line * 0.5f;
    for (float side : {-1.0f, 1.0f}) {
        centredText(dl, ImVec2(f.origin.x + side * (f.radius + p.pad), below), kLabel, ninety);
    }
    float labelsEnd = f.origin.x; // the right edge of the last ring label, to skip crowded ones
    const float labelsLimit = f.origin.x + f.radius + p.pad - ninetyW * 0.5f - p.pad;
    for (const RadialRing& ring : radialRings(maxI, scale)) {
        dl->PathArcTo(f.origin, ring.radius * f.radius, pi, 2.0f * pi, segments);
        dl->PathStroke(kGrid, 0, p.thin);
        std::string t = tickText(ring.value);
        float w = textSize(t).x, x = f.origin.x + ring.radius * f.radius;
        if (x - w * 0.5f > labelsEnd + p.pad && x + w * 0.5f < labelsLimit) {
            centredText(dl, ImVec2(x, below), kLabel, t);
            labelsEnd = x + w * 0.5f;
        }
    }
    dl->PathArcTo(f.origin, f.radius, pi, 2.0f * pi, segments);
    dl->PathStroke(kAxis, 0, p.thin);
    for (int deg = -60; deg <= 60; deg += 30) {
        glm::vec2 d = dirFromDeg(static_cast<float>(deg), 1.0f);
        dl->AddLine(f.at({0, 0}), f.at(d), kGrid, p.thin);
        std::string t = degrees(static_cast<float>(std::abs(deg)));
        ImVec2 size = textSize(t), rim = f.at(d * 1.0f);
        float out = p.pad + 0.5f * (std::abs(d.x) * size.x + std::abs(d.y) * size.y);
        centredText(dl, ImVec2(rim.x + d.x * out, rim.y - d.y * out), kLabel, t);
    }
    dl->AddLine(f.at({-1.02f, 0}), f.at({1.02f, 0}), kAxis, p.stroke);
    if (scale == RadialScale::Log) {
        // 2…9 times each decade: ticks standing on the surface line, on both sides of N.
        for (float decade : decadeTicks(maxI * 10.0f, kLogDecades + 1.0f)) {
            for (int k = 2; k <= 9; ++k) {
                float r = plotRadius(decade * 0.1f * static_cast<float>(k), maxI, scale);
                if (r <= 0.0f || r >= 1.0f) {
                    continue;
                }
                for (float side : {-1.0f, 1.0f}) {
                    ImVec2 m = f.at({side * r, 0});
                    dl->AddLine(ImVec2(m.x, m.y - (k == 5 ? 0.6f : 0.4f) * p.font), m, kAxis, p.thin);
                }
            }
        }
    }
}

// A Cartesian plot's frame: lo is the bottom left (x from, y 0), hi the top right.
struct Box {
    ImVec2 lo, hi;
    ImVec2 at(float u, float v) const { return ImVec2(lo.x + u * (hi.x - lo.x), lo.y + v * (hi.y - lo.y)); }
};

// Values up the left axis of a box: each (value, v in [0, 1]) with a grid line and its text;
// "0" at the bottom where the axis starts at 0 (not on a logarithmic one).
inline void yAxis(ImDrawList* dl, const Pens& p, const Box& b, const std::vector<RadialRing>& ticks, bool fromZero) {
    for (const RadialRing& t : ticks) {
        ImVec2 y = b.at(0, t.radius);
        dl->AddLine(y, b.at(1, t.radius), kGrid, p.thin);
        std::string text = tickText(t.value);
        ImVec2 size = textSize(text);
        dl->AddText(ImVec2(b.lo.x - p.pad - size.x, y.y - size.y * 0.5f), kLabel, text.c_str());
    }
    if (fromZero) {
        centredText(dl, ImVec2(b.lo.x - p.pad - textSize("0").x * 0.5f, b.lo.y), kLabel, "0");
    }
}

} // namespace lab::ui::plotkit
