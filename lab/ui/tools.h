// tools.h — the lab's smaller windows: pixel probe, shader editor, help overlay.
// ImGui only; what they ask for comes back as actions for the app.
#pragma once

#include "core/probe.h"

#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

// One keyboard shortcut, as listed by the help overlay and the README.
struct Shortcut {
    const char* keys;
    const char* action;
};
const std::vector<Shortcut>& shortcuts();

void helpWindow(bool& open);

// Opens at `position` (screen units) the first time.
void probeWindow(const ProbeResult& probe, const Preset& preset, bool& open, float x, float y);

struct ShaderEditorState {
    bool open = false;
    std::string vertex, fragment;  // the text being edited
    std::vector<std::string> log;  // the last compile's messages
    bool lastCompileFailed = false;
    bool customActive = false;     // edited shaders are running
};

struct ShaderEditorActions {
    bool compile = false;
    bool revert = false;
};

void shaderEditorWindow(ShaderEditorState& state, ShaderEditorActions& actions, std::string_view lightingSource);

} // namespace lab::ui
