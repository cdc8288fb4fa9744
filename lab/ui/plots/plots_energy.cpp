// plots_energy.cpp — the Energy view: ρ(θi) of each term, drawn as the albedo figure is
// (core/plots/plot_drawing.h) and painted onto ImGui's draw list.
//
// One frame: the curves of A (and B) from the plot cache (computed when the material changes),
// the readout as tokens measured and wrapped into a strip, the canvas below it taking the rest
// of the region. x is θi from 0° to 90° (the curve ends at 89°: at 90° no light arrives), y the
// albedo from 0 to a nice value at or above both 1 and the largest total.
#include "ui/plots/plots_energy.h"
#include "ui/plots/plot_kit.h"
#include "ui/widgets.h"

#include "core/lighting/lighting.h"
#include "core/plots/energy.h"
#include "core/scene/limits.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lab::ui {

namespace {

using namespace plotkit;

// A horizontal dashed line from x0 to x1 at y.
void dashedLine(PlotCanvas& canvas, float x0, float x1, float y, Ink ink, float width, float dash) {
    for (float x = x0; x < x1; x += 2.0f * dash) {
        canvas.line({{x, y}, {std::min(x + dash, x1), y}}, width, ink);
    }
}

// The readout: a legend, the numbers at the marker and what 1 means; `brief`, only the numbers
// (a low region keeps its room for the curves).
// `a` and `b` are the albedos at `incident` itself (none at 90°, where no light arrives).
Readout readout(const std::optional<Albedo>& a, const std::optional<Albedo>* b, float incident, bool brief, bool stale,
                const Pens& p) {
    Readout r;
    if (!brief) {
        r.add("diffuse", Ink::Diffuse, true);
        r.add("specular", Ink::Specular, true);
        r.add("total", Ink::Total, true);
        if (b) {
            r.add("total B", Ink::Compare, true);
        }
        r.lineBreak();
    }
    r.add(format("at %s:", degrees(std::fabs(incident)).c_str()), Ink::Light);
    // While they lag behind a change, the numbers are in the muted ink (the same text: nothing moves).
    auto in = [&](Ink ink) { return stale ? Ink::Muted : ink; };
    if (a) {
        r.add(format("%.3f", double(albedoOf(*a, PlotComponent::Diffuse))), in(Ink::Diffuse));
        r.add(format("+ %.3f", double(albedoOf(*a, PlotComponent::Specular))), in(Ink::Specular));
        r.add(format("= %.3f", double(albedoOf(*a, PlotComponent::Total))), in(Ink::Total));
        if (b && *b) {
            r.add(format("B %.3f", double(albedoOf(**b, PlotComponent::Total))), in(Ink::Compare));
        }
    } else {
        r.add("no light arrives", in(Ink::Text));
    }
    if (!brief) {
        r.lineBreak();
        r.add("albedo = reflected / arriving light;", Ink::Text);
        r.add("1 = all of it (Lambert, Kd = 1)", Ink::Text);
    }
    r.measure(p);
    return r;
}

// The curves against θi and, on each, a dot at the preset's incident angle (atA, atB: the albedos
// there, computed at that angle, not read off the curve's whole degrees; none while the curves lag
// behind a change, so that no dot sits off its curve).
void energyCanvas(const Canvas& c, const std::vector<AlbedoSample>& a, const std::vector<AlbedoSample>* b,
                  const std::optional<Albedo>& atA, const std::optional<Albedo>* atB, Preset& preset, PaintedLines* kept) {
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
    ScreenPlot plot;
    const PlotStyle& style = plot.style;
    const float text = style.text();
    const std::optional<Box> fits = canvasBox(c, style, "0.25", degrees(90.0f));
    if (!fits) {
        return;
    }
    const Box& box = *fits;
    auto at = [&](float deg, float value) { return box.at(deg / 90.0f, value / top); };
    std::vector<AxisTick> xs, ys{{0.0f, 0.0f}};
    const int count = std::clamp(static_cast<int>((box.lo.y - box.hi.y) / (2.5f * text)), 1, 6);
    for (float v : linearTicks(top, count)) {
        ys.push_back({v / top, v});
    }
    for (int deg = 0; deg <= 90; deg += 15) {
        const float fd = static_cast<float>(deg);
        if (deg % 30 == 0 || box.hi.x - box.lo.x > 12.0f * text) {
            xs.push_back({fd / 90.0f, fd, degrees(fd)});
        }
    }
    axes(plot.canvas, box, xs, ys, std::string(kTheta) + "i", "", false);
    dashedLine(plot.canvas, at(0, 1).x, at(90, 1).x, at(0, 1).y, Ink::Axis, style.thin() * 1.5f, 0.5f * text);

    // The marker under the curves, the curves over it.
    const float incident = std::fabs(preset.plotIncidentDeg);
    plot.canvas.line({at(incident, 0), at(incident, top)}, style.stroke(), Ink::Light);
    auto curve = [&](const std::vector<AlbedoSample>& set, const std::optional<Albedo>& there, PlotComponent component,
                     Ink ink, float width) {
        std::vector<glm::vec2> points;
        points.reserve(set.size());
        for (const AlbedoSample& s : set) {
            points.push_back(at(s.incidentDeg, albedoOf(s.albedo, component)));
        }
        plot.canvas.line(std::move(points), width, ink);
        if (there) {
            plot.canvas.disc(at(incident, albedoOf(*there, component)), 3.5f * style.scale, ink);
        }
    };
    curve(a, atA, PlotComponent::Diffuse, Ink::Diffuse, style.stroke());
    curve(a, atA, PlotComponent::Specular, Ink::Specular, style.stroke());
    curve(a, atA, PlotComponent::Total, Ink::Total, style.bold());
    if (b && atB) {
        curve(*b, *atB, PlotComponent::Total, Ink::Compare, style.stroke());
    }
    plot.paint(c.dl, kept);

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
    // The curves and the numbers lag while the material changes frame after frame (PlotCache).
    const double now = ImGui::GetTime();
    using Slot = PlotCache::Slot;
    const Lagged<std::vector<AlbedoSample>> curveA = s.cache.laggingAlbedoCurve(Slot::EnergyA, lobeInputs(a, 0.0f), now);
    const Lagged<std::vector<AlbedoSample>> curveB = b ? s.cache.laggingAlbedoCurve(Slot::EnergyB, lobeInputs(*b, 0.0f), now)
                                                       : Lagged<std::vector<AlbedoSample>>{};
    // The numbers and the dots at the incident angle itself (the plane plots' readout has the same).
    const Lagged<std::optional<Albedo>> atA = s.cache.laggingAlbedo(Slot::EnergyA, lobeInputs(a, a.plotIncidentDeg), now);
    const Lagged<std::optional<Albedo>> atB = b ? s.cache.laggingAlbedo(Slot::EnergyB, lobeInputs(*b, a.plotIncidentDeg), now)
                                                : Lagged<std::optional<Albedo>>{};
    const bool stale = atA.stale || atB.stale; // the numbers; a dot also waits for its curve
    const ImVec2 room = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    // The full readout where it leaves the curves at least 8 lines, else the numbers only; the
    // strip never takes the last 5 lines (what does not fit is clipped, never scrolled to).
    Readout r = readout(*atA.value, atB.value.get(), a.plotIncidentDeg, false, stale, p);
    if (room.y - r.height(p, room.x) < 8.0f * p.line) {
        r = readout(*atA.value, atB.value.get(), a.plotIncidentDeg, true, stale, p);
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
        const std::optional<Albedo> none;
        energyCanvas(canvas, *curveA.value, curveB.value.get(), atA.stale || curveA.stale ? none : *atA.value,
                     atB.stale || curveB.stale ? nullptr : atB.value.get(), a, &s.cache.painted());
    }
}

} // namespace lab::ui
