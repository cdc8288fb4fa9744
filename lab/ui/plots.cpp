// plots.cpp — drawing the lobes, the arrows and the attenuation curve with ImDrawList.
#include "ui/plots.h"

#include "ui/widgets.h"

#include "core/lighting.h"
#include "core/limits.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>

namespace lab::ui {

namespace {

constexpr ImU32 kDiffuse = IM_COL32(90, 160, 255, 255);
constexpr ImU32 kSpecular = IM_COL32(255, 160, 60, 255);
constexpr ImU32 kTotal = IM_COL32(240, 240, 240, 255);
constexpr ImU32 kCompare = IM_COL32(230, 90, 220, 255);
constexpr ImU32 kGrid = IM_COL32(255, 255, 255, 40);
constexpr ImU32 kAxis = IM_COL32(255, 255, 255, 110);
constexpr ImU32 kOverlay[3] = {IM_COL32(255, 110, 110, 255), IM_COL32(120, 230, 120, 255), IM_COL32(120, 170, 255, 255)};

// Maps the plot's unit half-disc (x right, y up along N) to screen pixels.
struct Frame {
    ImVec2 origin;
    float radius;
    ImVec2 at(glm::vec2 p) const { return ImVec2(origin.x + p.x * radius, origin.y - p.y * radius); }
    glm::vec2 from(ImVec2 s) const { return {(s.x - origin.x) / radius, (origin.y - s.y) / radius}; }
};

void arrow(ImDrawList* dl, const Frame& f, glm::vec2 dir, float length, ImU32 color, const char* label, float thickness = 2.0f) {
    glm::vec2 tip = dir * length;
    ImVec2 a = f.at({0, 0}), b = f.at(tip);
    dl->AddLine(a, b, color, thickness);
    glm::vec2 d = glm::normalize(glm::vec2(b.x - a.x, b.y - a.y));
    glm::vec2 n(-d.y, d.x);
    float s = 8.0f;
    dl->AddTriangleFilled(b, ImVec2(b.x - d.x * s + n.x * s * 0.5f, b.y - d.y * s + n.y * s * 0.5f),
                          ImVec2(b.x - d.x * s - n.x * s * 0.5f, b.y - d.y * s - n.y * s * 0.5f), color);
    dl->AddText(ImVec2(b.x + 4, b.y - ImGui::GetFontSize()), color, label);
}

void polyline(ImDrawList* dl, const Frame& f, const std::vector<glm::vec2>& points, ImU32 color, float thickness) {
    std::vector<ImVec2> screen;
    screen.reserve(points.size());
    for (const glm::vec2& p : points) {
        screen.push_back(f.at(p));
    }
    dl->AddPolyline(screen.data(), static_cast<int>(screen.size()), color, 0, thickness);
}

glm::vec2 dirFromDeg(float deg, float side) {
    float r = glm::radians(deg);
    return {side * std::sin(r), std::cos(r)};
}

// The grid of the polar plot: the surface, half circles and 30° spokes.
void polarGrid(ImDrawList* dl, const Frame& f, RadialScale scale) {
    int rings = scale == RadialScale::Linear ? 4 : static_cast<int>(kLogDecades);
    for (int i = 1; i <= rings; ++i) {
        float r = static_cast<float>(i) / static_cast<float>(rings);
        dl->PathArcTo(f.origin, r * f.radius, glm::pi<float>(), 2.0f * glm::pi<float>(), 48);
        dl->PathStroke(kGrid, 0, 1.0f);
    }
    for (int deg = -60; deg <= 60; deg += 30) {
        dl->AddLine(f.at({0, 0}), f.at(dirFromDeg(static_cast<float>(deg), 1.0f)), kGrid);
    }
    dl->AddLine(f.at({-1.05f, 0}), f.at({1.05f, 0}), kAxis, 2.0f);
}

// A plot's area: an invisible button (for the mouse) `aspect` times as tall as the panel is wide,
// filled with the plot background, registered in the widget map as `name`.
struct Canvas {
    ImVec2 corner;
    float width, height;
    ImDrawList* dl;
};

Canvas beginCanvas(const char* id, const char* name, float aspect) {
    Canvas c;
    c.width = ImGui::GetContentRegionAvail().x;
    c.height = c.width * aspect;
    c.corner = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton(id, ImVec2(c.width, c.height));
    mark(name);
    c.dl = ImGui::GetWindowDrawList();
    c.dl->AddRectFilled(c.corner, ImVec2(c.corner.x + c.width, c.corner.y + c.height), IM_COL32(20, 20, 26, 255));
    return c;
}

// The lobes of one frame: A's samples (and B's), all scaled by the same maximum.
struct Lobes {
    float incident;
    std::vector<PlotSample> a, b; // b empty without a compare set
    float maxI;
};

// x: θo from -90 to 90; y: intensity (radius function), 0 at the bottom.
void cartesianLobes(const Canvas& c, const Lobes& lobes, const PlotSettings& s) {
    ImDrawList* dl = c.dl;
    ImVec2 lo(c.corner.x + 30, c.corner.y + c.height - 18), hi(c.corner.x + c.width - 10, c.corner.y + 10);
    auto at = [&](float deg, float r) { return ImVec2(lo.x + (deg + 90.0f) / 180.0f * (hi.x - lo.x), lo.y + r * (hi.y - lo.y)); };
    for (int deg = -90; deg <= 90; deg += 30) {
        dl->AddLine(at(static_cast<float>(deg), 0), at(static_cast<float>(deg), 1), kGrid);
        char t[8];
        std::snprintf(t, sizeof t, "%d", deg);
        dl->AddText(ImVec2(at(static_cast<float>(deg), 0).x - 8, lo.y + 2), kAxis, t);
    }
    dl->AddLine(at(-90, 0), at(90, 0), kAxis, 2.0f);
    auto curve = [&](const std::vector<PlotSample>& set, PlotComponent component, ImU32 color) {
        std::vector<ImVec2> pts;
        for (const PlotSample& x : set) {
            pts.push_back(at(x.thetaOutDeg, plotRadius(componentOf(x, component), lobes.maxI, s.scale)));
        }
        dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), color, 0, 2.0f);
    };
    curve(lobes.a, PlotComponent::Diffuse, kDiffuse);
    curve(lobes.a, PlotComponent::Specular, kSpecular);
    curve(lobes.a, PlotComponent::Total, kTotal);
    if (!lobes.b.empty()) {
        curve(lobes.b, PlotComponent::Total, kCompare);
    }
    dl->AddLine(at(lobes.incident, 0), at(lobes.incident, 1), IM_COL32(120, 220, 120, 160)); // the mirror angle
}

// The probe's vectors in its own plane of incidence: N up, L to the left.
void probeArrows(ImDrawList* dl, const Frame& f, const ProbeResult& probe, BrdfModel brdf) {
    const ProbeLight& pl = probe.lights.front();
    glm::vec3 side = pl.L - pl.NoL * probe.N;
    glm::vec3 ex = glm::length(side) > 1e-5f ? -glm::normalize(side) : glm::vec3(1, 0, 0);
    auto project = [&](const glm::vec3& v) { return glm::vec2(glm::dot(v, ex), glm::dot(v, probe.N)); };
    ImU32 c = IM_COL32(255, 255, 255, 150);
    arrow(dl, f, project(pl.L), 0.6f, c, "probe L", 1.0f);
    arrow(dl, f, project(probe.V), 0.6f, c, "probe V", 1.0f);
    bool phong = brdf == BrdfModel::Phong;
    arrow(dl, f, project(phong ? pl.R : pl.H), 0.6f, c, phong ? "probe R" : "probe H", 1.0f);
}

// Dragging L (the preset's incident angle) or V (the reading direction) by its tip.
void dragArrows(const Frame& f, glm::vec2 L, glm::vec2 V, Preset& a, PlotSettings& s) {
    if (ImGui::IsItemActivated()) {
        glm::vec2 m = f.from(ImGui::GetIO().MousePos);
        s.dragging = glm::distance(m, L) < glm::distance(m, V) ? 1 : 2;
    }
    if (!ImGui::IsItemActive() || !s.dragging) {
        s.dragging = 0;
        return;
    }
    glm::vec2 m = f.from(ImGui::GetIO().MousePos);
    float deg = glm::degrees(std::atan2(m.x, std::max(m.y, 0.0f)));
    if (s.dragging == 1) {
        a.plotIncidentDeg = limits::clamp(limits::kPlotIncidentDeg, std::round(-deg));
    } else {
        s.viewerDeg = std::round(glm::clamp(deg, -90.0f, 90.0f));
    }
}

void polarLobes(const Canvas& c, const Lobes& lobes, Preset& a, PlotSettings& s, const ProbeResult* probe) {
    ImDrawList* dl = c.dl;
    Frame f{ImVec2(c.corner.x + c.width * 0.5f, c.corner.y + c.height - 14.0f), std::min(c.width * 0.46f, c.height - 34.0f)};
    polarGrid(dl, f, s.scale);
    polyline(dl, f, lobePoints(lobes.a, PlotComponent::Diffuse, lobes.maxI, s.scale), kDiffuse, 2.0f);
    polyline(dl, f, lobePoints(lobes.a, PlotComponent::Specular, lobes.maxI, s.scale), kSpecular, 2.0f);
    polyline(dl, f, lobePoints(lobes.a, PlotComponent::Total, lobes.maxI, s.scale), kTotal, 2.5f);
    if (!lobes.b.empty()) {
        polyline(dl, f, lobePoints(lobes.b, PlotComponent::Total, lobes.maxI, s.scale), kCompare, 2.0f);
    }
    glm::vec2 L = dirFromDeg(lobes.incident, -1.0f), R = dirFromDeg(lobes.incident, 1.0f), V = dirFromDeg(s.viewerDeg, 1.0f);
    arrow(dl, f, {0, 1}, 1.0f, kAxis, "N");
    arrow(dl, f, L, 1.0f, IM_COL32(255, 230, 90, 255), "L", 2.5f);
    arrow(dl, f, R, 0.85f, IM_COL32(120, 220, 120, 255), "R");
    arrow(dl, f, V, 0.95f, IM_COL32(90, 220, 230, 255), "V");
    if (a.brdf != BrdfModel::Phong) {
        glm::vec3 H = glsl::halfVector(glm::vec3(L, 0.0f), glm::vec3(V, 0.0f)); // the model's own H
        arrow(dl, f, glm::vec2(H), 0.7f, IM_COL32(255, 100, 100, 255), "H");
    }
    if (probe && !probe->lights.empty()) {
        probeArrows(dl, f, *probe, a.brdf);
    }
    dragArrows(f, L, V, a, s);
}

// The legend, and the values towards V.
void lobeLegend(const Canvas& c, const Lobes& lobes, const PlotSettings& s) {
    const PlotSample& atV = lobes.a[static_cast<std::size_t>(std::lround(glm::clamp(s.viewerDeg, -90.0f, 90.0f)) + 90)];
    ImVec2 t(c.corner.x + 6, c.corner.y + 4);
    float line = ImGui::GetTextLineHeight();
    c.dl->AddText(t, kDiffuse, "diffuse");
    c.dl->AddText(ImVec2(t.x, t.y + line), kSpecular, "specular");
    c.dl->AddText(ImVec2(t.x, t.y + 2 * line), kTotal, "total");
    if (!lobes.b.empty()) {
        c.dl->AddText(ImVec2(t.x, t.y + 3 * line), kCompare, "total (B)");
    }
    char values[96];
    std::snprintf(values, sizeof values, "at V %+.0f: %.3f + %.3f = %.3f", s.viewerDeg, atV.diffuse, atV.specular, atV.total);
    ImVec2 size = ImGui::CalcTextSize(values);
    c.dl->AddText(ImVec2(c.corner.x + c.width - size.x - 6, c.corner.y + 4), kTotal, values);
}

// Lobes and arrows for the preset's incident angle.
void lobePlot(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe) {
    const Canvas canvas = beginCanvas("lobe", "plot.lobe", 0.62f);
    Lobes lobes{a.plotIncidentDeg, reflectedIntensity(a, a.plotIncidentDeg), {}, 0.0f};
    if (b) {
        lobes.b = reflectedIntensity(*b, lobes.incident);
    }
    lobes.maxI = b ? maxTotal({lobes.a, lobes.b}) : maxTotal({lobes.a});
    if (s.cartesian) {
        cartesianLobes(canvas, lobes, s);
    } else {
        polarLobes(canvas, lobes, a, s, probe);
    }
    lobeLegend(canvas, lobes, s);
    const limits::Range& incident = limits::kPlotIncidentDeg;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.45f);
    ImGui::SliderFloat("incident", &a.plotIncidentDeg, incident.sliderMin, incident.sliderMax, "%.0f deg");
    a.plotIncidentDeg = limits::clamp(incident, a.plotIncidentDeg);
    mark("plot.incident");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    ImGui::SliderFloat("V##viewer", &s.viewerDeg, -90.0f, 90.0f, "%.0f deg");
}

void overlayPlot(const Preset& a, PlotSettings& s) {
    const Canvas canvas = beginCanvas("overlay", "plot.overlay", 0.55f);
    // Plain locals, not structured bindings: clang 14 (the browser build) cannot capture those.
    const ImVec2 corner = canvas.corner;
    const float width = canvas.width, height = canvas.height;
    ImDrawList* dl = canvas.dl;
    Frame f{ImVec2(corner.x + width * 0.5f, corner.y + height - 10.0f), std::min(width * 0.46f, height - 24.0f)};
    polarGrid(dl, f, s.scale);
    std::vector<std::vector<PlotSample>> sets;
    for (int i = 0; i < 3; ++i) {
        sets.push_back(reflectedIntensity(a, s.overlayDeg[i]));
    }
    float maxI = maxTotal(sets);
    for (int i = 0; i < 3; ++i) {
        polyline(dl, f, lobePoints(sets[static_cast<std::size_t>(i)], PlotComponent::Total, maxI, s.scale), kOverlay[i], 2.0f);
        arrow(dl, f, dirFromDeg(s.overlayDeg[i], -1.0f), 1.0f, kOverlay[i], "", 1.5f);
    }
    ImGui::DragFloat3("angles", &s.overlayDeg.x, 0.5f, -90.0f, 90.0f, "%.0f");
    s.overlayDeg = glm::clamp(s.overlayDeg, glm::vec3(-90.0f), glm::vec3(90.0f));
}

void attenuationPlot(const Preset& a, PlotSettings& s) {
    if (a.lights.empty()) {
        ImGui::TextDisabled("No lights.");
        return;
    }
    s.attenuationLight = glm::clamp(s.attenuationLight, 0, static_cast<int>(a.lights.size()) - 1);
    const LightDesc& l = a.lights[static_cast<std::size_t>(s.attenuationLight)];
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
    int shown = s.attenuationLight + 1;
    if (ImGui::SliderInt("light", &shown, 1, static_cast<int>(a.lights.size()), "Light %d")) {
        s.attenuationLight = shown - 1;
    }
    if (l.type == LightType::Directional) {
        ImGui::TextDisabled("A directional light is not attenuated (Att = 1).");
        return;
    }
    float distance = glm::length(l.position - a.model.translate);
    float maxD = std::max(5.0f, std::ceil(distance * 2.0f));
    const Canvas canvas = beginCanvas("attenuation", "plot.attenuation", 0.38f);
    // Plain locals, not structured bindings: clang 14 (the browser build) cannot capture those.
    const ImVec2 corner = canvas.corner;
    const float width = canvas.width, height = canvas.height;
    ImDrawList* dl = canvas.dl;
    ImVec2 lo(corner.x + 28, corner.y + height - 16), hi(corner.x + width - 8, corner.y + 8);
    auto at = [&](float d, float att) { return ImVec2(lo.x + d / maxD * (hi.x - lo.x), lo.y + att * (hi.y - lo.y)); };
    for (int i = 0; i <= static_cast<int>(maxD); ++i) {
        dl->AddLine(at(static_cast<float>(i), 0), at(static_cast<float>(i), 1), kGrid);
    }
    dl->AddLine(at(0, 0), at(maxD, 0), kAxis, 2.0f);
    dl->AddLine(at(0, 1), at(maxD, 1), kGrid);
    dl->AddText(ImVec2(corner.x + 4, at(0, 1).y - 6), kAxis, "1");
    dl->AddText(ImVec2(corner.x + 4, lo.y - 6), kAxis, "0");
    std::vector<ImVec2> pts;
    for (const glm::vec2& p : attenuationCurve(l.attenuation, maxD, 200)) {
        pts.push_back(at(p.x, p.y));
    }
    dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), kTotal, 0, 2.0f);
    float att = glsl::attenuation(l.attenuation, distance);
    ImVec2 m = at(distance, att);
    dl->AddCircleFilled(m, 5.0f, kSpecular);
    char label[64];
    std::snprintf(label, sizeof label, "d = %.2f, Att = %.3f", distance, att);
    dl->AddText(ImVec2(m.x + 8, m.y - ImGui::GetFontSize()), kSpecular, label);
}

} // namespace

void plotsPanel(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe) {
    int scale = s.scale == RadialScale::Linear ? 0 : 1;
    ImGui::RadioButton("linear", &scale, 0);
    mark("plot.linear");
    ImGui::SameLine();
    ImGui::RadioButton("log", &scale, 1);
    mark("plot.log");
    s.scale = scale == 0 ? RadialScale::Linear : RadialScale::Log;
    ImGui::SameLine();
    ImGui::Checkbox("Cartesian", &s.cartesian);
    mark("plot.cartesian");
    if (ImGui::CollapsingHeader("Reflection lobe", ImGuiTreeNodeFlags_DefaultOpen)) {
        lobePlot(a, b, s, probe);
    }
    if (ImGui::CollapsingHeader("Incident angles overlaid", ImGuiTreeNodeFlags_DefaultOpen)) {
        overlayPlot(a, s);
    }
    if (ImGui::CollapsingHeader("Attenuation", ImGuiTreeNodeFlags_DefaultOpen)) {
        attenuationPlot(a, s);
    }
}

} // namespace lab::ui
