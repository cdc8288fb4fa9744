// plots.cpp — drawing the lobes, the arrows and the attenuation curve with ImDrawList.
//
// One frame: sample the lighting model (core/plots/plot_data.h), or find the samples and curves of an
// earlier frame with the same inputs (ui/plot_cache.h); write the readouts as tokens and measure
// them, ask core/plots/plot_layout.h where each plot goes in the room left in the window, then draw
// each plot's block there — readout strip, canvas, controls — with the cursor set explicitly, so
// nothing reaches past the region and the window never scrolls.
#include "ui/plots.h"
#include "ui/plot_kit.h"
#include "ui/plots_energy.h"

#include "ui/widgets.h"

#include "core/lighting/lighting.h"
#include "core/scene/limits.h"
#include "core/plots/plot_layout.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdarg>
#include <cstdio>
#include <functional>
#include <string>

namespace lab::ui {

namespace {

using namespace plotkit; // the drawing kit (ui/plot_kit.h)

//----------------------------------------------------------------------------------------
// The plots' data, computed once a frame before anything is measured or drawn
//----------------------------------------------------------------------------------------

// The lobes of one frame: A's samples (and B's), all scaled by the same outer circle; the
// samples from the cache, found by their inputs.
struct Lobes {
    float incident = 0;
    LobeInputs inA, inB;
    PlotCache::Samples a, b; // b null without a compare set
    float largest = 0;       // the largest total now
    float outer = 0;         // the outer circle's intensity (largest, or held while locked)
    Readout readout;
};

struct Overlay {
    std::array<LobeInputs, 3> inputs;
    std::array<PlotCache::Samples, 3> sets;
    float largest = 0, outer = 0;
    Readout readout;
};

struct Attenuation {
    const LightDesc* light = nullptr; // none without lights
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
void albedoTokens(Readout& r, const std::optional<Albedo>& a, const std::optional<Albedo>* b, float incident) {
    r.add(format("albedo at %s:", degrees(std::fabs(incident)).c_str()), kLabel);
    if (!a) {
        r.add("none (no light arrives)", kLabel);
        return;
    }
    r.add(format("%.3f", double(luminance(a->diffuse))), kDiffuse);
    r.add(format("+ %.3f", double(luminance(a->specular))), kSpecular);
    r.add(format("= %.3f", double(luminance(a->total()))), kTotal);
    if (b && *b) {
        r.add(format("B %.3f", double(luminance((*b)->total()))), kCompare);
    }
}

Lobes lobeData(const Preset& a, const Preset* b, PlotSettings& s, const Pens& p) {
    Lobes l;
    l.incident = a.plotIncidentDeg;
    l.inA = lobeInputs(a, l.incident);
    l.a = s.cache.samples(l.inA);
    if (b) {
        l.inB = lobeInputs(*b, l.incident);
        l.b = s.cache.samples(l.inB);
    }
    l.largest = b ? largestTotal({l.a.get(), l.b.get()}) : largestTotal({l.a.get()});
    l.outer = scaleMaximum(outerRing(l.largest), s.lockScale, s.lobeScale);
    const PlotSample& v = sampleAt(*l.a, s.viewerDeg);
    l.readout.add(format("at V %+.0f%s:", double(s.viewerDeg), kDeg), kViewer);
    l.readout.add(format("diffuse %.3f", double(v.diffuse)), kDiffuse, true);
    l.readout.add(format("specular %.3f", double(v.specular)), kSpecular, true);
    l.readout.add(format("total %.3f", double(v.total)), kTotal, true);
    if (b) {
        l.readout.add(format("total B %.3f", double(sampleAt(*l.b, s.viewerDeg).total)), kCompare, true);
    }
    l.readout.lineBreak();
    scaleTokens(l.readout, l.outer, l.largest, s.lockScale, b ? "max total of A and B" : "max total");
    l.readout.lineBreak();
    albedoTokens(l.readout, *s.cache.albedo(l.inA), b ? s.cache.albedo(l.inB).get() : nullptr, l.incident);
    l.readout.measure(p);
    return l;
}

Overlay overlayData(const Preset& a, PlotSettings& s, const Pens& p) {
    Overlay o;
    for (std::size_t i = 0; i < 3; ++i) {
        o.inputs[i] = lobeInputs(a, s.overlayDeg[static_cast<int>(i)]);
        o.sets[i] = s.cache.samples(o.inputs[i]);
    }
    o.largest = largestTotal({o.sets[0].get(), o.sets[1].get(), o.sets[2].get()});
    o.outer = scaleMaximum(outerRing(o.largest), s.lockScale, s.overlayScale);
    o.readout.add("total for each incident angle;", kLabel);
    scaleTokens(o.readout, o.outer, o.largest, s.lockScale, "max of the three");
    o.readout.measure(p);
    return o;
}

Attenuation attenuationData(const Preset& a, PlotSettings& s, const Pens& p) {
    Attenuation t;
    if (a.lights.empty()) {
        t.readout.add("No lights.", kLabel);
        t.readout.measure(p);
        return t;
    }
    s.attenuationLight = glm::clamp(s.attenuationLight, 0, static_cast<int>(a.lights.size()) - 1);
    t.light = &a.lights[static_cast<std::size_t>(s.attenuationLight)];
    std::string name = format("Light %d", s.attenuationLight + 1);
    if (t.light->type == LightType::Directional) {
        t.readout.add(name + " is directional:", kLabel);
        t.readout.add("Att = 1 at every distance", kSpecular);
    } else {
        const AttenuationSpan span = attenuationSpan(*t.light, a.model); // as the figure's (core/plots/plot_data.h)
        t.distance = span.distance;
        t.maxD = span.maxDistance;
        t.att = glsl::attenuation(t.light->attenuation, t.distance);
        t.readout.add(name + ", at the model:", kLabel);
        t.readout.add(format("d = %.2f", double(t.distance)), kSpecular);
        t.readout.add(format("Att(d) = %.3f", double(t.att)), kSpecular);
    }
    t.readout.measure(p);
    return t;
}

//----------------------------------------------------------------------------------------
// A plot's block: readout strip, canvas, controls
//----------------------------------------------------------------------------------------

// Where a block's canvas and controls go. Normally the readout is a strip above the canvas and
// the controls a row below it. When even one plot at a time leaves the canvas too short (a low
// band at a large UI scale), the readout moves to a column at the right of the canvas instead.
struct Block {
    ImVec2 canvas;
    float canvasW = 0, canvasH = 0;
    ImVec2 controls;
    bool controlsFit = true; // false where the row would reach past the block: it is left out
};

Block placeBlock(const PlotBox& box, ImVec2 origin, const Pens& p, const Readout& r, const char* readoutMark,
                 bool cramped, bool controls, float minCanvas, const std::function<float(float)>& maxCanvas) {
    const ImVec2 top(origin.x + box.x, origin.y + box.y);
    const float controlsH = controls ? p.frame + p.gap : 0.0f;
    Block b;
    float stripW = box.w, stripH = r.height(p, box.w);
    ImVec2 strip = top;
    if (cramped) {
        // Too low for the controls too: the canvas takes the whole height (drag L and V in it).
        // Else the controls take the bottom row, across the whole width: the text stays above it.
        const bool controlsShown = controls && box.h - controlsH - p.gap >= 3.0f * p.line;
        const float textRoom = controlsShown ? box.h - controlsH : box.h;
        // The narrowest column (from 30% to 60% of the width) whose text fits the height.
        for (float share = 0.3f; share <= 0.61f; share += 0.05f) {
            stripW = box.w * share;
            stripH = r.height(p, stripW);
            if (stripH <= textRoom) {
                break;
            }
        }
        stripH = std::min(stripH, textRoom); // what still does not fit is clipped, never scrolled to
        strip = ImVec2(top.x + box.w - stripW, top.y);
        b.canvas = top;
        b.canvasW = box.w - stripW - p.gapX;
        float room = controlsShown ? box.h - controlsH - p.gap : box.h;
        b.canvasH = std::clamp(room, 0.0f, maxCanvas(b.canvasW));
    } else {
        float canvasH = box.canvas;
        if (canvasH < minCanvas) {
            // One plot at a time in a column too low for its wrapped readout (a narrow column at a
            // large UI scale): the readout gives way, clipped, so that the canvas keeps its minimum.
            canvasH = std::min(minCanvas, std::max(box.h - controlsH - p.gap, 0.0f));
            stripH = std::max(box.h - controlsH - p.gap - canvasH, 0.0f);
        }
        b.canvas = ImVec2(top.x, top.y + stripH + p.gap);
        b.canvasW = box.w;
        b.canvasH = canvasH;
    }
    // Below the canvas and the text, whichever ends lower (beside a short canvas the text may).
    b.controls = ImVec2(top.x, std::max(b.canvas.y + b.canvasH, strip.y + stripH) + p.gap);
    b.controlsFit = b.controls.y + p.frame <= top.y + box.h + 0.5f;
    ImGui::SetCursorScreenPos(strip);
    ImGui::Dummy(ImVec2(stripW, std::max(stripH, 1.0f)));
    mark(readoutMark);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(strip, ImVec2(strip.x + stripW, strip.y + std::max(stripH, 1.0f)), true);
    r.draw(dl, p, strip, stripW);
    dl->PopClipRect();
    ImGui::SetCursorScreenPos(b.canvas);
    return b;
}

//----------------------------------------------------------------------------------------
// The lobe plot
//----------------------------------------------------------------------------------------

// The lobe's curves, where `at` puts them: A's diffuse, specular and total, and B's total.
void lobeCurves(ImDrawList* dl, const Pens& p, const Lobes& lobes, PlotSettings& s, const CurvePlacement& at) {
    auto curve = [&](const LobeInputs& in, PlotComponent component, ImU32 color, float thickness) {
        polyline(dl, *s.cache.lobe(in, component, lobes.outer, s.scale, at), color, thickness);
    };
    curve(lobes.inA, PlotComponent::Diffuse, kDiffuse, p.stroke);
    curve(lobes.inA, PlotComponent::Specular, kSpecular, p.stroke);
    curve(lobes.inA, PlotComponent::Total, kTotal, p.bold);
    if (lobes.b) {
        curve(lobes.inB, PlotComponent::Total, kCompare, p.stroke);
    }
}

// x: θo from -90 to 90; y: intensity (radius function), 0 at the bottom.
void cartesianLobes(const Canvas& c, const Pens& p, const Lobes& lobes, PlotSettings& s) {
    ImDrawList* dl = c.dl;
    std::vector<RadialRing> ticks = radialRings(lobes.outer, s.scale);
    float labelW = textSize("0.000").x;
    Box b{ImVec2(c.corner.x + labelW + 2.0f * p.pad, c.corner.y + c.height - p.line - p.pad),
          ImVec2(c.corner.x + c.width - textSize("90" + std::string(kDeg)).x * 0.5f - p.pad, c.corner.y + p.line * 0.6f)};
    if (b.hi.x - b.lo.x < p.font || b.lo.y - b.hi.y < p.font) {
        return;
    }
    auto at = [&](float deg, float r) { return b.at((deg + 90.0f) / 180.0f, r); };
    yAxis(dl, p, b, ticks, s.scale == RadialScale::Linear);
    dl->AddLine(at(-90, 1), at(90, 1), kAxis, p.thin); // the outer circle's value
    for (int deg = -90; deg <= 90; deg += 30) {
        dl->AddLine(at(static_cast<float>(deg), 0), at(static_cast<float>(deg), 1), kGrid, p.thin);
        centredText(dl, ImVec2(at(static_cast<float>(deg), 0).x, b.lo.y + p.pad * 0.5f + p.line * 0.5f), kLabel,
                    degrees(static_cast<float>(deg)));
    }
    if (s.scale == RadialScale::Log) {
        for (float decade : decadeTicks(lobes.outer * 10.0f, kLogDecades + 1.0f)) {
            for (int k = 2; k <= 9; ++k) {
                float r = plotRadius(decade * 0.1f * static_cast<float>(k), lobes.outer, s.scale);
                if (r > 0.0f && r < 1.0f) {
                    ImVec2 m = b.at(0, r);
                    dl->AddLine(m, ImVec2(m.x + (k == 5 ? 0.6f : 0.4f) * p.font, m.y), kAxis, p.thin);
                }
            }
        }
    }
    dl->AddLine(at(-90, 0), at(90, 0), kAxis, p.stroke);
    dl->AddLine(b.lo, b.at(0, 1), kAxis, p.stroke);
    dl->AddLine(at(lobes.incident, 0), at(lobes.incident, 1), kMirror, p.thin); // the mirror angle
    dl->AddLine(at(s.viewerDeg, 0), at(s.viewerDeg, 1), kViewer, p.thin);
    lobeCurves(dl, p, lobes, s, {false, {b.lo.x, b.lo.y}, {b.hi.x - b.lo.x, b.hi.y - b.lo.y}});
}

// The probe's vectors in its own plane of incidence: N up, L to the left.
void probeArrows(ImDrawList* dl, const Pens& p, const Frame& f, const ProbeResult& probe, BrdfModel brdf) {
    const ProbeLight& pl = probe.lights.front();
    glm::vec3 side = pl.L - pl.NoL * probe.N;
    glm::vec3 ex = glm::length(side) > 1e-5f ? -glm::normalize(side) : glm::vec3(1, 0, 0);
    auto project = [&](const glm::vec3& v) { return glm::vec2(glm::dot(v, ex), glm::dot(v, probe.N)); };
    arrow(dl, p, f, project(pl.L), 0.6f, kProbe, "probe L", p.thin * 1.5f);
    arrow(dl, p, f, project(probe.V), 0.6f, kProbe, "probe V", p.thin * 1.5f);
    bool phong = brdf == BrdfModel::Phong;
    arrow(dl, p, f, project(phong ? pl.R : pl.H), 0.6f, kProbe, phong ? "probe R" : "probe H", p.thin * 1.5f);
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

void polarLobes(const Canvas& c, const Pens& p, const Lobes& lobes, Preset& a, PlotSettings& s, const ProbeResult* probe) {
    ImDrawList* dl = c.dl;
    Frame f = polarFrame(c, p);
    polarGrid(dl, p, f, lobes.outer, s.scale);
    lobeCurves(dl, p, lobes, s, f.placement());
    glm::vec2 L = dirFromDeg(lobes.incident, -1.0f), R = dirFromDeg(lobes.incident, 1.0f), V = dirFromDeg(s.viewerDeg, 1.0f);
    arrow(dl, p, f, {0, 1}, 0.8f, kAxis, "N", p.stroke);
    arrow(dl, p, f, L, 0.92f, kLight, "L", p.bold);
    arrow(dl, p, f, R, 0.8f, kMirror, "R", p.stroke);
    arrow(dl, p, f, V, 0.88f, kViewer, "V", p.stroke);
    if (a.brdf != BrdfModel::Phong) {
        glm::vec3 H = glsl::halfVector(glm::vec3(L, 0.0f), glm::vec3(V, 0.0f)); // the model's own H
        arrow(dl, p, f, glm::vec2(H), 0.65f, kHalf, "H", p.stroke);
    }
    if (probe && !probe->lights.empty()) {
        probeArrows(dl, p, f, *probe, a.brdf);
    }
    dragArrows(f, L, V, a, s);
}

// Lobe plot rows: readout strip, canvas, the incident-angle and V sliders.
PlotNeeds lobeNeeds(const Lobes& lobes, const PlotSettings& s, const Pens& p, float width) {
    PlotNeeds n;
    n.fixed = lobes.readout.height(p, width) + 2.0f * p.gap + p.frame;
    n.minWidth = 14.0f * p.font;
    n.minCanvas = 7.0f * p.line;
    n.maxCanvas = s.cartesian ? width * 0.55f : polarMaxHeight(p, width);
    n.maxCanvas = std::max(n.maxCanvas, n.minCanvas);
    return n;
}

void lobePlot(const PlotBox& box, ImVec2 origin, const Pens& p, bool cramped, const Lobes& lobes, Preset& a,
              PlotSettings& s, const ProbeResult* probe) {
    const Block block = placeBlock(box, origin, p, lobes.readout, "plot.lobe.readout", cramped, true,
                                   lobeNeeds(lobes, s, p, box.w).minCanvas, [&](float w) {
        return s.cartesian ? w * 0.55f : polarMaxHeight(p, w);
    });
    const Canvas canvas = beginCanvas("lobe", "plot.lobe", block.canvasW, block.canvasH);
    if (canvas.shown()) {
        if (s.cartesian) {
            cartesianLobes(canvas, p, lobes, s);
        } else {
            polarLobes(canvas, p, lobes, a, s, probe);
        }
    }
    if (!block.controlsFit) {
        return;
    }
    ImGui::SetCursorScreenPos(block.controls);
    const limits::Range& incident = limits::kPlotIncidentDeg;
    float labels = ImGui::CalcTextSize("incident").x + ImGui::CalcTextSize("V").x + 2.0f * p.inner + p.gapX;
    float field = std::max((box.w - labels) * 0.5f, p.font);
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
    n.maxCanvas = std::max(polarMaxHeight(p, width), n.minCanvas);
    return n;
}

// A colour's darker shade as a field background, white text on it readable.
ImVec4 shade(ImU32 color, float k) {
    ImVec4 c = ImGui::ColorConvertU32ToFloat4(color);
    return ImVec4(c.x * k, c.y * k, c.z * k, 1.0f);
}

void overlayPlot(const PlotBox& box, ImVec2 origin, const Pens& p, bool cramped, const Overlay& o, PlotSettings& s) {
    const Block block = placeBlock(box, origin, p, o.readout, "plot.overlay.readout", cramped, true,
                                   overlayNeeds(o, p, box.w).minCanvas, [&](float w) { return polarMaxHeight(p, w); });
    const Canvas canvas = beginCanvas("overlay", "plot.overlay", block.canvasW, block.canvasH);
    if (canvas.shown()) {
        Frame f = polarFrame(canvas, p);
        polarGrid(canvas.dl, p, f, o.outer, s.scale);
        for (std::size_t i = 0; i < 3; ++i) {
            const PlotCache::Points curve = s.cache.lobe(o.inputs[i], PlotComponent::Total, o.outer, s.scale, f.placement());
            polyline(canvas.dl, *curve, kOverlay[i], p.stroke);
        }
        for (std::size_t i = 0; i < 3; ++i) {
            float deg = s.overlayDeg[static_cast<int>(i)];
            arrow(canvas.dl, p, f, dirFromDeg(deg, -1.0f), 0.9f, kOverlay[i], nullptr, p.stroke); // the fields name them
        }
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
        ImGui::PushStyleColor(ImGuiCol_FrameBg, shade(kOverlay[i], 0.45f));
        ImGui::PushStyleColor(ImGuiCol_FrameBgHovered, shade(kOverlay[i], 0.6f));
        ImGui::PushStyleColor(ImGuiCol_FrameBgActive, shade(kOverlay[i], 0.75f));
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

bool lightChooser(const Preset& a) { return a.lights.size() > 1; }

PlotNeeds attenuationNeeds(const Attenuation& t, const Preset& a, const Pens& p, float width) {
    PlotNeeds n;
    n.fixed = t.readout.height(p, width) + p.gap + (lightChooser(a) ? p.frame + p.gap : 0.0f);
    n.minWidth = 12.0f * p.font;
    if (t.light) {
        n.minCanvas = 5.0f * p.line;
        n.maxCanvas = std::max(width * 0.42f, n.minCanvas);
    }
    return n;
}

void attenuationCanvas(const Canvas& c, const Pens& p, const Attenuation& t, PlotCache& cache) {
    ImDrawList* dl = c.dl;
    Box b{ImVec2(c.corner.x + textSize("0.5").x + 2.0f * p.pad, c.corner.y + c.height - p.line - p.pad),
          ImVec2(c.corner.x + c.width - textSize("10").x * 0.5f - p.pad, c.corner.y + p.line * 0.6f)};
    if (b.hi.x - b.lo.x < p.font || b.lo.y - b.hi.y < p.font) {
        return;
    }
    float maxD = t.maxD;
    auto at = [&](float d, float att) { return b.at(d / maxD, att); };
    yAxis(dl, p, b, {{0.5f, 0.5f}, {1.0f, 1.0f}}, true);
    int count = std::clamp(static_cast<int>((b.hi.x - b.lo.x) / (3.5f * p.font)), 2, 10);
    for (float d : linearTicks(maxD, count)) {
        dl->AddLine(at(d, 0), at(d, 1), kGrid, p.thin);
        centredText(dl, ImVec2(at(d, 0).x, b.lo.y + p.pad * 0.5f + p.line * 0.5f), kLabel, tickText(d));
    }
    dl->AddLine(at(0, 0), at(maxD, 0), kAxis, p.stroke);
    dl->AddLine(at(0, 0), at(0, 1), kAxis, p.stroke);
    if (t.light->type == LightType::Directional) {
        const ImVec2 flat[2] = {at(0, 1), at(maxD, 1)};
        dl->AddPolyline(flat, 2, kTotal, 0, p.bold);
    } else {
        const CurvePlacement place{false, {b.lo.x, b.lo.y}, {b.hi.x - b.lo.x, b.hi.y - b.lo.y}};
        polyline(dl, *cache.attenuation(t.light->attenuation, maxD, place), kTotal, p.bold);
    }
    if (t.light->type != LightType::Directional) {
        ImVec2 m = at(t.distance, t.att);
        dl->AddLine(at(t.distance, 0), m, kSpecular, p.thin);
        dl->AddCircleFilled(m, 5.0f * p.s, kSpecular);
    }
    // The axis's name at its end, above the line.
    ImVec2 end = at(maxD, 0);
    ImVec2 size = textSize("d");
    dl->AddText(ImVec2(end.x - size.x, end.y - size.y - p.pad * 0.5f), kLabel, "d");
}

void attenuationPlot(const PlotBox& box, ImVec2 origin, const Pens& p, bool cramped, const Attenuation& t,
                     const Preset& a, PlotSettings& s) {
    const Block block = placeBlock(box, origin, p, t.readout, "plot.attenuation.readout", cramped, lightChooser(a),
                                   attenuationNeeds(t, a, p, box.w).minCanvas, [&](float w) { return t.light ? w * 0.42f : 0.0f; });
    if (t.light) {
        const Canvas canvas = beginCanvas("attenuation", "plot.attenuation", block.canvasW, block.canvasH);
        if (canvas.shown()) {
            attenuationCanvas(canvas, p, t, s.cache);
        }
    }
    if (lightChooser(a) && block.controlsFit) {
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

// Keeps the next item on this line when it fits the window, else starts a new line.
void sameLineIfFits(float nextWidth) {
    float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + nextWidth <= right) {
        ImGui::SameLine();
    }
}

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
        if (labels == brief && ImGui::IsItemHovered()) {
            ImGui::SetTooltip("%s", text);
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
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("Off: the outer ring is the largest total in the plot, and follows every change.\n"
                          "On: the outer ring keeps its value, so a change (another BRDF, a shininess)\n"
                          "shows its real size; lobes beyond it are cut at the ring.");
    }
}

// The plane of incidence: the lobe, the overlaid angles and Att(d).
void planeView(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe) {
    options(s);
    const Pens p = pens();
    const Lobes lobes = lobeData(a, b, s, p);
    const Overlay overlay = overlayData(a, s, p);
    const Attenuation attenuation = attenuationData(a, s, p);

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

// The views in the selector's order: a further view is its PlotView and one line here.
struct ViewEntry {
    PlotView view;
    const char* name;
    const char* mark;
    void (*draw)(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe);
};
const ViewEntry kViews[] = {
    {PlotView::Plane, "Plane", "plot.view.plane", planeView},
    {PlotView::Lobe3d, "3D lobe", "plot.view.lobe3d", [](Preset& a, const Preset* b, PlotSettings& s, const ProbeResult*) { lobe3dPanel(a, b, s); }},
    {PlotView::Energy, "Energy", "plot.view.energy", [](Preset& a, const Preset* b, PlotSettings& s, const ProbeResult*) { energyPanel(a, b, s); }},
};

} // namespace

void plotsPanel(Preset& a, const Preset* b, PlotSettings& s, const ProbeResult* probe) {
    // The selector's row as low as the text allows (a row less for the views below it): thinner
    // tabs, the views' own widgets at the usual padding.
    const ImVec2 padding = ImGui::GetStyle().FramePadding;
    const ImVec2 thin(padding.x, std::floor(padding.y * 0.35f));
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, thin);
    if (!ImGui::BeginTabBar("plots.view")) {
        ImGui::PopStyleVar();
        return;
    }
    // A view chosen from outside (a test, the first frame) is selected until its tab opens; after
    // that the tabs decide.
    const bool pending = s.shownView != static_cast<int>(s.view);
    for (const ViewEntry& v : kViews) {
        const bool select = pending && s.view == v.view;
        const bool open = ImGui::BeginTabItem(v.name, nullptr, select ? ImGuiTabItemFlags_SetSelected : 0);
        mark(v.mark);
        if (open) {
            ImGui::PopStyleVar();
            if (!pending) {
                s.view = v.view;
            }
            s.shownView = static_cast<int>(v.view);
            v.draw(a, b, s, probe);
            ImGui::EndTabItem();
            ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, thin);
        }
    }
    ImGui::EndTabBar();
    ImGui::PopStyleVar();
}

} // namespace lab::ui
