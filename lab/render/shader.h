// shader.h — assembling and compiling the lab's GLSL.
//
// The GLSL files in shaders/ are embedded in the program at build time (shader_sources.h).
// A program is assembled as: version line, precision, defines, lighting_api.glsl,
// lighting.glsl, view.glsl (the value views' palettes), then the stage's own body, each part
// after a `#line` so compile errors name the file and line they come from ("lighting.glsl:12:
// ..."). lighting_api.glsl (the constants, structs and prototypes) and view.glsl are always the
// embedded ones; lighting.glsl and the stage bodies are strings the caller owns, so the GUI's
// shader editor can compile edited text the same way. Text that is not ASCII is refused before anything is compiled: GLSL ES and WebGL
// reject it, and the drivers' messages about it are cryptic. Programs that are not lit (the
// overlay's lines) get the version line and the precision only (buildPlainProgram).
#pragma once

#include "core/io/diagnostics.h"
#include "render/gl.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

// The embedded text of a file in shaders/, e.g. "lit.frag"; empty if there is none.
std::string_view shaderSource(std::string_view name);

// The editable parts of the lit shaders, each named after the file it replaces.
struct StageSources {
    std::string vertex;   // body of lit.vert (or an edited version)
    std::string fragment; // body of lit.frag
    std::string lighting; // lighting.glsl: the definitions of lighting_api.glsl's functions
};

StageSources builtinStageSources();

// One diagnostic per line of `sources` that holds a character outside ASCII, at most `maxLines`
// in all: "lighting.glsl:12: column 5: non-ASCII character U+00E9 ...". True if there is none.
bool checkAscii(const StageSources& sources, Diagnostics& diagnostics, int maxLines = 8);

// A driver's info log as diagnostics, one per line, with the first "0:12" (Mesa, ANGLE) or
// "0(12)" (NVIDIA) of each rewritten as the file and line it is in: "lighting.glsl:12" for a
// line of the assembled source inside lighting.glsl, "lit.frag:12" (`bodyName`) in the body.
// A driver quotes the source: each line is cut at 1000 bytes (core/io/safe_text.h shortened), and
// after kMaxLogLines lines one more says how many were left out, so that a 1 MB shader's log does
// not reach the editor, the page and the terminal whole.
inline constexpr std::size_t kMaxLogLines = 50;
void readableLog(std::string_view log, std::string_view bodyName, Diagnostics& out);

// Compiles and links; on failure adds one diagnostic per log line, with file names restored
// and a message both stages repeat (an error in lighting.glsl) given once.
std::optional<GLuint> buildProgram(const StageSources& sources, const std::vector<std::string>& defines,
                                   Diagnostics& diagnostics);

// A program of two embedded files of shaders/ that need no lighting (the overlay's lines:
// wireframe.vert, wireframe.frag): each body after the version line and the precision only, compiled
// and linked as buildProgram does, the log naming those files.
std::optional<GLuint> buildPlainProgram(std::string_view vertexFile, std::string_view fragmentFile,
                                        Diagnostics& diagnostics);

} // namespace lab
