// page_model.h — the lab as the browser page's parallel DOM shows it (web/access.js), and what
// comes back from it.
//
// A screen reader cannot read the canvas, and the keyboard cannot reach into it from the page. So
// the app describes itself as data: every field of the field table (core/scene/field_table.h) that
// the panel would show — its label, unit, range, step, help and value, behind the exercise's gate —
// grouped by the panel's sections and the compact layout's tabs; the command table's buttons
// (ui/actions.h); and the pictures' text alternatives (core/plots/describe.h), the exercise's
// score and the lab's messages. The page builds native HTML controls from it and sends back field
// edits (checked by core/scene/field_edit.h) and commands, which take the same way as the ImGui
// panel's (one undo step a change). No ImGui, no GL, no browser: JSON text in, JSON text out.
#pragma once

#include "app/orbit_clock.h"
#include "app/workspace.h"
#include "core/lighting/probe.h"
#include "ui/layout.h"
#include "ui/panel/exercise_panel.h"
#include "ui/panel/panel.h"
#include "ui/tools/notes.h"
#include "ui/tools/shader_editor.h"
#include "ui/tools/share_code.h"
#include "ui/tools/sweep_view.h"

#include <optional>
#include <string>
#include <vector>

namespace lab {

// A field edit of the page's that the lab refused: the path as the page sent it (its control's
// data-path), and why ("material.shininess: must be in [0.001, 1000000], got 1000001").
struct PageRefusal {
    std::string path, message;
};

// What the page is owed by its next description, the last 30 of each: every message shown, oldest
// first (the page's message log keeps each, however short its time on screen: a toast replaced
// within one description interval is not lost), and the field edits refused (each control says why,
// in its description and with aria-invalid, besides the message log).
struct PageNews {
    std::vector<std::string> said;
    std::vector<PageRefusal> refused;
    void say(std::string text);
    void refuse(PageRefusal refusal);
};

// What the app knows beside the workspace, for the page.
struct PageFacts {
    const ui::ExercisePanelModel* exercise = nullptr; // while one is solved
    std::string problem; // the error dialog's text while it is shown
    std::string question; // the unsaved-changes dialog's sentence while it is shown
    std::string probe;   // the pixel probe's readout, "" when none
    std::string legend;  // the factor view's legend, "" when the lit model is shown
    MovingLights motion = MovingLights::None; // a light moves by itself: the Pause button, pressed while paused
    std::string_view theme = "dark";           // the theme in use (the page's own colours follow it)
    const ui::ShareCodeModel* share = nullptr; // the QR code window while it is shown: its link, or why it has no code
    // The tool windows while they are open: the page offers their fields too (and sets them).
    ui::ShaderEditorState* shader = nullptr;
    ui::SweepViewState* sweep = nullptr;
    PageNews news; // what was said and refused since the last description
    const ui::NotesModel* notes = nullptr; // the speaker's notes while their strip is shown (S)
};

// The page's description of the lab (a JSON object; web/access.js reads it). The pictures' words
// (the scene, the plots, the albedo) are found again only when set A changed.
class PageModel {
public:
    const std::string& json(Workspace& workspace, const PageFacts& facts);

private:
    std::optional<Preset> described_;
    std::string pictures_; // the words of described_, as JSON
    std::string json_;
};

// One thing the page's controls asked for.
struct PageEdit {
    std::string path;  // a field's path; empty for a command
    std::string value; // the field's new value as text (field_edit.h)
    int command = -1;  // a Command (ui/actions.h) when `path` is empty; `index` its argument
    int index = -1;
};

// Carries out the page's field edits on the edited set, behind the exercise's gate (a field it does
// not open is refused), and on the open tool windows ("shader.lighting", "sweep.values[1]");
// returns the edits refused (none when all were taken), and appends the page's commands to `requests`.
std::vector<PageRefusal> applyPageEdits(Workspace& workspace, const std::vector<PageEdit>& edits, const PageFacts& tools,
                                        std::vector<Request>& requests);

// The facts of the tool windows that are open (the rest empty).
PageFacts openTools(ui::ShaderEditorState& shader, ui::SweepViewState& sweep);

// The page's input for this frame: its field edits carried out (applyPageEdits; what is refused
// becomes the workspace's note and goes into `news`), its focused control ringed on the canvas (on
// the compact layout's tab that has it); returns its commands.
std::vector<Request> takePageInput(Workspace& workspace, const std::vector<PageEdit>& edits,
                                   const std::optional<std::string>& focus, const PageFacts& tools, ui::PanelState& panel,
                                   PageNews& news);

// The tool window's text field at `path` ("shader.lighting", "sweep.key0", "sweep.val1") while it is open, else nullptr.
std::string* toolField(const std::string& path, const PageFacts& tools);

// The compact layout's tab that shows the field at `path` (a light's also selects it), if any.
std::optional<ui::PanelTab> panelTabOf(const std::string& path, int& selectedLight);

// The probe's readout in words ("Probe: colour 0.82, 0.40, 0.31; light 1: diffuse ..."), "" for none.
std::string probeWords(const ProbeResult* probe);

} // namespace lab
