// view_mode.h — views of the model that show one part of the lighting.
//
// A view mode changes what is drawn, never the preset: viewed() returns a copy with the other
// terms switched off. Shared by the workspace (which holds the mode), the UI (which picks it)
// and the renderer's caller.
#pragma once

#include "core/scene/preset.h"

#include <array>

namespace lab {

enum class ViewMode { Lit, Emissive, Ambient, Diffuse, Specular, Normals };

inline constexpr std::array kViewModes{ViewMode::Lit,     ViewMode::Emissive, ViewMode::Ambient,
                                       ViewMode::Diffuse, ViewMode::Specular, ViewMode::Normals};

// How the scene is shown: the per-term view, and compare mode (set B beside set A).
struct ViewSettings {
    ViewMode mode = ViewMode::Lit;
    bool compare = false;
    bool editingB = false; // the panel edits B
};

// "Lit (all terms)", "Diffuse only", ...
const char* toString(ViewMode mode);

// The preset as `mode` shows it: only that term switched on (if the preset has it on).
Preset viewed(const Preset& preset, ViewMode mode);

} // namespace lab
