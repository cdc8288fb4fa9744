// figure_export.h — the lab's "Export figures": the four plot figures (core/plots/figures.h) with the
// GUI's current settings (the preset's incident angle, the overlay's angles, the radial scale, the
// attenuation's light, compare set B), each as SVG, PNG (at the panel's scale, 2 for a projector
// unless chosen otherwise) and CSV, in the lab's theme (core/plots/theme.h).
// Returns the files; the workspace writes them beside the screenshots or hands them to the
// browser as downloads (Workspace::saveFiles).
#pragma once

#include "app/workspace.h"
#include "core/plots/theme.h"
#include "ui/plots/plots.h"

#include <vector>

namespace lab {

// Files named "<figure>.svg", ".png" and ".csv"; the attenuation only when the preset has lights.
std::vector<Download> exportFigures(const Preset& a, const Preset* b, const ui::PlotSettings& settings, float pngScale,
                                    Theme theme);

} // namespace lab
