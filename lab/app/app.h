// app.h — the interactive lab: one frame function that every windowed platform calls.
//
// The app owns the workspace (the editing state and the file operations, app/workspace.h), the
// renderer and the UI's own state. Each frame reads as the data flow: the layout (a pure
// function), the UI (lab/ui, which edits the scene in place and returns requests), the requests
// carried out (by the workspace, or here for the window's own ones), one undo step per gesture,
// then the renderer draws what the workspace holds; the platform renders ImGui's draw data on
// top and presents. The loop belongs to the platform (platform/window.h); the app never sees
// GLFW or the browser, and draws no ImGui itself.
//
// Implemented: live panel, plots, presets list, open/save/revert with unsaved-changes prompt,
// drag-and-drop of presets and models, undo/redo, orbit/pan/zoom, light markers and dragging,
// compare mode, per-term views, pixel probe, shader editor, screenshots, presenter mode,
// help overlay, frame time. Errors are shown in the window and never change the scene.
#pragma once

#include "app/workspace.h"
#include "core/diagnostics.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lab {

// A key press as the platform saw it: a GLFW key code (letters and digits are their ASCII
// codes) with the modifiers held. Queued by the platform, because ImGui 1.86 polls key state
// once a frame and misses a press and release that fall within one frame.
struct KeyPress {
    int key = 0;
    bool ctrl = false, shift = false, alt = false;
};

// A mouse button going down or up, where it happened (window units). Queued by the platform, so
// a click is seen at its own place however slow the frame.
struct MouseButtonEvent {
    float x = 0, y = 0;
    int button = 0; // 0 left, 1 right
    bool pressed = false;
};

// The left-button clicks in `events`: a press and its release less than 4 units apart, at the
// press's place. A press whose release has not come yet is carried over in `pending`.
std::vector<std::pair<float, float>> clicksOf(const std::vector<MouseButtonEvent>& events,
                                              std::optional<MouseButtonEvent>& pending);

struct FrameInput {
    float windowWidth = 0, windowHeight = 0; // ImGui's units (screen coordinates)
    int framebufferWidth = 0, framebufferHeight = 0;
    float deltaTime = 1.0f / 60.0f;
    std::vector<std::string> droppedFiles;
    std::vector<KeyPress> keys;  // pressed since the last frame, in order
    std::vector<MouseButtonEvent> mouseButtons; // since the last frame, in order
    bool closeRequested = false; // the user closed the window
    std::optional<std::string> openLink; // a preset link to open ("preset=name" or "p=...", see core/link.h)
    unsigned targetFramebuffer = 0;      // the GL framebuffer to draw into (0: the window's)
};

struct FrameOutput {
    bool quit = false;
    bool toggleFullscreen = false;
    float uiScale = 1.0f; // the platform rebuilds fonts and style when this changes
    std::string title;
    std::string link;               // the current scene as a preset link (shareable, restorable)
    std::vector<Download> downloads; // only when AppOptions::saveByDownload
    bool pickFile = false;           // the user asked to open a file (the browser shows its picker)
};

struct AppOptions {
    std::optional<std::filesystem::path> preset;      // opened at start; the defaults otherwise
    bool presenter = false;                            // start in presenter mode
    std::filesystem::path screenshotFolder = ".";
    std::vector<std::filesystem::path> presetFolders;  // the first that exists fills the preset list
    std::optional<std::filesystem::path> layoutFile;   // GUI tests: widget rectangles written here
    // The browser: files are saved by downloading them and opened through the page's picker,
    // so the panel offers Download and Open instead of path fields.
    bool saveByDownload = false;
    // Where Save puts the edits of a shipped preset (defaultUserFolder() when empty).
    std::filesystem::path userFolder;
};

// Owns the workspace, the renderer and the UI state (not copyable: impl_ is unique).
class App {
public:
    explicit App(AppOptions options);
    ~App();

    // Needs the GL context and the ImGui context. False (with diagnostics) if the built-in
    // shaders do not compile; a preset that fails to open is shown as an error in the window.
    bool init(Diagnostics& diagnostics);

    // Between ImGui::NewFrame() and ImGui::Render(), with the default framebuffer bound.
    FrameOutput frame(const FrameInput& input);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lab
