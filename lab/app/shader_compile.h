// shader_compile.h — the shader editor's Compile and Revert: its three sources (or the built-in
// ones) into the renderer. A source that does not compile leaves the running shaders as they
// were; the editor's log says what the compiler said, or what is running now. Needs the GL context.
#pragma once

#include "render/renderer.h"
#include "ui/tools/shader_editor.h"

namespace lab {

// `builtin`: the built-in sources, which the editor then shows again.
void compileShaders(Renderer& renderer, ui::ShaderEditorState& shaderEditor, bool builtin);

} // namespace lab
