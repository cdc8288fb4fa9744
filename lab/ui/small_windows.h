// small_windows.h — the lab's smaller windows: pixel probe and help overlay (the shader editor has its
// own file, shader_editor.h).
// ImGui only; what they ask for comes back as requests (ui/actions.h) for the app.
#pragma once

#include "core/lighting/probe.h"
#include "ui/actions.h"

#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

// The shortcuts, from the command table (ui/actions.h helpRows()).
void helpWindow(bool& open);

// Opens at `position` (screen units) the first time.
void probeWindow(const ProbeResult& probe, const Preset& preset, bool& open, float x, float y);

} // namespace lab::ui
