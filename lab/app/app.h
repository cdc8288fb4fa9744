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
// Frames are drawn only when something changes (app/frame_pacer.h), and the model's viewport only when
// what it shows changes (app/viewport_cache.h).
//
// Implemented: live panel, plots, presets list, open/save/revert with unsaved-changes prompt,
// drag-and-drop of presets and models, undo/redo, orbit/pan/zoom, light markers and dragging,
// compare mode, per-term views, pixel probe, shader editor, screenshots, presenter mode,
// help overlay, frame time. Errors are shown in the window and never change the scene.
#pragma once

#include "app/input.h"
#include "app/orbit_clock.h"
#include "app/page_model.h"
#include "app/workspace.h"
#include "core/io/diagnostics.h"
#include "core/plots/theme.h"
#include "ui/actions.h"
#include "ui/tools/notes.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lab {

struct FrameInput {
    float windowWidth = 0, windowHeight = 0; // ImGui's units (screen coordinates)
    int framebufferWidth = 0, framebufferHeight = 0;
    float deltaTime = 1.0f / 60.0f;     // since the last frame (long after an idle wait)
    float lastFrameSeconds = 0.0f;      // what the last frame cost, from its start to its swap
    std::vector<std::string> droppedFiles;
    std::vector<std::string> notes;     // the platform's own messages for the toast (the page: "Loading the Draco decoder…")
    std::vector<InputEvent> events;     // this frame's share of the queued input (app/input.h)
    int framesDue = 0;                  // frames the platform will draw after this one anyway (FramePacer::dueAfterThis)
    bool repaint = false;               // the window's picture was lost (uncovered, resized): draw it even if unchanged
    bool closeRequested = false; // the user closed the window
    bool notesWindowClosed = false; // the user closed the notes' own window (FrameOutput::notesWindow)
    bool touch = false;          // the pointer is a finger (app/touch.h): touch-sized widgets
    std::optional<std::string> openLink; // a link to open ("preset=name", "z=...": core/share/share_link.h)
    bool openLinkSaved = false;          // it is the page's own saved state (kMaxSavedLinkChars), not an address
    unsigned targetFramebuffer = 0;      // the GL framebuffer to draw into (0: the window's)
    std::vector<PageEdit> pageEdits;     // the page's own controls (app/page_model.h), in order
    std::optional<std::string> pageFocus; // the page's control that has the keyboard (its field's path, "" none)
    // The browser, a few times a second: this frame describes the lab for the page's parallel DOM
    // (FrameOutput::page). Not every frame: a drag would pay for the description and the DOM's update.
    bool describePage = false;
    // Who this frame's keys are for: the model's shortcuts, a window's widget, a text field
    // (set by the ImGui host, platform/imgui_host.h, from ui/keyboard.h).
    KeyOwner keys = KeyOwner::Canvas;
};

struct FrameOutput {
    bool quit = false;
    bool toggleFullscreen = false;
    float uiScale = 1.0f; // the platform rebuilds fonts and style when this or `touch` changes
    bool touch = false;   // touch-sized widgets (FrameInput::touch)
    bool typing = false;  // a text field has the keyboard (the browser shows a touch screen's keyboard)
    std::string title;
    std::string link;               // the current scene as a preset link (shareable, restorable; may exceed kMaxLinkChars)
    std::string problem;            // the error dialog's text while it is shown (the page mirrors it for screen readers)
    // The exercise's score as one line of plain text (exerciseScoreLine, app/exercise_score.h: "Score 42%: not
    // solved yet", "Solved: score 100%"), as the panel's bar says it; "" outside an exercise (the page announces it).
    std::string exerciseScore;
    // Whether a light of the scene orbits by itself, and whether that motion is paused (Command::ToggleLightMotion).
    MovingLights movingLights = MovingLights::None;
    std::vector<Download> downloads; // only when AppOptions::saveByDownload
    bool pickFile = false;           // the user asked to open a file (the browser shows its picker)
    bool copyLink = false;           // the user asked for the scene's link on the clipboard (the browser)
    // When the next frame is needed without input (app/frame_pacer.h): 0 at once, > 0 in that
    // many seconds (a toast going away), < 0 only on input.
    float redrawIn = -1.0f;
    bool viewportDrawn = false;  // the model's viewport was drawn this frame (otherwise its cached copy was shown)
    bool presented = true;   // the window was drawn (false: it would have looked exactly as the last; no swap needed)
    std::string page;            // FrameInput::describePage: the page's description of the lab (app/page_model.h)
    bool pageDescribed = false;  // `page` was made: asked for, and no value is being dragged (the description waits)
    KeyOwner keys = KeyOwner::Canvas; // who this frame's keys went to (the page: Tab is the browser's only on the model)
    float viewportScale = 1.0f;  // the fraction of the view's width and height drawn (< 1 while dragging on a slow machine)
    // The speaker's notes for a window of their own (Command::NotesWindow, AppOptions::notesWindows): the
    // platform opens one while this is set, draws it with ui::notesScreen, and closes it when it is not.
    std::optional<ui::NotesModel> notesWindow;
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
    int viewportSamples = 0; // multisampling of the model's viewport (the desktop asks for 4 where the GL has them)
    // While dragging, the model's viewport is drawn at a lower resolution when frames take longer than
    // this (app/viewport_cache.h); 0 turns that off.
    float frameBudgetSeconds = 0.05f;
    // The course page's address (https://.../lab/): the QR code (Q) opens the scene's link there.
    // The page gives its own; the desktop --share-base (remembered in the settings file).
    std::string shareBase;
    // Called when the user gives the course page's address in the QR code's window (Command::SetShareBase,
    // checked by shareBaseProblem): the desktop remembers it as --share-base. Without it the address
    // is not editable there (the page's is its own).
    std::function<void(const std::string&)> shareBaseChosen;
    // The theme at start (core/plots/theme.h): the UI's, the plots' and the exported figures'
    // colours; dark when none. The desktop's --theme (remembered), the page's prefers-color-scheme
    // or the visitor's earlier choice.
    std::optional<Theme> theme;
    // Called when the user chooses a theme in the panel (not for setTheme): the desktop remembers
    // it in the settings file, the page in its saved state, and stops following the system's.
    std::function<void(Theme)> themeChosen;
    // The user asked for less motion (the page: the prefers-reduced-motion media query): a scene whose
    // light orbits opens with the motion paused (app/orbit_clock.h); Command::ToggleLightMotion resumes it.
    bool reducedMotion = false;
    // The platform can open a second window for the speaker's notes (the desktop): Shift+S asks for it.
    // Without one, Shift+S shows the notes' strip as S does.
    bool notesWindows = false;
};

// Owns the workspace, the renderer and the UI state (not copyable: impl_ is unique).
class App {
public:
    explicit App(AppOptions options);
    ~App();

    // Needs the GL context and the ImGui context. False (with diagnostics) if the built-in
    // shaders do not compile; a preset that fails to open is shown as an error in the window.
    bool init(Diagnostics& diagnostics);

    // Between ImGui::NewFrame() and ImGui::Render(): the UI, the requests, and the viewports
    // drawn offscreen where what they show changed. Draws nothing into the window.
    FrameOutput frame(const FrameInput& input);
    // The window's picture under ImGui's draw data: the background and this frame's views, into
    // `targetFramebuffer` (width × height pixels). The platform skips it, and the draw data and
    // the swap, when the frame would look exactly as the last (imgui_host.h).
    void compose(unsigned targetFramebuffer, int width, int height);

    // The theme in use; setTheme changes it as the panel would, but is not the user's choice
    // (the page follows prefers-color-scheme with it until the user chooses).
    Theme theme() const;
    void setTheme(Theme theme);
    // Whether the user has chosen a theme in the panel since the lab started.
    bool themeChosen() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lab
