// plots_probe.h — the Plane view's words and controls for plots at the probe (ui/plots/plots.h).
//
// At a probed point the lobe plot says where it is: which light, θi, what of that light arrives
// (Att and the spot factor), where V lies — in words how far out of the plane of incidence, when
// it is — and the intensities at that real V (core/plots/lobe3d.h's intensityAt, not the nearest
// whole-degree sample). Its sliders show the point's θi and V, greyed: they are the point's, and
// the preset's own angle is not touched. What it does not do: decide the layout or draw curves
// (plots_plane.cpp does).
#pragma once

#include "core/plots/probe_lobe.h"
#include "ui/plots/plot_kit.h"

namespace lab::ui {

// The lobe readout's first line(s) at the point: A's (and B's, when given) intensities at V.
void probeLobeTokens(plotkit::Readout& r, const ProbeLobe& at, const LobeInputs& inA, const LobeInputs* inB);

// Att(d)'s readout at the point: the light, d and Att(d), and the spot factor.
void probeAttenuationTokens(plotkit::Readout& r, const ProbeLobe& at, bool directional);

// The lobe plot's row of controls at the point: θi and V as greyed sliders, `field` wide each.
void probeSliders(const ProbeLobe& at, float field);

} // namespace lab::ui
