// actions.cpp — the command table and what is derived from it.
#include "ui/actions.h"

#include <array>

namespace lab {

namespace {

using C = Command;

// clang-format off
constexpr std::array kRows = {
    //          command               key                  modifiers      label               help                                                     typing
    CommandRow{C::ToggleHelp,         keys::F1,            kNoModifier,   "?",                "show or hide this help",                                true},
    CommandRow{C::CloseHelp,          keys::Escape,        kNoModifier,   "Close",            "close this help"},
    CommandRow{C::PreviousPreset,     keys::Left,          kNoModifier,   "Previous",         "previous slide: the deck's, or the preset list's (never asks: each keeps its edits)"},
    CommandRow{C::PreviousPreset,     keys::PageUp,        kNoModifier,   "Previous",         ""},
    CommandRow{C::NextPreset,         keys::Right,         kNoModifier,   "Next",             "next slide (a clicker's Page Down and Space too)"},
    CommandRow{C::NextPreset,         keys::PageDown,      kNoModifier,   "Next",             ""},
    CommandRow{C::NextPreset,         keys::Space,         kNoModifier,   "Next",             ""},
    CommandRow{C::FirstSlide,         keys::Home,          kNoModifier,   "First",            "first slide"},
    CommandRow{C::LastSlide,          keys::End,           kNoModifier,   "Last",             "last slide"},
    CommandRow{C::ResetSlide,         'R',                 kNoModifier,   "Reset slide (R)",  "reset the slide: the scene, set B and the view as the file has them (Ctrl+Z brings the edits back)"},
    CommandRow{C::TogglePointer,      'X',                 kNoModifier,   "Pointer (X)",      "a large pointer over the model that the back row sees (in screenshots too)"},
    CommandRow{C::ToggleNotes,        'S',                 kNoModifier,   "Notes (S)",        "speaker notes: the slide's notes, the next slide and the time"},
    CommandRow{C::NotesWindow,        'S',                 kShift,        "Notes window (Shift+S)", "speaker notes in a window of their own, for the laptop's screen while the lab fills the projector (the page: as S)"},
    CommandRow{C::ShadingFlat,        '1',                 kNoModifier,   "flat",             "flat shading"},
    CommandRow{C::ShadingGouraud,     '2',                 kNoModifier,   "Gouraud",          "Gouraud shading"},
    CommandRow{C::ShadingPhong,       '3',                 kNoModifier,   "Phong",            "Phong shading"},
    CommandRow{C::NextBrdf,           'B',                 kNoModifier,   "Next BRDF",        "next BRDF: Phong, Blinn-Phong, Cook-Torrance"},
    CommandRow{C::ToggleNormalMatrix, 'M',                 kNoModifier,   "Normal matrix",    "normal matrix: correct / wrong"},
    CommandRow{C::NextViewMode,       'V',                 kNoModifier,   "Next view",        "next view: lit, each term, normals, each factor that applies, Gouraud error"},
    CommandRow{C::PreviousViewMode,   'V',                 kShift,        "Previous view",    "previous view (only the views that apply to the scene)"},
    CommandRow{C::ToggleWireframe,    'W',                 kNoModifier,   "Wireframe",        "wireframe: the triangles' edges over the shaded model"},
    CommandRow{C::ToggleVertexNormals, 'N',                kNoModifier,   "Vertex normals",   "vertex normals as short lines over the model"},
    CommandRow{C::ToggleCompare,      'C',                 kNoModifier,   "Compare",          "compare mode: the view split in two"},
    CommandRow{C::ToggleShareCode,    'Q',                 kNoModifier,   "QR code (Q)",      "a large QR code of the scene's link, for students' phones (the exercise too)"},
    CommandRow{C::TogglePanels,       'H',                 kNoModifier,   "Panels",           "hide the panels in turn: all, plots and model, model only"},
    CommandRow{C::TogglePresenter,    'P',                 kNoModifier,   "Presenter",        "presenter mode (large UI, with the caption)"},
    CommandRow{C::ToggleCaption,      'I',                 kNoModifier,   "Caption",          "show or hide the caption: the preset's name and description"},
    CommandRow{C::ToggleLightShapes,  'L',                 kNoModifier,   "Light shapes",     "show or hide the spot cones and the directional lights' rays"},
    CommandRow{C::ToggleFrameTime,    'T',                 kNoModifier,   "Frame time",       "show or hide the frame time: the median cost of a frame while the model changes (a drag, a moving light), gone 3 s after; off in presenter mode"},
    CommandRow{C::PresenterLarger,    keys::Equal,         kCtrl,         "Larger",           "presenter scale up (1.5x to 2.5x)",                     true},
    CommandRow{C::PresenterLarger,    keys::KeypadAdd,     kCtrl,         "Larger",           "",                                                      true},
    CommandRow{C::PresenterSmaller,   keys::Minus,         kCtrl,         "Smaller",          "presenter scale down",                                  true},
    CommandRow{C::PresenterSmaller,   keys::KeypadSubtract, kCtrl,        "Smaller",          "",                                                      true},
    CommandRow{C::ToggleFullscreen,   keys::F11,           kNoModifier,   "Fullscreen",       "fullscreen",                                            true},
    CommandRow{C::ResetCamera,        'R',                 kShift,        "Reset camera (Shift+R)", "reset the camera to the preset's"},
    CommandRow{C::FrameModel,         'F',                 kNoModifier,   "Frame model (F)",  "frame the model: the camera moves to show all of it"},
    CommandRow{C::Screenshot,         keys::F12,           kNoModifier,   "Screenshot",       "screenshot of the 3D view to PNG",                      true},
    CommandRow{C::Undo,               'Z',                 kCtrl,         "Undo",             "undo"},
    CommandRow{C::Redo,               'Y',                 kCtrl,         "Redo",             "redo"},
    CommandRow{C::Redo,               'Z',                 kCtrl | kShift, "Redo",            ""},
    CommandRow{C::Save,               'S',                 kCtrl,         "Save",             "save",                                                  true},
    CommandRow{C::SaveAs,             'S',                 kCtrl | kShift, "Save as",         "save as (the path field)",                              true},
    CommandRow{C::FocusOpenPath,      'O',                 kCtrl,         "Open",             "open a preset by path (the path field)",                true},
    CommandRow{C::ToggleShaderEditor, 'E',                 kCtrl,         "Shader editor",    "shader editor",                                         true},
    CommandRow{C::CompileShaders,     keys::Enter,         kCtrl,         "Compile (Ctrl+Enter)", "compile the edited shaders (in the shader editor)",  true},
    CommandRow{C::CompileShaders,     keys::KeypadEnter,   kCtrl,         "Compile (Ctrl+Enter)", "",                                                   true},
    CommandRow{C::ToggleSweep,        'G',                 kCtrl,         "Sweep",            "sweep: a grid of renders, one or two values varied",    true},
    CommandRow{C::RevertShaders,      0,                   kNoModifier,   "Revert to built-in", ""},
    CommandRow{C::Revert,             0,                   kNoModifier,   "Revert",           ""},
    CommandRow{C::OpenPresetAt,       0,                   kNoModifier,   "",                 ""},
    CommandRow{C::OpenPath,           0,                   kNoModifier,   "Open",             ""},
    CommandRow{C::LoadModel,          0,                   kNoModifier,   "Load",             ""},
    CommandRow{C::DownloadPreset,     0,                   kNoModifier,   "Download preset",  ""},
    CommandRow{C::PickFile,           0,                   kNoModifier,   "Open preset...",   ""},
    CommandRow{C::CopyLink,           0,                   kNoModifier,   "Copy link",        ""},
    CommandRow{C::ExportFigures,      0,                   kNoModifier,   "Export figures",   ""},
    CommandRow{C::SaveSweep,          0,                   kNoModifier,   "Save PNG",         ""},
    CommandRow{C::ExerciseReset,      0,                   kNoModifier,   "Start again",      ""},
    CommandRow{C::ExerciseHint,       0,                   kNoModifier,   "Hint",             ""},
    CommandRow{C::ExerciseLeave,      0,                   kNoModifier,   "Leave exercise",   ""},
    CommandRow{C::MakeExercise,       0,                   kNoModifier,   "Make exercise",    ""},
    CommandRow{C::SaveExercise,       0,                   kNoModifier,   "Save exercise",    ""},
    CommandRow{C::OrbitLeft,          0,                   kNoModifier,   "Orbit left",       ""},
    CommandRow{C::OrbitRight,         0,                   kNoModifier,   "Orbit right",      ""},
    CommandRow{C::OrbitUp,            0,                   kNoModifier,   "Orbit up",         ""},
    CommandRow{C::OrbitDown,          0,                   kNoModifier,   "Orbit down",       ""},
    CommandRow{C::ZoomIn,             0,                   kNoModifier,   "Zoom in",          ""},
    CommandRow{C::ZoomOut,            0,                   kNoModifier,   "Zoom out",         ""},
    CommandRow{C::FitPhong,           0,                   kNoModifier,   "Fit Phong",        ""},
    CommandRow{C::FitBlinnPhong,      0,                   kNoModifier,   "Fit Blinn-Phong",  ""},
    CommandRow{C::FitCookTorrance,    0,                   kNoModifier,   "Fit Cook-Torrance", ""},
    CommandRow{C::ToggleLightMotion,  0,                   kNoModifier,   "Pause moving lights", ""},
    CommandRow{C::AnswerSaveFirst,    0,                   kNoModifier,   "Save first",       ""},
    CommandRow{C::AnswerDiscard,      0,                   kNoModifier,   "Discard",          ""},
    CommandRow{C::AnswerCancel,       0,                   kNoModifier,   "Cancel",           ""},
    CommandRow{C::CloseProblem,       0,                   kNoModifier,   "OK",               ""},
    CommandRow{C::SetShareBase,       0,                   kNoModifier,   "Use",              ""},
};
// clang-format on

// The keys inside a window (ImGui's keyboard navigation, ui/keyboard.h): not commands, but the help
// lists them with the shortcuts.
constexpr std::array<std::pair<const char*, const char*>, 7> kWindowKeyHelp = {{
    {"Tab / Shift+Tab", "from the model into the control panel (or the open tool window); then the next / previous "
                        "field to type a value in"},
    {"Enter, on the model",
     "into the control panel as Tab does (in the browser, where Tab goes to the page's controls)"},
    {"Ctrl+Tab", "the next window: control panel, plots, the open tools (keep Ctrl down and press Tab again to go on)"},
    {"Arrows, in a window",
     "move between widgets; on a slider after Space, Left / Right change it (Shift: 10x faster, Ctrl: 10x finer)"},
    {"Space / Enter, in a window",
     "press a button, tick a box, open a list, start changing a slider; Enter types a value instead"},
    {"Page Up / Page Down / Home / End, in a window", "a page up or down, the first or last widget"},
    {"Esc, in a window", "end the slider or the typing, close a list or a tooltip; then leave the window: the keys "
                         "above act on the model again"},
}};

// What the mouse and drops do: not commands, but the help lists them with the keys.
constexpr std::array<std::pair<const char*, const char*>, 4> kPointerHelp = {{
    {"Left drag / Right or middle drag / Wheel", "orbit / pan / zoom; drag a light marker to move the light"},
    {"Click", "probe the pixel under the mouse"},
    {"Touch: one finger / two fingers / tap", "orbit / pan and pinch to zoom / probe or press"},
    {"Drop a file", ".json opens a preset, .gltf/.glb loads a model"},
}};

std::string baseKeyName(int key) {
    switch (key) {
    case keys::Escape: return "Esc";
    case keys::Enter: return "Enter";
    case keys::KeypadEnter: return "Keypad Enter";
    case keys::Tab: return "Tab";
    case keys::Space: return "Space";
    case keys::PageUp: return "Page Up";
    case keys::PageDown: return "Page Down";
    case keys::Home: return "Home";
    case keys::End: return "End";
    case keys::Left: return "Left";
    case keys::Right: return "Right";
    case keys::Up: return "Up";
    case keys::Down: return "Down";
    case keys::KeypadAdd: return "Keypad +";
    case keys::KeypadSubtract: return "Keypad -";
    case keys::Equal: return "=";
    case keys::Minus: return "-";
    default: break;
    }
    if (key >= keys::F1 && key <= keys::F12) {
        return "F" + std::to_string(key - keys::F1 + 1);
    }
    return std::string(1, static_cast<char>(key));
}

} // namespace

std::span<const CommandRow> commandTable() { return kRows; }

const CommandRow& commandRow(Command command) {
    for (const CommandRow& row : kRows) {
        if (row.command == command) {
            return row;
        }
    }
    return kRows.front(); // unreachable: every command has a row (tested)
}

std::optional<Command> commandForKey(int key, unsigned modifiers, KeyOwner owner) {
    for (const CommandRow& row : kRows) {
        if (row.key == 0 || row.key != key || row.modifiers != modifiers) {
            continue;
        }
        // A widget with the keyboard keeps the plain keys; a text field all but the whileTyping rows.
        bool fires = owner == KeyOwner::Canvas || row.whileTyping || (owner == KeyOwner::Panel && (row.modifiers & kCtrl));
        return fires ? std::optional<Command>(row.command) : std::nullopt;
    }
    return std::nullopt;
}

std::optional<Command> commandForKey(int key, unsigned modifiers, bool typing) {
    return commandForKey(key, modifiers, typing ? KeyOwner::Typing : KeyOwner::Canvas);
}

std::string keyName(int key, unsigned modifiers) {
    std::string name;
    if (modifiers & kCtrl) {
        name += "Ctrl+";
    }
    if (modifiers & kShift) {
        name += "Shift+";
    }
    return name + baseKeyName(key);
}

std::vector<HelpRow> helpRows() {
    std::vector<HelpRow> rows;
    for (const CommandRow& row : kRows) {
        if (*row.help == '\0' || row.key == 0) {
            continue;
        }
        HelpRow help{keyName(row.key, row.modifiers), row.help};
        for (const CommandRow& alias : kRows) { // the command's other bindings
            if (&alias != &row && alias.command == row.command && alias.key != 0 && *alias.help == '\0') {
                help.keys += " / " + keyName(alias.key, alias.modifiers);
            }
        }
        rows.push_back(std::move(help));
    }
    for (const auto& [keysText, help] : kWindowKeyHelp) {
        rows.push_back({keysText, help});
    }
    for (const auto& [keysText, help] : kPointerHelp) {
        rows.push_back({keysText, help});
    }
    return rows;
}

} // namespace lab
