// plots.h — the live plots beside the model, drawn every frame from the lighting functions (the
// samples and curves kept from frame to frame while their inputs stay the same: ui/plots/plot_cache.h).
//
//   * the reflection lobe in the plane of incidence for the preset's incident angle: diffuse,
//     specular and total, with N, L, R, V (and H for Blinn-Phong and Cook-Torrance) as arrows;
//     drag L to change the incident angle, drag V to read the intensities in that direction;
//   * the albedo of each term at that angle, under the lobe's readout (core/plots/energy.h; B's total too);
//   * the lobes for several incident angles overlaid (the classic 60°/25°/10° figure);
//   * linear or logarithmic radial scale, polar or Cartesian, with the ring values, angle ticks
//     and decade marks written on the plot; the scale can be locked;
//   * the attenuation curve Att(d) of a light, with a marker at its distance to the model.
// With plots at the probe (`point` given: core/plots/probe_lobe.h) the lobe plot, the 3D lobe and
// Att(d) show the probed point instead: its θi, the light that arrives there, its real V (how far
// out of the plane of incidence, in words) and its light's distance; L, V and their sliders are
// then the point's, not draggable, and the preset's plot settings stay as they are.
// The numbers come from core/plots/plot_data.h (the same code as `lab plot`), where each plot goes and what
// its rings are from core/plots/plot_layout.h; this file measures text and draws.
//
// What it promises the window it draws in: everything fits the content region that is left
// when it is called, whatever its size and the UI scale — side by side in a wide band, stacked in
// a tall column, or one plot at a time in tabs when there is no room for all three. It never
// makes the window scroll. Readouts have strips of their own above the canvases. Lines, arrows
// and text offsets scale with the font (ImGui::GetFontSize() / 13).
#pragma once

#include "core/lighting/probe.h"
#include "core/plots/probe_lobe.h"
#include "ui/plots/plot_settings.h"

namespace lab::ui {

// Draws the view selector and the chosen view into the current ImGui window's remaining content
// region: "Plane" (the plots below), "3D lobe" (ui/plots/plots_3d.h), "Energy" (ui/plots/plots_energy.h)
// or "Slice" (ui/plots/plots_slice.h, drawn in settings.palette).
// Dragging L edits a.plotIncidentDeg (part of the preset, so it is undoable and saved). `b` is the
// compare set, overlaid when given. The probe's vectors are drawn only when `probe` is given;
// `point`, the probed point's lobe, turns plots at the probe on.
void plotsPanel(Preset& a, const Preset* b, PlotSettings& settings, const ProbeResult* probe,
                const ProbeLobe* point = nullptr);

} // namespace lab::ui
