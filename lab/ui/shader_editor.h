// shader_editor.h — the shader editor: the stage bodies of the lit shaders, editable, compiled on
// request; the log of the last compile. ImGui only: compiling is the app's (the renderer's).
#pragma once

#include "core/commands.h"

#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

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
