// probe_lobe.h — the plots' inputs at a probed point of the model ("plots at the probe").
//
// The plots (core/plots/plot_data.h) show a directional light in a plane of incidence of their
// own: N = +y, L = (−sin θi, cos θi, 0), V = (sin θo, cos θo, 0) on the R side for θo > 0. At a
// point of the model the pixel probe (core/lighting/probe.h) knows the real N, L and V. This file
// puts them in that frame: θi is the angle between N and L; the light that arrives is the light's
// diffuse and specular colours × Att(d) × spot factor (lab::glsl's own distanceAttenuation and
// spotTerm, as the shaders compute them); V is written in the plot's frame — x along the plane of
// incidence away from L (towards R), y along N, z across the plane — with its angle from the plane
// of incidence. The lobe made from these inputs reads, at V, what the model reflects there:
// intensityAt(probeLobeInputs(...), viewer) is the luminance of the probe's diffuse and specular
// for that light (tested in tests/probe_lobe_test.cpp).
//
// What it does not do: probe (the caller has a ProbeResult), draw, or change the preset: the
// preset's own plot settings and `lab plot` never see any of it.
#pragma once

#include "core/lighting/probe.h"
#include "core/plots/plot_data.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace lab {

// The plot's frame on the model (world space): the point, N, the x axis (in the plane of
// incidence, away from L) and the z axis (across that plane; x × N).
struct PointFrame {
    glm::vec3 origin{0.0f};
    glm::vec3 N{0.0f, 1.0f, 0.0f}, tangent{1.0f, 0.0f, 0.0f}, across{0.0f, 0.0f, 1.0f};
    bool operator==(const PointFrame&) const = default;
};

struct ProbeLobe {
    int light = 0;             // the light, an index into preset.lights
    float incidentDeg = 0.0f;  // θi, the angle between N and L: 0…180° (over 90°: the light is behind the surface)
    float distance = 0.0f;     // d from the point to the light (0 for a directional light)
    float attenuation = 1.0f;  // Att(d) (1 for a directional light)
    float spot = 1.0f;         // the spot factor (1 but for a spot light)
    glm::vec3 incomingDiffuse{1.0f}, incomingSpecular{1.0f}; // Id·Att·spot and Is·Att·spot: the light that arrives
    glm::vec3 viewer{0.0f, 1.0f, 0.0f}; // V in the plot's frame (unit)
    float viewerDeg = 0.0f;    // θo of V's projection on the plane of incidence, signed as the plot's (−180…180)
    float outOfPlaneDeg = 0.0f; // V's angle from the plane of incidence, 0…90°
    PointFrame world;          // where the plot's frame lies on the model
    bool operator==(const ProbeLobe&) const = default;
};

// The plots' geometry at the probed point for preset.lights[light]. `preset` is the scene the
// probe was made from (its camera and lights where they were shown). None when that light does
// not exist or is switched off.
std::optional<ProbeLobe> probeLobe(const ProbeResult& probe, const Preset& preset, int light);

// The incident angle the plots draw for the point: θi, at most 90° (a light behind the surface
// lies along it and lights nothing).
float plottedIncidentDeg(const ProbeLobe& at);

// The plots' inputs at the point: preset's material, BRDF and term switches (lobeInputs), the
// plotted θi and the light that arrives there.
LobeInputs probeLobeInputs(const Preset& preset, const ProbeLobe& at);

// The lobe at the point as a wireframe, in the plot's frame: `planes` curves through N (the first
// the plane of incidence, the others turned about N by 180°/planes each), θo from −90° to 90° in
// 3° steps, the radius the total intensity; scaled so that the largest radius is 1 (all of them 0
// where nothing is reflected).
std::vector<std::vector<glm::vec3>> lobeWireframe(const LobeInputs& inputs, int planes);

} // namespace lab
