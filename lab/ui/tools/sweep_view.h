// sweep_view.h — the sweep view: one or two keys of the current preset, their values typed, and
// the grid of renders the app made of them (core/scene/sweep.h), labelled, with Save PNG.
//
// ImGui only. The window edits SweepViewState's choices; the app (app/sweep_image.h) renders
// the grid through its renderer when they or the scene change, and hands back a texture number
// to show with ImGui::Image and the message of a refused value. Save PNG comes back as a
// SaveSweep request. Nothing here when the window is closed.
#pragma once

#include "core/scene/preset.h"
#include "ui/actions.h"

#include <string>
#include <vector>

namespace lab::ui {

inline constexpr int kSweepCellSizes[] = {128, 256, 512};

struct SweepViewState {
    bool open = false;
    // The user's choices: the columns' key and values, the rows' (an empty key: one row), the
    // cells' side in pixels.
    std::string key[2] = {"material.shininess", "material.specular"};
    std::string values[2] = {"10,20,30,50", "0.2,0.5,1"};
    int cellSize = 256;
    bool editing = false; // a key or values field has the keyboard: the grid waits for Enter or a click away
    std::vector<std::string> fromPreset; // the preset's own `sweep` last shown (followPresetSweep)
    // From the app: the grid to show (0: none yet) and its size, or why there is none.
    unsigned texture = 0;
    int textureWidth = 0, textureHeight = 0;
    std::string error;
};

// The "KEY=V1,..." arguments of the current choices, as `lab render --sweep` takes them.
std::vector<std::string> sweepArguments(const SweepViewState& state);

// A preset that carries its own `sweep` (the one `lab check` compares) shows it: when the preset's
// sweep differs from the one last shown, its keys and values become the window's choices. Edits in
// the window stay the window's (they do not change the preset).
void followPresetSweep(SweepViewState& state, const Preset& preset);

// The window (when open; it follows the preset's sweep first, open or not): each key typed, or picked from those offered for `preset` (core/scene/sweep.h
// sweepKeySuggestions, each with a range to start from), and its values typed.
void sweepWindow(SweepViewState& state, const Preset& preset, std::vector<Request>& requests);

} // namespace lab::ui
