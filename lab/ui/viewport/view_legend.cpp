// view_legend.cpp — the legend strip and the wipe's divider, drawn with ImGui's draw list.
#include "ui/viewport/view_legend.h"

#include "core/lighting/lighting.h"
#include "core/plots/legend.h"
#include "ui/widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace lab::ui {

namespace {

float unit() { return ImGui::GetFontSize() / 13.0f; }
float pad() { return 0.4f * ImGui::GetFontSize(); }

ImU32 toColor(const glm::vec3& c) {
    auto byte = [](float v) { return static_cast<int>(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f))); };
    return IM_COL32(byte(c.r), byte(c.g), byte(c.b), 255);
}

constexpr ImU32 kText = IM_COL32(235, 235, 235, 255);
constexpr ImU32 kDim = IM_COL32(170, 170, 170, 255);

// The palette across [x0, x1] × [y0, y1]: one quad per step, coloured at both ends as the shaders
// colour a value (viridis is linear between its stops, so 64 steps draw it exactly).
void paletteBar(ValuePalette palette, float x0, float y0, float x1, float y1, ImDrawList* dl) {
    constexpr int kSteps = 64;
    for (int i = 0; i < kSteps; ++i) {
        float t0 = static_cast<float>(i) / kSteps, t1 = static_cast<float>(i + 1) / kSteps;
        ImU32 c0 = toColor(paletteColor(palette, t0)), c1 = toColor(paletteColor(palette, t1));
        dl->AddRectFilledMultiColor(ImVec2(x0 + (x1 - x0) * t0, y0), ImVec2(x0 + (x1 - x0) * t1 + 0.5f, y1), c0, c1, c1, c0);
    }
    dl->AddRect(ImVec2(x0, y0), ImVec2(x1, y1), IM_COL32(0, 0, 0, 255));
}

} // namespace

std::string constantWords(const LegendModel& m) { return m.range ? lab::constantWords(m.title, *m.range) : std::string(); }

float legendStripHeight() { return 2.0f * ImGui::GetFontSize() + 3.0f * pad(); }

void legendStrip(const LegendModel& m, const Rect& r, ImDrawList* dl) {
    if (r.w <= 0.0f || r.h <= 0.0f) {
        return;
    }
    widgets().set("view.legend", r);
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true);
    const float line = ImGui::GetFontSize(), p = pad();
    float y = r.y + p;
    std::string right;
    if (m.value) {
        right = "here: " + legendNumber(*m.value, m.range ? legendDigits(*m.range) : 3);
    }
    float rightW = right.empty() ? 0.0f : ImGui::CalcTextSize(right.c_str()).x;
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w - rightW - 2 * p, r.y + r.h), true);
    const std::string said = constantWords(m), title = said.empty() ? m.title : said; // a constant: what it is
    dl->AddText(ImVec2(r.x + p, y), kText, title.c_str());
    dl->PopClipRect();
    if (!right.empty()) {
        dl->AddText(ImVec2(r.x + r.w - p - rightW, y), kText, right.c_str());
    }
    y += line + p;
    if (!m.range) {
        dl->AddText(ImVec2(r.x + p, y), kDim, m.note.c_str());
        dl->PopClipRect();
        return;
    }
    // lo [bar] hi (automatic), the middle's value under its tick, the cursor's value marked on the bar.
    const int digits = legendDigits(*m.range);
    std::string lo = legendNumber(m.range->lo, digits), hi = legendNumber(m.range->hi, digits) + (m.automatic ? "  (auto)" : "");
    float loW = ImGui::CalcTextSize(lo.c_str()).x, hiW = ImGui::CalcTextSize(hi.c_str()).x;
    dl->AddText(ImVec2(r.x + p, y), kText, lo.c_str());
    dl->AddText(ImVec2(r.x + r.w - p - hiW, y), kText, hi.c_str());
    float x0 = r.x + 2 * p + loW, x1 = std::max(x0 + 1.0f, r.x + r.w - 2 * p - hiW);
    float y0 = y + 0.15f * line, y1 = y + 0.85f * line;
    paletteBar(m.palette, x0, y0, x1, y1, dl);
    widgets().set("view.legend-bar", {x0, y0, x1 - x0, y1 - y0});
    dl->AddLine(ImVec2(0.5f * (x0 + x1), y1), ImVec2(0.5f * (x0 + x1), y1 + 0.15f * line), kText, unit());
    if (m.value) {
        float x = x0 + (x1 - x0) * rangePosition(*m.value, *m.range);
        dl->AddTriangleFilled(ImVec2(x, y0 + 0.2f * line), ImVec2(x - 0.3f * line, y0 - 0.2f * line),
                              ImVec2(x + 0.3f * line, y0 - 0.2f * line), IM_COL32(255, 255, 255, 255));
        dl->AddTriangle(ImVec2(x, y0 + 0.2f * line), ImVec2(x - 0.3f * line, y0 - 0.2f * line),
                        ImVec2(x + 0.3f * line, y0 - 0.2f * line), IM_COL32(0, 0, 0, 255), unit());
    }
    dl->PopClipRect();
}

void wipeDivider(float at, const Rect& r, bool active, ImDrawList* dl) {
    float x = std::round(r.x + std::clamp(at, 0.0f, 1.0f) * r.w);
    float s = 9.0f * unit(), cy = r.y + 0.5f * r.h;
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true);
    dl->AddLine(ImVec2(x, r.y), ImVec2(x, r.y + r.h), IM_COL32(0, 0, 0, 200), 4.0f * unit());
    dl->AddLine(ImVec2(x, r.y), ImVec2(x, r.y + r.h), IM_COL32(255, 255, 255, 255), 2.0f * unit());
    dl->AddCircleFilled(ImVec2(x, cy), s, active ? IM_COL32(255, 220, 90, 255) : IM_COL32(255, 255, 255, 255));
    dl->AddCircle(ImVec2(x, cy), s, IM_COL32(0, 0, 0, 255), 0, 1.5f * unit());
    // Two arrows on the handle: it moves sideways.
    float a = 0.45f * s;
    dl->AddTriangleFilled(ImVec2(x - 0.25f * s - a, cy), ImVec2(x - 0.25f * s, cy - a), ImVec2(x - 0.25f * s, cy + a),
                          IM_COL32(0, 0, 0, 255));
    dl->AddTriangleFilled(ImVec2(x + 0.25f * s + a, cy), ImVec2(x + 0.25f * s, cy - a), ImVec2(x + 0.25f * s, cy + a),
                          IM_COL32(0, 0, 0, 255));
    dl->PopClipRect();
    widgets().set("view.wipe", {x - s, cy - s, 2 * s, 2 * s});
}

float wipeGrabDistance() { return 10.0f * unit(); }

} // namespace lab::ui
