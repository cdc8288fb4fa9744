// plot_settings.h — what the plots window keeps between frames: the tab shown, the radial scale,
// the dragged vectors, the overlaid angles, the plot cache, the 3D lobe's and the slice's state. Every
// plot tab (plots_plane, plots_3d, plots_energy, plots_slice) and the plot kit read it; plots.h draws the window.
#pragma once

#include "core/plots/plot_data.h"
#include "ui/plots/plot_cache.h"
#include "ui/plots/plots_3d.h"
#include "ui/plots/plots_slice.h"

#include <array>
#include <optional>
#include <string_view>

namespace lab::ui {

// The plots window's views, one tab each in this order (plots.cpp's table names and draws them; a
// preset's display.plots names them as core/scene/preset.h's kPlotTabNames, in the same order).
enum class PlotTab { Plane, Lobe3d, Energy, Slice };
std::optional<PlotTab> plotTabNamed(std::string_view name);

struct PlotSettings {
    PlotTab view = PlotTab::Plane;
    int shownView = -1; // the view whose tab was open last frame (-1: none yet)
    RadialScale scale = RadialScale::Linear;
    bool cartesian = false;
    bool lockScale = false;                    // the outer circle stays where it was when locked
    float lobeScale = 0.0f, overlayScale = 0.0f; // the outer circles' intensities (held while locked)
    float viewerDeg = 20.0f;                   // V in the lobe plot
    glm::vec3 overlayDeg{60.0f, 25.0f, 10.0f}; // the overlaid incident angles
    std::array<ChangeWatch, 3> overlayChanges; // the overlay draws coarse plots while its lobes change
    // Those coarse plots lag like the albedo while the material changes; a change of the overlay's own
    // angles is drawn at once.
    LaggingDraft<std::array<LobeInputs, 3>> overlayDraft;
    int attenuationLight = 0;
    int dragging = 0; // 0 none, 1 L, 2 V
    PlotCache cache;  // samples and curves of earlier frames, found again by their inputs
    Lobe3dState lobe3d; // the 3D lobe's camera, component and kept meshes (ui/plots/plots_3d.h)
    SliceState slice;   // the slice's component, compare choice and kept images (ui/plots/plots_slice.h)
    // The value views' palette (DisplaySettings::palette), which the slice is drawn in: the screen
    // sets it each frame from the view's settings; the plots keep no palette of their own.
    ValuePalette palette = ValuePalette::Viridis;
};

} // namespace lab::ui
