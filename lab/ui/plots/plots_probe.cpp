// plots_probe.cpp — the readouts and greyed sliders of plots at the probe.
#include "ui/plots/plots_probe.h"

#include "core/plots/lobe3d.h"
#include "ui/widgets.h"

#include <imgui.h>

#include <glm/common.hpp>

#include <cmath>
#include <string>

namespace lab::ui {

using namespace plotkit;

namespace {

constexpr const char* kTheta = "\xce\xb8"; // θ

// V's own place, when it is off the plane of incidence by half a degree or more: "V is 23° out of
// the plane of incidence" (the plot shows its projection).
std::string outOfPlane(const ProbeLobe& at) {
    if (at.outOfPlaneDeg < 0.5f) {
        return "";
    }
    return format("V is %.0f%s out of the plane of incidence", double(at.outOfPlaneDeg), kDeg);
}

} // namespace

void probeLobeTokens(Readout& r, const ProbeLobe& at, const LobeInputs& inA, const LobeInputs* inB) {
    r.add(format("at the probe, Light %d:", at.light + 1), Ink::Text);
    if (at.incidentDeg > 90.0f) {
        r.add(format("%si %.0f%s, behind the surface: no light arrives", kTheta, double(at.incidentDeg), kDeg), Ink::Light);
    } else {
        r.add(format("%si %.1f%s", kTheta, double(at.incidentDeg), kDeg), Ink::Light);
        if (at.spot <= 0.0f) {
            r.add("outside the spot's cone: no light arrives", Ink::Light); // rather than "terms switched off?"
        } else {
            r.add(format("arriving: colour %s Att %.3f %s spot %.3f", "\xc3\x97", double(at.attenuation), "\xc3\x97",
                         double(at.spot)), Ink::Light);
        }
    }
    r.lineBreak();
    const std::string words = outOfPlane(at);
    // (+ 0.0: a rounded −0.4° reads +0°, not −0°)
    r.add(format("at V %so %+.0f%s%s", kTheta, std::round(double(at.viewerDeg)) + 0.0, kDeg, words.empty() ? ":" : ","), Ink::Viewer);
    if (!words.empty()) {
        r.add(words + ":", Ink::Viewer);
    }
    const float d = intensityAt(inA, at.viewer, PlotComponent::Diffuse), sp = intensityAt(inA, at.viewer, PlotComponent::Specular);
    r.add(format("diffuse %.3f", double(d)), Ink::Diffuse, true);
    r.add(format("specular %.3f", double(sp)), Ink::Specular, true);
    r.add(format("total %.3f", double(d + sp)), Ink::Total, true);
    if (inB) {
        r.add(format("total B %.3f", double(intensityAt(*inB, at.viewer, PlotComponent::Total))), Ink::Compare, true);
    }
}

void probeAttenuationTokens(Readout& r, const ProbeLobe& at, bool directional) {
    const std::string name = format("Light %d", at.light + 1);
    if (directional) {
        r.add(name + " is directional:", Ink::Text);
        r.add("Att = 1 at every distance", Ink::Specular);
        return;
    }
    r.add(name + ", at the probe:", Ink::Text);
    r.add(format("d = %.2f", double(at.distance)), Ink::Specular);
    r.add(format("Att(d) = %.3f", double(at.attenuation)), Ink::Specular);
    if (at.spot != 1.0f) {
        r.add(format("spot %.3f", double(at.spot)), Ink::Light);
    }
}

void probeSliders(const ProbeLobe& at, float field) {
    // The point's angles, shown where the preset's are, and not to be moved: the mode never edits the preset.
    float incident = at.incidentDeg, viewer = std::round(at.viewerDeg) + 0.0f; // never "-0°"
    const std::string unit = "%.0f" + std::string(kDeg);
    ImGui::BeginDisabled();
    ImGui::SetNextItemWidth(field);
    ImGui::SliderFloat("incident", &incident, 0.0f, 180.0f, unit.c_str());
    mark("plot.incident");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(field);
    ImGui::SliderFloat("V##viewer", &viewer, -180.0f, 180.0f, unit.c_str());
    mark("plot.viewer");
    ImGui::EndDisabled();
    itemTooltip("The probed point's angles (plots at the probe): move the probe's marker to change them.");
}

} // namespace lab::ui
