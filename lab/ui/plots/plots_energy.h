// plots_energy.h — the plots window's Energy view: the albedo of each term against the incident
// angle.
//
//   * the directional-hemispherical reflectance ρ(θi) of the diffuse and specular terms and their
//     total, as luminance, for θi = 0°…89° (core/plots/energy.h: the same numbers `lab plot --albedo`
//     writes), A's three curves and the compare set's total;
//   * a line at 1, "all the light that arrives", so that a model reflecting more than arrives (a
//     Phong lobe with a large Ks and a small exponent at grazing light) shows at a glance, and so
//     does the energy that a sharper Phong lobe loses;
//   * a marker at the lobe's incident angle with the readout of the numbers there; clicking or
//     dragging in the plot moves it (it is the preset's plotIncidentDeg, as L in the lobe plot).
// The curve is computed once per material, BRDF and term switches (about 90 albedos, kept in
// the plot cache), never per frame. Like the other plots, it fits the region it is given and
// never scrolls.
#pragma once

#include "ui/plots/plot_settings.h"

namespace lab::ui {

// Draws the Energy view into the current window's remaining content region.
void energyPanel(Preset& a, const Preset* b, PlotSettings& settings);

} // namespace lab::ui
