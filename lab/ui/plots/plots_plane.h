// plots_plane.h — the plots window's Plane view: the plane of incidence's three plots.
//
//   * the lobe: the reflected intensity against the outgoing angle (polar, or Cartesian), its
//     diffuse, specular and total parts and B's total, with N, L, R, V and H; L and V dragged by
//     their tips, the readout at V, the outer ring's value and the albedo at the incident angle;
//   * the lobes at three incident angles overlaid, each in its colour;
//   * Att(d) of a light, with the model's distance marked.
// One frame: sample the lighting model (core/plots/plot_data.h), or find the samples and curves
// of an earlier frame with the same inputs (ui/plots/plot_cache.h); write the readouts as tokens and
// measure them, ask core/plots/plot_layout.h where each plot goes in the room left in the window,
// then draw each plot's block there — readout strip, canvas, controls — with the cursor set
// explicitly, so nothing reaches past the region and the window never scrolls.
#pragma once

#include "ui/plots/plot_settings.h"

namespace lab::ui {

// Draws the Plane view into the current window's remaining content region; at the probed point
// `point` when given (plots at the probe, ui/plots/plots.h).
void planeView(Preset& a, const Preset* b, PlotSettings& settings, const ProbeResult* probe, const ProbeLobe* point);

} // namespace lab::ui
