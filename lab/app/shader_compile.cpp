// shader_compile.cpp — the shader editor's sources compiled into the renderer (shader_compile.h).
#include "app/shader_compile.h"

#include "render/shader.h"

namespace lab {

void compileShaders(Renderer& renderer, ui::ShaderEditorState& shaderEditor, bool builtin) {
    StageSources sources = builtin ? builtinStageSources()
                                   : StageSources{shaderEditor.vertex, shaderEditor.fragment, shaderEditor.lighting};
    Diagnostics d;
    shaderEditor.log.clear();
    shaderEditor.lastCompileFailed = !renderer.setStageSources(sources, d);
    if (shaderEditor.lastCompileFailed) {
        shaderEditor.log.push_back("Compile failed; the previous shaders keep running:");
        for (const Diagnostic& x : d) {
            shaderEditor.log.push_back(x.str());
        }
        return;
    }
    shaderEditor.customActive = !builtin;
    // The plots and the probe evaluate the C++ build of the built-in lighting.glsl.
    shaderEditor.customLighting = sources.lighting != shaderSource("lighting.glsl");
    shaderEditor.log.push_back(builtin ? "Built-in shaders restored." : "Compiled: the edited shaders are running.");
    if (builtin) {
        shaderEditor.vertex = sources.vertex;
        shaderEditor.fragment = sources.fragment;
        shaderEditor.lighting = sources.lighting;
    }
}

} // namespace lab
