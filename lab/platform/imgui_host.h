// imgui_host.h — the Dear ImGui start-up and frame sequence that every platform shares.
//
// Desktop (glfw_window.cpp), browser (web_window.cpp) and headless (headless_app.cpp) differ only
// in where input, the display size and the loop come from: each passes its platform backend's
// NewFrame as a callback, and everything else — the context, the OpenGL3 renderer backend on
// GLSL ES 3.00, the frame order, fonts re-rasterized at the app's UI scale — is here, once.
// Not here: windows, events, the loop.
#pragma once

#include "app/app.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lab {

// ImGui's built-in font (ProggyClean) at `pixels`: the desktop's font when none of its files loads.
void imguiBuiltinFont(float pixels);
using FallbackFont = void (*)(float pixels);
// The first of `fontFiles` that loads, at `pixels`, into the current ImGui context's atlas, else
// `fallback`'s font (the atlas's texture is the renderer backend's to make).
void loadUiFont(const std::vector<std::string>& fontFiles, FallbackFont fallback, float pixels);

// Owns the ImGui context and its renderer backend (not copyable: impl_ is unique).
class ImGuiHost {
public:
    // `fontFiles`: the first that exists is the UI font; `fallback`'s when none does. The page passes
    // none: its font is in lab.data, and ImGui's own stays out of lab.wasm (cmake/web.cmake).
    explicit ImGuiHost(std::vector<std::string> fontFiles = {}, FallbackFont fallback = imguiBuiltinFont);
    ~ImGuiHost(); // shuts the renderer backend down and destroys the context

    // Creates the context (no .ini file, dark style) and the renderer backend; needs a current
    // GL ES 3.0 context. Then App::init. False with `error` when either fails.
    bool start(App& app, std::string& error);

    // One frame: the renderer backend's NewFrame, `platformNewFrame` (display size, time, the
    // cursor's shape), the frame's input events (in.events: mouse, keys, text), ImGui::NewFrame,
    // App::frame, ImGui::Render; then App::compose and ImGui's draw data into
    // in.targetFramebuffer — unless the picture would be exactly the last one (the same draw
    // data, no view drawn, no in.repaint): then nothing is drawn and out.presented is false, so
    // the platform need not swap. Fonts are rebuilt when the app asks for another UI scale.
    FrameOutput frame(const FrameInput& in, const std::function<void()>& platformNewFrame);

    // The browser: false, so that Tab leaves the canvas for the page's controls and Enter takes the
    // keyboard into the lab's windows instead (ui/keyboard.h). True to start with (the desktop).
    void setTabEntersWindows(bool on);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lab
