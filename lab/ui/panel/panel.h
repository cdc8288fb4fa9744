// panel.h — the control panel: every preset field, edited live, plus files and presets.
//
// The panel edits the Preset it is given, in place; there is no apply button and no copy. The
// widgets allow exactly the ranges the preset validator accepts (core/scene/limits.h). Anything that
// needs more than an edit (open a file, save, undo, load a model) comes back as a Request
// (ui/actions.h) for the app to carry out. ImGui only: no GL, no file access.
#pragma once

#include "core/plots/theme.h"
#include "core/scene/preset.h"
#include "core/scene/view_mode.h"
#include "ui/actions.h"
#include "ui/panel/exercise_panel.h"
#include "ui/layout.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lab::ui {

// What the panel shows about the workspace (read-only for the panel).
struct PanelInfo {
    std::vector<std::string> presetNames; // the list: a deck's slides, else the preset list's files
    int currentPreset = -1;               // index in presetNames, -1 if none
    std::string deckTitle;                // the deck's, when the list is a deck's
    std::string documentName;
    bool dirty = false;
    bool canUndo = false, canRedo = false;
    bool compareStacked = false; // A above B rather than beside it
    bool browser = false;        // files by download and the page's picker, not by path
    const std::vector<std::filesystem::path>* exerciseFiles = nullptr; // the shipped exercises
    const ExercisePanelModel* exercise = nullptr; // an exercise is being solved
    DraftPanelModel* draft = nullptr;     // an exercise is being made
    bool lightsPaused = false;            // the moving lights' motion is paused (Command::ToggleLightMotion)
};

// What the panel keeps between frames, and the workspace settings it edits in place.
struct PanelState {
    std::string openPath, saveAsPath, modelPath; // text fields
    int selectedLight = 0;
    PanelTab tab = PanelTab::Plots; // the compact layout's chosen tab (ui/layout.h)
    bool focusOpenPath = false; // Ctrl+O: the open field takes the keyboard this frame
    int listScrolledTo = -1;    // the preset the list last scrolled to: it follows the current one
    float figureScale = 2.0f;   // Export figures' PNGs: 1 is 720 pixels wide (kFigureScales)
    std::string exercisePath;   // "Make exercise": where it is saved
    Theme theme = Theme::Dark;  // the UI's, the plots' and the exported figures' colours (core/plots/theme.h)
    int fitDistribution = 0;    // the fitted Cook-Torrance's distribution, in kDistributions' order
};

// The PNG scales Export figures offers: 720, 1440 (a projector, the default) and 2880 pixels wide.
inline constexpr float kFigureScales[] = {1.0f, 2.0f, 4.0f};

// The whole panel, or one of the compact layout's tabs (ui/layout.h): Model (files, presets,
// compare, tools, the model, the camera), Material (material, BRDF, shading and terms), Lights.
enum class PanelPart { All, Model, Material, Lights };

// Draws the panel's contents into the current ImGui window: edits `preset` (the set being
// edited) and `view` in place, appends what it asks for to `requests`.
void controlPanel(Preset& preset, DisplaySettings& view, const PanelInfo& info, PanelState& state,
                  std::vector<Request>& requests, PanelPart part = PanelPart::All);

} // namespace lab::ui
