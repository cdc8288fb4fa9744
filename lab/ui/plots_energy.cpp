// plots_energy.cpp — the Energy view: ρ(θi) of each term, drawn with ImDrawList.
//
// One frame: the curves of A (and B) from the plot cache (computed when the material changes),
// the readout as tokens measured and wrapped into a strip, the canvas below it taking the rest
// of the region. x is θi from 0° to 90° (the curve ends at 89°: at 90° no light arrives), y the
// albedo from 0 to a nice value at or above both 1 and the largest total.
#include "ui/plots_energy.h"
#include "ui/plot_kit.h"

#include "core/plots/energy.h"
#include "core/lighting/lighting.h"
#include "core/scene/limits.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lab::ui {

namespace {

using namespace plotkit;

// A horizontal dashed line from x0 to x1 at y.
void dashedLine(ImDrawList* dl, float x0, float x1, float y, ImU32 color, float thickness, float dash) {
    for (float x = x0; x < x1; x += 2.0f * dash) {
        dl->AddLine(ImVec2(x, y), ImVec2(std::min(x + dash, x1), y), color, thickness);
    }
}

// The readout: a legend, the numbers at the marker and what 1 means; `brief`, only the numbers
// (a low region keeps its room for the curves).
// `a` and `b` are the albedos at `incident` itself (none at 90°, where no light arrives).
Readout readout(const std::optional<Albedo>& a, const std::optional<Albedo>* b, float incident, bool brief,
                const Pens& p) {
    Readout r;
    if (!brief) {
        r.add("diffuse", kDiffuse, true);
        r.add("specular", kSpecular, true);
        r.add("total", kTotal, true);
        if (b) {
            r.add("total B", kCompare, true);
        }
        r.lineBreak();
    }
    r.add(format("at %s:", degrees(std::fabs(incident)).c_str()), kLight);
    if (a) {
        r.add(format("%.3f", double(albedoOf(*a, PlotComponent::Diffuse))), kDiffuse);
        r.add(format("+ %.3f", double(albedoOf(*a, PlotComponent::Specular))), kSpecular);
        r.add(format("= %.3f", double(albedoOf(*a, PlotComponent::Total))), kTotal);
        if (b && *b) {
            r.add(format("B %.3f", double(albedoOf(**b, PlotComponent::Total))), kCompare);
        }
    } else {
        r.add("no light arrives", kLabel);
    }
    if (!brief) {
        r.lineBreak();
        r.add("albedo = reflected / arriving light;", kLabel);
        r.add("1 = all of it (Lambert, Kd = 1)", kLabel);
    }
    r.measure(p);
    return r;
}

// The curves against θi and, on each, a dot at the preset's incident angle (atA, atB: the albedos
// there, computed at that angle, not read off the curve's whole degrees).
void energyCanvas(const Canvas& c, const Pens& p, const std::vector<AlbedoSample>& a, const std::vector<AlbedoSample>* b,
                  const std::optional<Albedo>& atA, const std::optional<Albedo>* atB, Preset& preset) {
    ImDrawList* dl = c.dl;
    float largest = 1.0f;
    for (const std::vector<AlbedoSample>* set : {&a, b}) {
        for (std::size_t i = 0; set && i < set->size(); ++i) {
            largest = std::max(largest, albedoOf((*set)[i].albedo, PlotComponent::Total));
        }
    }
    // The top of the axis: the first nice tick at or above the largest value, so that the curves
    // never reach past the frame.
    const float step = niceStep(largest / 4.0f);
    const float top = std::ceil(largest / step - 1e-4f) * step;
    Box box{ImVec2(c.corner.x + textSize("0.25").x + 2.0f * p.pad, c.corner.y + c.height - p.line - p.pad),
            ImVec2(c.corner.x + c.width - textSize("90" + std::string(kDeg)).x * 0.5f - p.pad, c.corner.y + p.line * 0.6f)};
    if (box.hi.x - box.lo.x < p.font || box.lo.y - box.hi.y < p.font) {
        return;
    }
    auto at = [&](float deg, float value) { return box.at(deg / 90.0f, value / top); };
    std::vector<RadialRing> ticks;
    int count = std::clamp(static_cast<int>((box.lo.y - box.hi.y) / (2.0f * p.line)), 1, 6);
    for (float v : linearTicks(top, count)) {
        ticks.push_back({v, v / top});
    }
    yAxis(dl, p, box, ticks, true);
    for (int deg = 0; deg <= 90; deg += 15) {
        float fd = static_cast<float>(deg);
        if (deg % 30 == 0 || box.hi.x - box.lo.x > 12.0f * p.font) {
            dl->AddLine(at(fd, 0), at(fd, top), kGrid, p.thin);
            centredText(dl, ImVec2(at(fd, 0).x, box.lo.y + p.pad * 0.5f + p.line * 0.5f), kLabel, degrees(fd));
        }
    }
    dl->AddLine(at(0, 0), at(90, 0), kAxis, p.stroke);
    dl->AddLine(at(0, 0), at(0, top), kAxis, p.stroke);
    dashedLine(dl, at(0, 1).x, at(90, 1).x, at(0, 1).y, kAxis, p.thin * 1.5f, 0.5f * p.font);

    // The marker under the curves, the curves over it.
    const float incident = std::fabs(preset.plotIncidentDeg);
    dl->AddLine(at(incident, 0), at(incident, top), kLight, p.stroke);
    auto curve = [&](const std::vector<AlbedoSample>& set, const std::optional<Albedo>& there, PlotComponent component,
                     ImU32 color, float thickness) {
        std::vector<ImVec2> points;
        points.reserve(set.size());
        for (const AlbedoSample& s : set) {
            points.push_back(at(s.incidentDeg, albedoOf(s.albedo, component)));
        }
        polyline(dl, points, color, thickness);
        if (there) {
            dl->AddCircleFilled(at(incident, albedoOf(*there, component)), 3.5f * p.s, color);
        }
    };
    curve(a, atA, PlotComponent::Diffuse, kDiffuse, p.stroke);
    curve(a, atA, PlotComponent::Specular, kSpecular, p.stroke);
    curve(a, atA, PlotComponent::Total, kTotal, p.bold);
    if (b && atB) {
        curve(*b, *atB, PlotComponent::Total, kCompare, p.stroke);
    }
    // The axes' names at their ends.
    ImVec2 end = at(90, 0);
    const char* xName = "\xce\xb8i"; // θi
    ImVec2 size = ImGui::CalcTextSize(xName);
    dl->AddText(ImVec2(end.x - size.x, end.y - size.y - p.pad * 0.5f), kLabel, xName);

    // Clicking or dragging sets the incident angle (keeping its side), as dragging L does.
    if (ImGui::IsItemActive()) {
        float u = (ImGui::GetIO().MousePos.x - box.lo.x) / (box.hi.x - box.lo.x);
        float deg = std::round(std::clamp(u, 0.0f, 1.0f) * 90.0f);
        preset.plotIncidentDeg = limits::clamp(limits::kPlotIncidentDeg, preset.plotIncidentDeg < 0.0f ? -deg : deg);
    }
}

} // namespace

void energyPanel(Preset& a, const Preset* b, PlotSettings& s) {
    const Pens p = pens();
    const PlotCache::AlbedoCurve curveA = s.cache.albedoCurve(lobeInputs(a, 0.0f));
    const PlotCache::AlbedoCurve curveB = b ? s.cache.albedoCurve(lobeInputs(*b, 0.0f)) : nullptr;
    // The numbers and the dots at the incident angle itself (the plane plots' readout has the same).
    const PlotCache::Albedos atA = s.cache.albedo(lobeInputs(a, a.plotIncidentDeg));
    const PlotCache::Albedos atB = b ? s.cache.albedo(lobeInputs(*b, a.plotIncidentDeg)) : nullptr;
    const ImVec2 room = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    // The full readout where it leaves the curves at least 8 lines, else the numbers only; the
    // strip never takes the last 5 lines (what does not fit is clipped, never scrolled to).
    Readout r = readout(*atA, atB.get(), a.plotIncidentDeg, false, p);
    if (room.y - r.height(p, room.x) < 8.0f * p.line) {
        r = readout(*atA, atB.get(), a.plotIncidentDeg, true, p);
    }
    const float stripH = std::clamp(std::min(r.height(p, room.x), room.y - 5.0f * p.line - p.gap), 1.0f, std::max(room.y, 1.0f));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(origin, ImVec2(origin.x + room.x, origin.y + stripH), true);
    r.draw(dl, p, origin, room.x);
    dl->PopClipRect();
    ImGui::Dummy(ImVec2(room.x, stripH));
    mark("plot.energy.readout");
    const float canvasH = room.y - stripH - p.gap;
    if (canvasH < 1.0f) {
        return;
    }
    ImGui::SetCursorScreenPos(ImVec2(origin.x, origin.y + stripH + p.gap));
    const Canvas canvas = beginCanvas("energy", "plot.energy", room.x, canvasH);
    if (canvas.shown()) {
        energyCanvas(canvas, p, *curveA, curveB.get(), *atA, atB.get(), a);
    }
}

} // namespace lab::ui
