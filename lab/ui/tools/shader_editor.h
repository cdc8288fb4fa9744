// shader_editor.h — the shader editor: the stage bodies of the lit shaders and lighting.glsl,
// editable, with line numbers, compiled on request; the log of the last compile, whose
// "file:line" places are marked in the files' tabs. ImGui only: compiling is the app's (the
// renderer's); lighting_api.glsl (prototypes, structs, constants) is not edited here.
#pragma once

#include "ui/actions.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

struct ShaderEditorState {
    bool open = false;
    std::string vertex, fragment, lighting; // the text being edited: lit.vert, lit.frag, lighting.glsl
    std::vector<std::string> log;           // the last compile's messages
    bool lastCompileFailed = false;
    bool customActive = false;   // edited shaders are running
    bool customLighting = false; // the running lighting.glsl is not the built-in one

    // The editor's own memory between frames.
    std::string jumpFile;        // a clicked log line: select this file's tab ...
    int jumpLine = 0;            // ... and scroll to this line (1-based)
    int cursorLine[3] = {0, 0, 0}; // the text cursor's line per tab, to follow it when it moves
    std::vector<std::string> shownLog; // the log as last drawn: a new failure jumps to its first place
};

// A place a compiler log line names: "lighting.glsl:12(5): error: ..." is {"lighting.glsl", 12}.
struct LogPlace {
    std::string file;
    int line = 0;
    bool operator==(const LogPlace&) const = default;
};

// The first "name.ext:N" in `line` where name.ext is one of the shader files; none if there is
// none. Pure, for the tests.
std::optional<LogPlace> logPlace(std::string_view line);
// The lines of `file` (1-based, sorted, each once) that the log names.
std::vector<int> linesNamed(const std::vector<std::string>& log, std::string_view file);

// Compile and "Revert to built-in" come back as CompileShaders and RevertShaders requests.
// `lightingSource` is the built-in lighting.glsl.
void shaderEditorWindow(ShaderEditorState& state, std::vector<Request>& requests, std::string_view lightingSource);

} // namespace lab::ui
