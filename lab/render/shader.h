// shader.h — assembling and compiling the lab's GLSL.
//
// The GLSL files in shaders/ are embedded in the program at build time (shader_sources.h).
// A program is assembled as: version line, precision, defines, lighting_api.glsl,
// lighting.glsl, then the stage's own body, each part after a `#line 1 N` so compile errors
// name the file and line they come from ("lit.frag:12: ..."). The stage bodies are strings the
// caller owns, so the GUI's shader editor can compile edited text the same way.
#pragma once

#include "core/diagnostics.h"
#include "render/gl.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

// The embedded text of a file in shaders/, e.g. "lit.frag"; empty if there is none.
std::string_view shaderSource(std::string_view name);

struct StageSources {
    std::string vertex;   // body of lit.vert (or an edited version)
    std::string fragment; // body of lit.frag
};

StageSources builtinStageSources();

// Compiles and links; on failure adds one diagnostic per log line, with file names restored.
std::optional<GLuint> buildProgram(const StageSources& sources, const std::vector<std::string>& defines,
                                   Diagnostics& diagnostics);

} // namespace lab
