// small_windows.h — the lab's smaller windows: pixel probe and help overlay (the shader editor has its
// own file, shader_editor.h).
// ImGui only; what they ask for comes back as requests (ui/actions.h) for the app.
#pragma once

#include "core/lighting/probe.h"
#include "core/scene/view_mode.h"
#include "ui/actions.h"

#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

// The speaker's notes (S): where the lecture is, what to say, what comes next and the time — a
// strip over the model's lower left for a single screen (the room sees it too: keep it short).
struct NotesModel {
    std::string position; // "Slide 5 of 12: Full Phong"; "05-full-phong.json" off a deck
    std::string notes;    // the slide's notes, else the preset's own; empty: none
    std::string next;     // the next slide's title; empty at the last
    std::string clock;    // "14:05"
};
void notesWindow(const NotesModel& notes, bool& open, float x, float y, float width);

// The shortcuts, from the command table (ui/actions.h helpRows()).
void helpWindow(bool& open);

// Opens at `position` (screen units) the first time. Its "plots at this point" box switches
// view.plotsAtProbe, and with more than one light chooses view.light, the light they use.
void probeWindow(const ProbeResult& probe, const Preset& preset, DisplaySettings& view, bool& open, float x, float y);

} // namespace lab::ui
