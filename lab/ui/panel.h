// panel.h — the control panel: every preset field, edited live, plus files and presets.
//
// The panel edits the Preset it is given, in place; there is no apply button and no copy.
// Anything that needs more than an edit (open a file, save, undo, load a model) is returned as a
// request in PanelActions for the app to carry out. ImGui only: no GL, no file access.
#pragma once

#include "core/preset.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab::ui {

// Views of the model that show one part of the lighting; they do not change the preset.
enum class ViewMode { Lit, Emissive, Ambient, Diffuse, Specular, Normals };
const char* toString(ViewMode mode);

// What the panel shows besides the preset (read-only for the panel, except the text fields).
struct PanelModel {
    std::vector<std::filesystem::path> presetFiles; // the preset list
    int currentPreset = -1;                          // index in presetFiles, -1 if none
    std::string documentName;
    bool dirty = false;
    bool canUndo = false, canRedo = false;
    std::string openPath;   // text fields, owned by the app between frames
    std::string saveAsPath;
    std::string modelPath;
    bool compare = false;        // compare mode on
    bool editingB = false;       // the panel edits the second set
    bool compareStacked = false; // A above B rather than beside it
    bool browser = false;        // files by download and the page's picker, not by path
    ViewMode viewMode = ViewMode::Lit;
    int selectedLight = 0;
};

struct PanelActions {
    std::optional<int> openPreset;          // index in presetFiles
    std::optional<std::string> openPath;
    std::optional<std::string> loadModel;   // a .gltf/.glb path typed in the model section
    bool save = false;
    std::optional<std::string> saveAs;
    bool revert = false, undo = false, redo = false;
    bool resetCamera = false;
    bool toggleCompare = false;
    bool screenshot = false;
    bool openShaderEditor = false;
    bool showHelp = false;
    bool download = false;    // the browser's "Download preset"
    bool pickFile = false;    // the browser's "Open preset..."
};

// Draws the panel's contents into the current ImGui window.
void controlPanel(Preset& preset, PanelModel& model, PanelActions& actions);

} // namespace lab::ui
