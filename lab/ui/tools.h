// tools.h — the lab's smaller windows: pixel probe, shader editor, help overlay.
// ImGui only; what they ask for comes back as requests (core/commands.h) for the app.
#pragma once

#include "core/commands.h"
#include "core/probe.h"

#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

// The shortcuts, from the command table (core/commands.h helpRows()).
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

// Compile and "Revert to built-in" come back as CompileShaders and RevertShaders requests.
void shaderEditorWindow(ShaderEditorState& state, std::vector<Request>& requests, std::string_view lightingSource);

} // namespace lab::ui
