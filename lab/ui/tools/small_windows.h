// small_windows.h — the lab's smaller windows: pixel probe and help overlay (the shader editor has its
// own file, shader_editor.h; the speaker's notes are notes.h's).
// ImGui only; what they ask for comes back as requests (ui/actions.h) for the app.
#pragma once

#include "core/lighting/probe.h"
#include "core/scene/view_mode.h"
#include "ui/actions.h"
#include "ui/tools/notes.h"

#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

// The shortcuts, from the command table (ui/actions.h helpRows()).
void helpWindow(bool& open);

// Opens at `position` (screen units) the first time. Its "plots at this point" box switches
// view.plotsAtProbe, and with more than one light chooses view.light, the light they use.
void probeWindow(const ProbeResult& probe, const Preset& preset, DisplaySettings& view, bool& open, float x, float y);

} // namespace lab::ui
