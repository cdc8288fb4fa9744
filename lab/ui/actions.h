// actions.h — every command of the lab, written down once.
//
// One row per key binding: {command, key, modifiers, label, help}. The rows drive the keyboard
// shortcuts (commandForKey), the help overlay and the README's shortcut table (helpRows, checked
// by a test), and the panel's buttons (their labels). Adding a command is adding a row here and
// carrying it out in the app. Commands that take an argument (a path, a list index) travel as a
// Request. No ImGui, no GL: the key codes are GLFW's, which ImGui 1.86's GLFW backend and the
// browser's GLFW also use.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace lab {

// GLFW key codes; letters and digits are their upper-case ASCII codes.
namespace keys {
constexpr int Space = 32, Escape = 256, Enter = 257, Tab = 258, Backspace = 259, Insert = 260, Delete = 261;
constexpr int Right = 262, Left = 263, Down = 264, Up = 265, PageUp = 266, PageDown = 267, Home = 268, End = 269;
constexpr int F1 = 290, F11 = 300, F12 = 301, Equal = 61, Minus = 45, KeypadAdd = 334, KeypadSubtract = 333;
constexpr int KeypadEnter = 335;
constexpr int LeftShift = 340, LeftControl = 341, LeftAlt = 342, LeftSuper = 343;
constexpr int RightShift = 344, RightControl = 345, RightAlt = 346, RightSuper = 347;
} // namespace keys

// Who a key press is for. The model (the canvas) has the keyboard unless a window's widget does:
// then the plain keys (letters, digits, arrows, Space, Esc) are the widget's and only the rows with
// Ctrl, or marked whileTyping, are shortcuts; while a text field has it, only the whileTyping rows.
enum class KeyOwner { Canvas, Panel, Typing };

// Modifier bits of a key press. No row uses Alt, so a press with Alt held runs no command.
enum Modifier : unsigned { kNoModifier = 0, kCtrl = 1, kShift = 2, kAlt = 4 };

enum class Command {
    // The scene and its files (the workspace carries these out)
    PreviousPreset, NextPreset, FirstSlide, LastSlide, ResetSlide, OpenPresetAt, OpenPath, Save, SaveAs, Revert, Undo, Redo,
    DownloadPreset, LoadModel, ShadingFlat, ShadingGouraud, ShadingPhong, NextBrdf,
    ToggleNormalMatrix, NextViewMode, PreviousViewMode, ToggleWireframe, ToggleVertexNormals, ToggleCompare, ResetCamera, FrameModel,
    // The camera in steps (the page's buttons: a keyboard's and a single pointer's way to orbit and zoom)
    OrbitLeft, OrbitRight, OrbitUp, OrbitDown, ZoomIn, ZoomOut,
    // Fitting (core/plots/fit.h): B becomes that model fitted to A's specular lobe, in compare mode
    // (FitCookTorrance's Request::index is the distribution; -1: A's own, else Beckmann)
    FitPhong, FitBlinnPhong, FitCookTorrance,
    // The window and its tools (the app carries these out)
    ToggleHelp, CloseHelp, TogglePanels, TogglePresenter, PresenterLarger, PresenterSmaller, ToggleCaption,
    ToggleLightShapes, ToggleLightMotion, ToggleNotes, NotesWindow, TogglePointer,
    ToggleFrameTime,
    ToggleFullscreen, Screenshot, FocusOpenPath, PickFile, CopyLink, ToggleShaderEditor, CompileShaders,
    ExportFigures,
    RevertShaders, ToggleSweep, SaveSweep,
    // Exercises (core/exercise/exercise.h): the workspace carries these out, the QR code the app
    ExerciseReset, ExerciseHint, ExerciseLeave, MakeExercise, SaveExercise,
    // The dialogs' answers as buttons (the page's parallel DOM answers them so)
    AnswerSaveFirst, AnswerDiscard, AnswerCancel, CloseProblem,
    // The QR code window's course address (Request::path), remembered where the platform can (AppOptions::shareBaseChosen)
    SetShareBase,
    ToggleShareCode,
};
inline constexpr Command kLastCommand = Command::ToggleShareCode; // a new command goes before it, or becomes it

struct CommandRow {
    Command command;
    int key = 0;             // 0: no key (a button or a drop only)
    unsigned modifiers = 0;  // Modifier bits
    const char* label = "";  // a button's text
    const char* help = "";   // the help overlay's line; "" for a second binding of a command
    bool whileTyping = false; // also when a text field has the keyboard
};

// A command with its argument, as the UI hands it to the app.
struct Request {
    Request(Command c, std::string p = {}, int i = -1) : command(c), path(std::move(p)), index(i) {}
    Command command;
    std::string path; // OpenPath, SaveAs, LoadModel, SaveExercise, SetShareBase; Save: the "Save as" field, for an untitled scene
    int index = -1;   // OpenPresetAt
};

// The answers to "discard unsaved changes?".
enum class UnsavedAnswer { SaveFirst, Discard, Cancel };

std::span<const CommandRow> commandTable();

// The first row of `command`.
const CommandRow& commandRow(Command command);

// The command bound to a key press for `owner` (see KeyOwner).
std::optional<Command> commandForKey(int key, unsigned modifiers, KeyOwner owner);
// ... the canvas's, or while `typing` only rows marked whileTyping.
std::optional<Command> commandForKey(int key, unsigned modifiers, bool typing);

// "Ctrl+Shift+Z", "F1", "Left".
std::string keyName(int key, unsigned modifiers);

// One line of the help overlay and of the README's shortcut table.
struct HelpRow {
    std::string keys;
    std::string help;
};

// Every command with a help text (its bindings joined by " / "), then the keys inside a window
// (ImGui's keyboard navigation), then the mouse and drops.
std::vector<HelpRow> helpRows();

} // namespace lab
