// plots_plane.cpp — the plots window's Plane view: the lobe, the incident angles overlaid, Att(d).
//
// One frame: sample the lighting model (core/plots/plot_data.h), or find the samples and curves of an
// earlier frame with the same inputs (ui/plots/plot_cache.h); write the readouts as tokens and measure
// them, ask core/plots/plot_layout.h where each plot goes in the room left in the window, then draw
// each plot's block there — readout strip, canvas, controls — with the cursor set explicitly, so
// nothing reaches past the region and the window never scrolls.
#include "ui/plots/plots_plane.h"
#include "ui/plots/plot_kit.h"
#include "ui/plots/plots_probe.h"

#include "ui/widgets.h"

#include "core/lighting/lighting.h"
#include "core/plots/plot_layout.h"
#include "core/plots/theme.h"
#include "core/scene/limits.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

namespace lab::ui {

namespace {

using namespace plotkit; // the drawing kit (ui/plots/plot_kit.h)

//----------------------------------------------------------------------------------------
// The plots' data, computed once a frame before anything is measured or drawn
//----------------------------------------------------------------------------------------

// The lobes of one frame: A's samples (and B's), all scaled by the same outer circle; the
// samples from the cache, found by their inputs.
struct Lobes {
    float incident = 0, viewer = 0;   // viewer: where V is drawn: the V slider's, or the probed point's
    const ProbeLobe* point = nullptr; // plots at the probe
    LobeInputs inA, inB;
    PlotCache::Samples a, b; // b null without a compare set
    float largest = 0, outer = 0; // the largest total now; the outer circle's intensity (largest, or held while locked)
    Readout readout;
};

struct Overlay {
    std::array<LobeInputs, 3> inputs;
    bool coarse = false; // every PlotCache::kCoarseStepDeg degrees, while the lobes change frame after frame
    std::array<PlotCache::Samples, 3> sets;
    float largest = 0, outer = 0;
    Readout readout;
};

struct Attenuation {
    const LightDesc* light = nullptr; // none without lights
    bool atPoint = false;             // the probed point's light and distance (no chooser then)
    float distance = 0, att = 1, maxD = 5;
    Readout readout;
};

const PlotSample& sampleAt(const std::vector<PlotSample>& s, float deg) {
    return s[static_cast<std::size_t>(std::lround(glm::clamp(deg, -90.0f, 90.0f)) + 90)];
}

// maxTotal() of the sets given.
float largestTotal(std::initializer_list<const std::vector<PlotSample>*> sets) {
    float m = 1e-6f;
    for (const std::vector<PlotSample>* set : sets) {
        for (const PlotSample& x : *set) {
            m = std::max(m, x.total);
        }
    }
    return m;
}

// How much light each term reflects in all at the lobe's incident angle (core/plots/energy.h: the
// reflected over the incident flux, a Lambertian Kd = 1 reflecting 1), as luminance: "diffuse +
// specular = total" in the curves' colours, and B's total. Short tokens without labels, so that a
// narrow column keeps room for the lobe.
// While the albedo lags behind a change (PlotCache), the numbers shown are the latest computed, in
// the muted ink (the same text: nothing moves while a drag goes on).
void albedoTokens(Readout& r, const Lagged<std::optional<Albedo>>& a, const Lagged<std::optional<Albedo>>* b, float incident) {
    r.add(format("albedo at %s:", degrees(std::fabs(incident)).c_str()), Ink::Text);
    const std::optional<Albedo>& at = *a.value;
    auto in = [&](Ink ink) { return a.stale ? Ink::Muted : ink; };
    if (!at) {
        r.add("none (no light arrives)", in(Ink::Text));
        return;
    }
    r.add(format("%.3f", double(luminance(at->diffuse))), in(Ink::Diffuse));
    r.add(format("+ %.3f", double(luminance(at->specular))), in(Ink::Specular));
    r.add(format("= %.3f", double(luminance(at->total()))), in(Ink::Total));
    if (b && *b->value) {
        r.add(format("B %.3f", double(luminance((*b->value)->total()))), b->stale ? Ink::Muted : Ink::Compare);
    }
}

Lobes lobeData(const Preset& a, const Preset* b, PlotSettings& s, const Pens& p, const ProbeLobe* point) {
    Lobes l;
    l.point = point;
    // At a probed point: its θi, the light that arrives there and its V; the preset's own angle
    // and the V slider stay as they are for when the mode ends.
    l.incident = point ? plottedIncidentDeg(*point) : a.plotIncidentDeg;
    l.viewer = point ? glm::clamp(point->viewerDeg, -90.0f, 90.0f) : s.viewerDeg;
    l.inA = point ? probeLobeInputs(a, *point) : lobeInputs(a, l.incident);
    l.a = s.cache.samples(l.inA);
    if (b) {
        l.inB = point ? probeLobeInputs(*b, *point) : lobeInputs(*b, l.incident);
        l.b = s.cache.samples(l.inB);
    }
    l.largest = b ? largestTotal({l.a.get(), l.b.get()}) : largestTotal({l.a.get()});
    l.outer = scaleMaximum(outerRing(l.largest), s.lockScale, s.lobeScale);
    if (point) {
        probeLobeTokens(l.readout, *point, l.inA, b ? &l.inB : nullptr);
    } else {
        const PlotSample& v = sampleAt(*l.a, s.viewerDeg);
        l.readout.add(format("at V %+.0f%s:", double(s.viewerDeg), kDeg), Ink::Viewer);
        l.readout.add(format("diffuse %.3f", double(v.diffuse)), Ink::Diffuse, true);
        l.readout.add(format("specular %.3f", double(v.specular)), Ink::Specular, true);
        l.readout.add(format("total %.3f", double(v.total)), Ink::Total, true);
        if (b) {
            l.readout.add(format("total B %.3f", double(sampleAt(*l.b, s.viewerDeg).total)), Ink::Compare, true);
        }
    }
    l.readout.lineBreak();
    scaleTokens(l.readout, l.outer, l.largest, s.lockScale, b ? "max total of A and B" : "max total");
    l.readout.lineBreak();
    const double now = ImGui::GetTime();
    const Lagged<std::optional<Albedo>> albedoA = s.cache.laggingAlbedo(PlotCache::Slot::PlaneA, l.inA, now);
    const Lagged<std::optional<Albedo>> albedoB = b ? s.cache.laggingAlbedo(PlotCache::Slot::PlaneB, l.inB, now)
                                                    : Lagged<std::optional<Albedo>>{};
    albedoTokens(l.readout, albedoA, b ? &albedoB : nullptr, l.incident);
    l.readout.measure(p);
    return l;
}

Overlay overlayData(const Preset& a, PlotSettings& s, const Pens& p) {
    Overlay o;
    // During a change (a drag), a coarse copy of the three (every 3rd degree: all three, so that they share one
    // scale), its readout muted, lagging like the albedo; the first frame after the change (owed) draws them in full.
    for (std::size_t i = 0; i < 3; ++i) {
        o.inputs[i] = lobeInputs(a, s.overlayDeg[static_cast<int>(i)]);
    }
    o.coarse = s.cache.coarseSet(s.overlayChanges, o.inputs);
    if (o.coarse) {
        const std::array<LobeInputs, 3>& drafted = s.overlayDraft.inputs();
        const bool moved = drafted[0].incidentDeg != o.inputs[0].incidentDeg || drafted[1].incidentDeg != o.inputs[1].incidentDeg ||
                           drafted[2].incidentDeg != o.inputs[2].incidentDeg;
        o.inputs = s.overlayDraft.take(o.inputs, ImGui::GetTime(), moved);
    }
    for (std::size_t i = 0; i < 3; ++i) {
        o.sets[i] = s.cache.samples(o.inputs[i], o.coarse);
    }
    o.largest = largestTotal({o.sets[0].get(), o.sets[1].get(), o.sets[2].get()});
    o.outer = scaleMaximum(outerRing(o.largest), s.lockScale, s.overlayScale);
    o.readout.add("total for each incident angle;", Ink::Text);
    scaleTokens(o.readout, o.outer, o.largest, s.lockScale, "max of the three", o.coarse ? Ink::Muted : Ink::Text);
    o.readout.measure(p);
    return o;
}

Attenuation attenuationData(const Preset& a, PlotSettings& s, const Pens& p, const ProbeLobe* point) {
    Attenuation t;
    if (a.lights.empty()) {
        t.readout.add("No lights.", Ink::Text);
        t.readout.measure(p);
        return t;
    }
    if (point && point->light < static_cast<int>(a.lights.size())) { // the point's light, at its distance from the point
        t.atPoint = true;
        t.light = &a.lights[static_cast<std::size_t>(point->light)];
        t.distance = point->distance;
        t.att = point->attenuation;
        t.maxD = std::max(5.0f, std::ceil(point->distance * 2.0f)); // as attenuationSpan's
        probeAttenuationTokens(t.readout, *point, t.light->type == LightType::Directional);
        t.readout.measure(p);
        return t;
    }
    s.attenuationLight = glm::clamp(s.attenuationLight, 0, static_cast<int>(a.lights.size()) - 1);
    t.light = &a.lights[static_cast<std::size_t>(s.attenuationLight)];
    std::string name = format("Light %d", s.attenuationLight + 1);
    if (t.light->type == LightType::Directional) {
        t.readout.add(name + " is directional:", Ink::Text);
        t.readout.add("Att = 1 at every distance", Ink::Specular);
    } else {
        const AttenuationSpan span = attenuationSpan(*t.light, a.model); // as the figure's (core/plots/plot_data.h)
        t.distance = span.distance;
        t.maxD = span.maxDistance;
        t.att = glsl::attenuation(t.light->attenuation, t.distance);
        t.readout.add(name + ", at the model:", Ink::Text);
        t.readout.add(format("d = %.2f", double(t.distance)), Ink::Specular);
        t.readout.add(format("Att(d) = %.3f", double(t.att)), Ink::Specular);
    }
    t.readout.measure(p);
    return t;
}

//----------------------------------------------------------------------------------------
// The lobe plot
//----------------------------------------------------------------------------------------

// The lobe's curves, where `at` puts them: A's diffuse, specular and total, and B's total; painted
// on their own, so that the rest of the plot (painted whole) stays the same while they follow a drag.
void lobeCurves(ImDrawList* dl, const Lobes& lobes, PlotSettings& s, const CurvePlacement& at) {
    ScreenPlot plot;
    const PlotStyle& style = plot.style;
    auto curve = [&](const LobeInputs& in, PlotComponent component, Ink ink, float width) {
        plot.canvas.line(*s.cache.lobe(in, component, lobes.outer, s.scale, at), width, ink);
    };
    curve(lobes.inA, PlotComponent::Diffuse, Ink::Diffuse, style.stroke());
    curve(lobes.inA, PlotComponent::Specular, Ink::Specular, style.stroke());
    curve(lobes.inA, PlotComponent::Total, Ink::Total, style.bold());
    if (lobes.b) {
        curve(lobes.inB, PlotComponent::Total, Ink::Compare, style.stroke());
    }
    plot.paint(dl, &s.cache.painted());
}

// x: θo from -90 to 90; y: intensity (radius function), 0 at the bottom.
void cartesianLobes(const Canvas& c, const Lobes& lobes, PlotSettings& s) {
    ScreenPlot plot;
    const PlotStyle& style = plot.style;
    const std::optional<Box> box = canvasBox(c, style, "0.000", degrees(90.0f));
    if (!box) {
        return;
    }
    const Box& b = *box;
    auto at = [&](float deg, float r) { return b.at((deg + 90.0f) / 180.0f, r); };
    std::vector<AxisTick> xs, ys;
    for (int deg = -90; deg <= 90; deg += 30) {
        xs.push_back({(static_cast<float>(deg) + 90.0f) / 180.0f, static_cast<float>(deg), degrees(static_cast<float>(deg))});
    }
    if (s.scale == RadialScale::Linear) {
        ys.push_back({0.0f, 0.0f});
    }
    for (const RadialRing& ring : radialRings(lobes.outer, s.scale)) {
        ys.push_back({ring.radius, ring.value});
    }
    axes(plot.canvas, b, xs, ys, "", "", false);
    plot.canvas.line({at(-90, 1), at(90, 1)}, style.thin(), Ink::Axis); // the outer circle's value
    if (s.scale == RadialScale::Log) {
        for (const DecadeMark& mark : decadeMarks(lobes.outer, style)) {
            const glm::vec2 m = b.at(0, mark.radius);
            plot.canvas.line({{m.x + mark.length, m.y}, m}, style.thin(), Ink::Axis);
        }
    }
    plot.canvas.line({at(lobes.incident, 0), at(lobes.incident, 1)}, style.thin(), Ink::Mirror); // the mirror angle
    plot.canvas.line({at(lobes.viewer, 0), at(lobes.viewer, 1)}, style.thin(), Ink::Viewer);
    plot.paintWhole(c.dl, s.cache.painted());
    lobeCurves(c.dl, lobes, s, placementOf(b));
}

// The probe's vectors in its own plane of incidence: N up, L to the left.
void probeArrows(ScreenPlot& plot, const Polar& f, const ProbeResult& probe, BrdfModel brdf) {
    const ProbeLight& pl = probe.lights.front();
    glm::vec3 side = pl.L - pl.NoL * probe.N;
    glm::vec3 ex = glm::length(side) > 1e-5f ? -glm::normalize(side) : glm::vec3(1, 0, 0);
    auto project = [&](const glm::vec3& v) { return glm::vec2(glm::dot(v, ex), glm::dot(v, probe.N)); };
    auto arrow = [&](const glm::vec3& v, const char* label) {
        plot.canvas.arrow(f.at({0, 0}), f.at(project(v) * 0.6f), Ink::Probe, plot.style.thin() * 1.5f, label);
    };
    arrow(pl.L, "probe L");
    arrow(probe.V, "probe V");
    bool phong = brdf == BrdfModel::Phong;
    arrow(phong ? pl.R : pl.H, phong ? "probe R" : "probe H");
}

// Dragging L (the preset's incident angle) or V (the reading direction) by its tip.
void dragArrows(const Polar& f, glm::vec2 L, glm::vec2 V, Preset& a, PlotSettings& s) {
    if (ImGui::IsItemActivated()) {
        glm::vec2 m = f.unitAt(toVec2(ImGui::GetIO().MousePos));
        s.dragging = glm::distance(m, L) < glm::distance(m, V) ? 1 : 2;
    }
    if (!ImGui::IsItemActive() || !s.dragging) {
        s.dragging = 0;
        return;
    }
    glm::vec2 m = f.unitAt(toVec2(ImGui::GetIO().MousePos));
    float deg = glm::degrees(std::atan2(m.x, std::max(m.y, 0.0f)));
    if (s.dragging == 1) {
        a.plotIncidentDeg = limits::clamp(limits::kPlotIncidentDeg, std::round(-deg));
    } else {
        s.viewerDeg = std::round(glm::clamp(deg, -90.0f, 90.0f));
    }
}

void polarLobes(const Canvas& c, const Lobes& lobes, Preset& a, PlotSettings& s, const ProbeResult* probe) {
    ScreenPlot plot;
    const PlotStyle& style = plot.style;
    const Polar f = polarFrame(c.origin(), c.width, c.height, style, false);
    paintWhole(c.dl, *s.cache.polarGrid(f, lobes.outer, s.scale, style), s.cache.painted()); // under the plot's shapes
    lobeCurves(c.dl, lobes, s, placementOf(f));
    glm::vec2 L = dirFromDeg(lobes.incident, -1.0f), R = dirFromDeg(lobes.incident, 1.0f), V = dirFromDeg(lobes.viewer, 1.0f);
    auto arrow = [&](glm::vec2 dir, float length, Ink ink, const char* label, float width) {
        plot.canvas.arrow(f.at({0, 0}), f.at(dir * length), ink, width, label);
    };
    arrow({0, 1}, 0.8f, Ink::Axis, "N", style.stroke());
    arrow(L, 0.92f, Ink::Light, "L", style.bold());
    arrow(R, 0.8f, Ink::Mirror, "R", style.stroke());
    // A probed point's V out of the plane of incidence is drawn as its projection: shorter.
    arrow(V, 0.88f * (lobes.point ? std::cos(glm::radians(lobes.point->outOfPlaneDeg)) : 1.0f), Ink::Viewer, "V", style.stroke());
    if (a.brdf != BrdfModel::Phong) {
        glm::vec3 H = glsl::halfVector(glm::vec3(L, 0.0f), glm::vec3(V, 0.0f)); // the model's own H
        arrow(glm::vec2(H), 0.65f, Ink::Half, "H", style.stroke());
    }
    if (probe && !probe->lights.empty() && !lobes.point) { // at the point, L and V are the probe's
        probeArrows(plot, f, *probe, a.brdf);
    }
    plot.paintWhole(c.dl, s.cache.painted());
    if (!lobes.point) {
        dragArrows(f, L, V, a, s);
    }
}

// Lobe plot rows: readout strip, canvas, the incident-angle and V sliders.
PlotNeeds lobeNeeds(const Lobes& lobes, const PlotSettings& s, const Pens& p, float width) {
    PlotNeeds n;
    n.fixed = lobes.readout.height(p, width) + 2.0f * p.gap + p.frame;
    n.minWidth = 14.0f * p.font;
    n.minCanvas = 7.0f * p.line;
    n.maxCanvas = s.cartesian ? width * 0.55f : polarMaxHeight(screenStyle(), width, false);
    n.maxCanvas = std::max(n.maxCanvas, n.minCanvas);
    return n;
}

void lobePlot(const PlotBox& box, ImVec2 origin, const Pens& p, bool cramped, const Lobes& lobes, Preset& a,
              PlotSettings& s, const ProbeResult* probe) {
    const Block block = placeBlock(box, origin, p, lobes.readout, "plot.lobe.readout", cramped, true,
                                   lobeNeeds(lobes, s, p, box.w).minCanvas, [&](float w) {
        return s.cartesian ? w * 0.55f : polarMaxHeight(screenStyle(), w, false);
    }, &s.cache.painted());
    const Canvas canvas = beginCanvas("lobe", "plot.lobe", block.canvasW, block.canvasH);
    if (canvas.shown()) {
        if (s.cartesian) {
            cartesianLobes(canvas, lobes, s);
        } else {
            polarLobes(canvas, lobes, a, s, probe);
        }
    }
    if (!block.controlsFit) {
        return;
    }
    ImGui::SetCursorScreenPos(block.controls);
    const limits::Range& incident = limits::kPlotIncidentDeg;
    float labels = ImGui::CalcTextSize("incident").x + ImGui::CalcTextSize("V").x + 2.0f * p.inner + p.gapX;
    float field = std::max((box.w - labels) * 0.5f, p.font);
    if (lobes.point) {
        probeSliders(*lobes.point, field);
        return;
    }
    std::string unit = "%.0f" + std::string(kDeg);
    ImGui::SetNextItemWidth(field);
    ImGui::SliderFloat("incident", &a.plotIncidentDeg, incident.sliderMin, incident.sliderMax, unit.c_str());
    a.plotIncidentDeg = limits::clamp(incident, a.plotIncidentDeg);
    mark("plot.incident");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(field);
    ImGui::SliderFloat("V##viewer", &s.viewerDeg, -90.0f, 90.0f, unit.c_str());
    mark("plot.viewer");
}

//----------------------------------------------------------------------------------------
// The incident angles overlaid
//----------------------------------------------------------------------------------------

PlotNeeds overlayNeeds(const Overlay& o, const Pens& p, float width) {
    PlotNeeds n;
    n.fixed = o.readout.height(p, width) + 2.0f * p.gap + p.frame;
    n.minWidth = 12.0f * p.font;
    n.minCanvas = 6.0f * p.line;
    n.maxCanvas = std::max(polarMaxHeight(screenStyle(), width, false), n.minCanvas);
    return n;
}

// An ink's darker shade as a field background (theme.h kFieldShades: white text on it 4.5:1).
ImVec4 shade(Ink ink, float k) {
    const FigureColor c = shaded(colorOf(*screenStyle().palette, ink), k);
    return ImVec4(float(c.r) / 255.0f, float(c.g) / 255.0f, float(c.b) / 255.0f, 1.0f);
}

void overlayPlot(const PlotBox& box, ImVec2 origin, const Pens& p, bool cramped, const Overlay& o, PlotSettings& s) {
    const Block block = placeBlock(box, origin, p, o.readout, "plot.overlay.readout", cramped, true,
                                   overlayNeeds(o, p, box.w).minCanvas, [&](float w) { return polarMaxHeight(screenStyle(), w, false); },
                                   &s.cache.painted());
    const Canvas canvas = beginCanvas("overlay", "plot.overlay", block.canvasW, block.canvasH);
    if (canvas.shown()) {
        ScreenPlot plot;
        const Polar f = polarFrame(canvas.origin(), canvas.width, canvas.height, plot.style, false);
        paintWhole(canvas.dl, *s.cache.polarGrid(f, o.outer, s.scale, plot.style), s.cache.painted());
        for (std::size_t i = 0; i < 3; ++i) {
            const PlotCache::Points curve = s.cache.lobe(o.inputs[i], PlotComponent::Total, o.outer, s.scale, placementOf(f), o.coarse);
            plot.canvas.line(*curve, plot.style.stroke(), overlayInk(i));
        }
        for (std::size_t i = 0; i < 3; ++i) {
            float deg = s.overlayDeg[static_cast<int>(i)];
            // The fields name them.
            plot.canvas.arrow(f.at({0, 0}), f.at(dirFromDeg(deg, -1.0f) * 0.9f), overlayInk(i), plot.style.stroke(), "");
        }
        plot.paintWhole(canvas.dl, s.cache.painted()); // the curves lag during a drag of the material
    }
    // The three angles, each field in its curve's colour.
    if (!block.controlsFit) {
        return;
    }
    ImGui::SetCursorScreenPos(block.controls);
    float label = ImGui::CalcTextSize("angles").x + p.inner;
    float field = std::max((box.w - label - 2.0f * p.inner) / 3.0f, p.font);
    std::string unit = "%.0f" + std::string(kDeg);
    static const char* const ids[3] = {"##angle0", "##angle1", "##angle2"};
    static const char* const marks[3] = {"plot.overlay.angle0", "plot.overlay.angle1", "plot.overlay.angle2"};
    for (int i = 0; i < 3; ++i) {
        if (i > 0) {
            ImGui::SameLine(0.0f, p.inner);
        }
        ImGui::PushStyleColor(ImGuiCol_FrameBg, shade(overlayInk(std::size_t(i)), kFieldShades[0]));
        ImGui::PushStyleColor(ImGuiCol_FrameBgHovered, shade(overlayInk(std::size_t(i)), kFieldShades[1]));
        ImGui::PushStyleColor(ImGuiCol_FrameBgActive, shade(overlayInk(std::size_t(i)), kFieldShades[2]));
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 255, 255, 255));
        ImGui::SetNextItemWidth(field);
        ImGui::DragFloat(ids[i], &s.overlayDeg[i], 0.5f, -90.0f, 90.0f, unit.c_str());
        ImGui::PopStyleColor(4);
        mark(marks[i]);
    }
    ImGui::SameLine(0.0f, p.inner);
    ImGui::TextUnformatted("angles");
    s.overlayDeg = glm::clamp(s.overlayDeg, glm::vec3(-90.0f), glm::vec3(90.0f));
}

//----------------------------------------------------------------------------------------
// Attenuation
//----------------------------------------------------------------------------------------

// At a probed point the probe's window chooses the light.
bool lightChooser(const Preset& a, const Attenuation& t) { return a.lights.size() > 1 && !t.atPoint; }

PlotNeeds attenuationNeeds(const Attenuation& t, const Preset& a, const Pens& p, float width) {
    PlotNeeds n;
    n.fixed = t.readout.height(p, width) + p.gap + (lightChooser(a, t) ? p.frame + p.gap : 0.0f);
    n.minWidth = 12.0f * p.font;
    if (t.light) {
        n.minCanvas = 5.0f * p.line;
        n.maxCanvas = std::max(width * 0.42f, n.minCanvas);
    }
    return n;
}

void attenuationCanvas(const Canvas& c, const Attenuation& t, PlotCache& cache) {
    ScreenPlot plot;
    const PlotStyle& style = plot.style;
    const std::optional<Box> box = canvasBox(c, style, "0.5", "10");
    if (!box) {
        return;
    }
    const Box& b = *box;
    const float maxD = t.maxD;
    auto at = [&](float d, float att) { return b.at(d / maxD, att); };
    std::vector<AxisTick> xs, ys{{0.0f, 0.0f}, {0.5f, 0.5f}, {1.0f, 1.0f}};
    const int count = std::clamp(static_cast<int>((b.hi.x - b.lo.x) / (3.5f * style.text())), 2, 10);
    for (float d : linearTicks(maxD, count)) {
        xs.push_back({d / maxD, d});
    }
    axes(plot.canvas, b, xs, ys, "d", "", false);
    if (t.light->type == LightType::Directional) {
        plot.canvas.line({at(0, 1), at(maxD, 1)}, style.bold(), Ink::Total);
    } else {
        plot.canvas.line(*cache.attenuation(t.light->attenuation, maxD, placementOf(b)), style.bold(), Ink::Total);
        const glm::vec2 m = at(t.distance, t.att);
        plot.canvas.line({at(t.distance, 0), m}, style.thin(), Ink::Specular);
        plot.canvas.disc(m, 5.0f * style.scale, Ink::Specular);
    }
    plot.paintWhole(c.dl, cache.painted());
}

void attenuationPlot(const PlotBox& box, ImVec2 origin, const Pens& p, bool cramped, const Attenuation& t,
                     const Preset& a, PlotSettings& s) {
    const Block block = placeBlock(box, origin, p, t.readout, "plot.attenuation.readout", cramped, lightChooser(a, t),
                                   attenuationNeeds(t, a, p, box.w).minCanvas, [&](float w) { return t.light ? w * 0.42f : 0.0f; },
                                   &s.cache.painted());
    if (t.light) {
        const Canvas canvas = beginCanvas("attenuation", "plot.attenuation", block.canvasW, block.canvasH);
        if (canvas.shown()) {
            attenuationCanvas(canvas, t, s.cache);
        }
    }
    if (lightChooser(a, t) && block.controlsFit) {
        ImGui::SetCursorScreenPos(block.controls);
        ImGui::SetNextItemWidth(std::max(box.w - ImGui::CalcTextSize("light").x - p.inner, p.font));
        int shown = s.attenuationLight + 1;
        if (ImGui::SliderInt("light", &shown, 1, static_cast<int>(a.lights.size()), "Light %d")) {
            s.attenuationLight = shown - 1;
        }
        mark("plot.attenuation.light");
    }
}

//----------------------------------------------------------------------------------------
// The options row
//----------------------------------------------------------------------------------------

// A checkbox's or radio button's width, for ui/widgets.h's sameLineIfFits.
float checkWidth(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

void options(PlotSettings& s) {
    // Full labels where they fit on one line, short ones (with the full meaning as a tooltip)
    // where they do not, so that the row does not take two lines of a low band.
    const char* full[4] = {"linear###linear", "log###log", "Cartesian###cartesian", "lock scale###lock"};
    const char* brief[4] = {"lin###linear", "log###log", "x-y###cartesian", "lock###lock"};
    float width = 3.0f * ImGui::GetStyle().ItemSpacing.x;
    for (const char* label : full) {
        width += checkWidth(label);
    }
    const char* const* labels = width <= ImGui::GetContentRegionAvail().x ? full : brief;
    auto tip = [&](const char* text) {
        if (labels == brief) {
            itemTooltip(text);
        }
    };
    int scale = s.scale == RadialScale::Linear ? 0 : 1;
    ImGui::RadioButton(labels[0], &scale, 0);
    mark("plot.linear");
    tip("linear radius");
    sameLineIfFits(checkWidth(labels[1]));
    ImGui::RadioButton(labels[1], &scale, 1);
    mark("plot.log");
    tip("logarithmic radius");
    s.scale = scale == 0 ? RadialScale::Linear : RadialScale::Log;
    sameLineIfFits(checkWidth(labels[2]));
    ImGui::Checkbox(labels[2], &s.cartesian);
    mark("plot.cartesian");
    tip("Cartesian: intensity against the outgoing angle");
    sameLineIfFits(checkWidth(labels[3]));
    ImGui::Checkbox(labels[3], &s.lockScale);
    mark("plot.lock");
    itemTooltip("Off: the outer ring is the largest total in the plot, and follows every change. "
                "On: the outer ring keeps its value, so a change (another BRDF, a shininess) "
                "shows its real size; lobes beyond it are cut at the ring.");
}

} // namespace

void planeView(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe, const ProbeLobe* point) {
    options(s);
    const Pens p = pens();
    const Lobes lobes = lobeData(a, b, s, p, point);
    const Overlay overlay = overlayData(a, s, p);
    const Attenuation attenuation = attenuationData(a, s, p, point);

    const ImVec2 room = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float tabBar = p.frame + p.gap;
    auto needs = [&](int plot, float width) {
        switch (plot) {
        case 0: return lobeNeeds(lobes, s, p, width);
        case 1: return overlayNeeds(overlay, p, width);
        default: return attenuationNeeds(attenuation, a, p, width);
        }
    };
    const PlotsLayout layout = arrangePlots(room.x, room.y, p.gap * 2.0f, tabBar, needs);
    widgets().set("plots.area", {origin.x, origin.y, room.x, room.y});

    ImGui::PushClipRect(origin, ImVec2(origin.x + room.x, origin.y + room.y), true);
    auto draw = [&](int plot) {
        const PlotBox& box = layout.plots[static_cast<std::size_t>(plot)];
        // A low band only (wider than tall): in a narrow column the readout wraps above the canvas.
        bool cramped = layout.arrangement == PlotArrangement::Tabs && box.canvas < needs(plot, box.w).minCanvas &&
                       box.w > 1.2f * box.h;
        switch (plot) {
        case 0: lobePlot(box, origin, p, cramped, lobes, a, s, probe); break;
        case 1: overlayPlot(box, origin, p, cramped, overlay, s); break;
        default: attenuationPlot(box, origin, p, cramped, attenuation, a, s); break;
        }
    };
    if (layout.arrangement != PlotArrangement::Tabs) {
        for (int plot = 0; plot < kPlotCount; ++plot) {
            draw(plot);
        }
    } else if (ImGui::BeginTabBar("plots.tabs")) {
        // No room for all three: one at a time, each with the whole area below the tabs.
        static const char* const names[kPlotCount] = {"Lobe", "Angles", "Att(d)"};
        for (int plot = 0; plot < kPlotCount; ++plot) {
            if (ImGui::BeginTabItem(names[plot])) {
                draw(plot);
                ImGui::EndTabItem();
            }
        }
        ImGui::EndTabBar();
    }
    ImGui::PopClipRect();
}

} // namespace lab::ui
