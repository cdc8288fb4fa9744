// point_lobe.h — "plots at the probe": a small lobe drawn on the model at the probed point.
//
// The reflected intensity at the point (core/plots/probe_lobe.h's wireframe: the plane of
// incidence bold, three more planes through N thin), standing on the point oriented by its N and
// L, with N, L and a ring in the surface's tangent plane — the plots' picture put where it
// belongs. A fixed share of the view in size, whatever the zoom, so it stays legible and never
// covers the model; its shape, not its size, tells the intensity (the plots give the numbers).
// Projected with the view's own matrices and drawn on `dl` clipped to the model's viewport, in the
// plots' colours. What it does not do: compute anything the plots do not (the lobe comes from the
// same inputs), or take input.
#pragma once

#include "core/plots/probe_lobe.h"
#include "ui/layout.h"

struct ImDrawList;

namespace lab::ui {

// The lobe of `at` on `scene` (set A: its material and camera) in the view rectangle `r`.
void pointLobe(const Preset& scene, const ProbeLobe& at, const Rect& r, ImDrawList* dl);

} // namespace lab::ui
