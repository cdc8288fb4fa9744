// screen.h — the whole UI of one frame, laid out: the panel, the plots, the tools, the dialogs,
// and the model's viewport's controls and overlay.
//
// The app fills a ScreenModel with what there is to show and edit (plain references into the
// workspace and its own UI state), calls drawScreen between ImGui::NewFrame and ImGui::Render,
// and carries out the ScreenEvents that come back. ImGui only: no GL, no files.
#pragma once

#include "core/io/diagnostics.h"
#include "core/lighting/probe.h"
#include "core/plots/probe_lobe.h"
#include "ui/actions.h"
#include "ui/layout.h"
#include "ui/panel/panel.h"
#include "ui/tools/share_code.h"
#include "ui/plots/plots.h"
#include "ui/tools/shader_editor.h"
#include "ui/tools/small_windows.h"
#include "ui/tools/sweep_view.h"
#include "ui/viewport/viewport.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

struct ScreenModel {
    Preset* a = nullptr;      // set A (the plots and the view's gestures edit it)
    Preset* b = nullptr;      // set B in compare mode, else nullptr
    Preset* edited = nullptr; // the set the panel edits
    DisplaySettings* view = nullptr;
    PanelInfo panelInfo;
    PanelState* panel = nullptr;
    PlotSettings* plots = nullptr;
    ShaderEditorState* shaderEditor = nullptr;
    SweepViewState* sweep = nullptr;
    std::string_view lightingSource;
    ViewportControls* viewportControls = nullptr;
    const ProbeResult* probe = nullptr; // the last probe, shown while probeOpen
    bool* probeOpen = nullptr;
    const ProbeLobe* probeLobe = nullptr; // plots at the probe: the probed point's lobe (app/pixel_probe.h), else nullptr
    bool* showHelp = nullptr;
    bool lightShapes = true; // spot cones and directional rays in the view
    const LightMotion* motion = nullptr; // while A's lights orbit: where the view shows them (core/scene/light_orbit.h)
    std::vector<std::pair<float, float>> clicks; // the frame's left clicks (window units), queued by the platform
    const Problem* problem = nullptr;           // shown until closed
    const std::string* unsavedQuestion = nullptr; // "open x.json": discard unsaved changes to do it?
    CaptionStrips captions; // the caption strips around the model: header, footer, legend, probe mark
    const ShareCodeModel* shareCode = nullptr; // the scene's link as a QR code, while shown (Q)
    bool equation = false;                     // the BRDF's equation over the model (presenter mode)
    bool pointer = false;                      // the room's pointer over the model (X)
    NotesModel notes;                          // the speaker's notes, shown while *showNotes
    bool* showNotes = nullptr;
};

struct ScreenEvents {
    std::vector<Request> requests;        // buttons and fields, in the order they were used
    ViewportEvents viewport;                  // gestures and probe clicks in the model's viewport
    bool problemClosed = false;
    std::optional<UnsavedAnswer> answer;
    bool gesture = false; // a widget or a view gesture is still active (one undo step when it ends)
    bool dragging = false; // ... with a mouse button held: a slider, a colour, the camera, a light
    bool typing = false;  // a text field has the keyboard: plain-key shortcuts are off
    float pointerX = 0, pointerY = 0; // where the pointer is, in window units (the value readout's)
};

// The UI's size relative to ImGui's 13-pixel default font (presenter mode makes it larger).
float uiScale();

ScreenEvents drawScreen(const Layout& layout, ScreenModel& model);

} // namespace lab::ui
