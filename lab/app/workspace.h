// workspace.h — the editing state of the lab and every operation on files and links.
//
// The workspace owns the document (set A, compare set B, saved state, undo/redo), the view mode,
// which set the panel edits, the preset list, and the meshes of both sets (through the one mesh
// cache). It carries out the commands that change the scene or touch files: open, step through
// presets, save, save as, revert, undo, redo, links in and out, downloads, dropped presets and
// models, screenshots to files. Everything is checked before anything changes: a file that does
// not load leaves the scene exactly as it was and reports why.
//
// It does not draw or read input: no ImGui, no GL (tests/workspace_test.cpp runs it headless).
// Problems come out as Diagnostics with a title (takeProblems), short messages as notes
// (takeNotes), files for the browser as downloads (takeDownloads); the app shows them.
#pragma once

#include "app/document.h"
#include "core/exercise/exercise.h"
#include "core/gltf/mesh_cache.h"
#include "core/io/diagnostics.h"
#include "core/io/image.h"
#include "core/lighting/lighting.h"
#include "core/scene/deck.h"
#include "core/scene/view_mode.h"
#include "ui/actions.h"

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lab {

// A file the platform should hand to the user (the browser downloads it).
struct Download {
    std::string name;
    std::string bytes;
};

struct WorkspaceOptions {
    std::vector<std::filesystem::path> presetFolders; // shipped presets: the first that has any fills the list
    std::filesystem::path screenshotFolder = ".";
    bool saveByDownload = false; // the browser: save and screenshots become downloads
    // Where Save puts a shipped preset's edits: the shipped files are never overwritten.
    std::filesystem::path userFolder;
};

// The user's preset folder: $XDG_DATA_HOME/lighting-lab/presets, else
// ~/.local/share/lighting-lab/presets, else ./lighting-lab-presets.
std::filesystem::path defaultUserFolder();

// A file name made of letters, digits, '-' and '_' only (downloads, numbered files).
std::string safeStem(const std::string& stem);

// An exercise being solved (core/exercise/exercise.h): A is the student's attempt, B the target,
// drawn beside it with its parameters hidden; only the open fields of A can change.
struct ExerciseSession {
    Exercise exercise;
    std::filesystem::path file;             // empty when it came from a link
    std::optional<std::string> bundledName; // a shipped exercise: linked by name
    int hintsShown = 0;
    unsigned opened = 0; // counts the exercises opened: a new one needs a new target render
};

// "Make exercise": the scene when it was pressed is the target; the author ticks the fields a
// student may change, sets them to where the student starts, writes the instructions and saves.
struct ExerciseDraft {
    Preset target;
    std::vector<std::string> open;
    std::string title = "Untitled exercise";
    std::string instructions;
    std::string hints; // one a line
};

// Compare mode's two sets, side by side: A (the document's preset, what is saved) and B.
enum class Side { A, B };
inline constexpr std::array kSides{Side::A, Side::B};
inline std::size_t indexOf(Side side) { return static_cast<std::size_t>(side); }

class Workspace {
public:
    explicit Workspace(WorkspaceOptions options);

    // The default scene (untitled, in `folder`), then `preset` when given.
    void start(const std::filesystem::path& folder, const std::optional<std::filesystem::path>& preset = {});

    //--- what is being edited -----------------------------------------------------------
    Document& document() { return doc_; }
    const Document& document() const { return doc_; }
    Preset& a() { return doc_.preset; }
    Preset& b() { return doc_.compare; }
    Preset& preset(Side side) { return side == Side::A ? doc_.preset : doc_.compare; }
    Preset& edited() { return view.compare && view.editingB ? doc_.compare : doc_.preset; }
    DisplaySettings view; // the per-term view and compare mode

    const std::vector<std::filesystem::path>& presetFiles() const { return presetFiles_; }
    // The list the panel shows and Left/Right step through: a deck's slides' titles, else the
    // preset list's file names; and the one open (-1 if none).
    std::vector<std::string> slideNames() const;
    int slideCount() const;
    std::string slideName(int index) const; // 0 <= index < slideCount()
    int currentSlide() const { return deck_ ? currentDeckSlide_ : currentPreset_; }
    // The shipped exercises (the first preset folder's exercises/), for the panel's list.
    const std::vector<std::filesystem::path>& exerciseFiles() const { return exerciseFiles_; }
    int currentPreset() const { return currentPreset_; } // index in presetFiles, -1 if none

    //--- commands -----------------------------------------------------------------------
    // Carries out a scene or file command; false if `request` is not the workspace's.
    bool run(const Request& request);
    void open(const std::filesystem::path& file);
    // "preset=name", "exercise=name", "z=...", "x=..." (core/share/share_link.h); `saved`: the page's
    // own saved state, which may be longer than a link from outside.
    void openLink(const std::string& fragment, bool saved = false);
    bool saveTo(const std::filesystem::path& file);
    // A .gltf/.glb becomes A's model, framed as a preset without a camera is (seen from
    // core/scene/camera.h threeQuarterDirection), and A's lights are carried to it
    // (core/gltf/model_loader.h carryLights from the old model's drawn bounds, the unit sphere when
    // there were none): all in one undo step.
    void useModel(const std::filesystem::path& file);
    // The camera frames A's model tightly (core/scene/camera.h framedCamera) along its current direction.
    void frameModel();
    void drop(const std::vector<std::string>& files);
    void requestQuit();
    // An open that waits for a file of the page's site (core/io/site_files.h: a bundled model, fetched
    // the first time a preset names it) is carried out once the file is here, or reports why it could
    // not be fetched; the app asks every frame. A newer open, link or model replaces the one waiting.
    void resumeWaiting();
    bool waiting() const { return waiting_.has_value(); }
    // A PNG of the view into the screenshot folder (a download in the browser), named
    // <preset><suffix>-NNN.png; `what` names it in the messages ("Screenshot", "Sweep").
    void saveScreenshot(const Image& image, const std::string& suffix = "", const std::string& what = "Screenshot");
    // Files into a new folder <preset>-figures-NNN in the screenshot folder (downloads named
    // <preset>-<file> in the browser); `what` names them in the messages.
    void saveFiles(const std::vector<Download>& files, const std::string& what);

    // B follows A's camera (in an exercise B is the target, and A keeps the start's value of
    // every field the exercise does not open); then the frame's edits become one undo step unless
    // a gesture is still in progress.
    void endFrame(bool gestureInProgress) {
        keepExercise();
        doc_.compare.camera = doc_.preset.camera;
        doc_.commit(gestureInProgress);
    }

    //--- slides (workspace_slides.cpp) -------------------------------------------------------
    // A deck's slides, or a folder's presets (the preset list), are slides: stepping through them
    // never asks, each keeps its live edits, its undo history and its display for the session
    // (going back shows them), and nothing is written unasked. A file opened by path that is not
    // in the list is a document as before (its unsaved changes asked about).
    const std::optional<Deck>& deck() const { return deck_; }
    bool onSlide() const { return !slideKey_.empty(); }
    // The speaker's notes of what is shown: the slide's, else the preset's own.
    const std::string& notes() const;
    // The next slide's title ("" at the last, or when not on a slide).
    std::string nextSlideTitle() const;
    void goToSlide(int index);
    // The scene, set B and the display back to the file's (one undo step).
    void resetSlide();
    // The display the file asks for (its `display`, core/scene/preset.h), compare mode when it
    // has `compare`; the defaults where it says nothing.
    void showAsOpened();

    //--- exercises ----------------------------------------------------------------------
    const std::optional<ExerciseSession>& exercise() const { return exercise_; }
    std::optional<ExerciseDraft>& draft() { return draft_; }
    // The mesh of the exercise's start (for d(start), core/exercise/score.h): A's or B's when the
    // start has their model, else loaded; null when no exercise is open or it cannot load.
    std::shared_ptr<const Mesh> exerciseStartMesh();
    // The exercise replaces the scene (asking first about unsaved changes): A its start, B its target.
    void openExercise(LoadedExercise loaded, std::optional<std::string> bundledName);
    // The exercise `draft` and the scene make, as saved (nullopt with the reasons when it is not one).
    std::optional<Exercise> draftExercise(Diagnostics& diagnostics) const;
    // Counts the scenes opened (files, links): what belonged to the last scene can be dropped.
    unsigned scenesOpened() const { return scenesOpened_; }
    // What the open document's file (or slide) says of its display (preset.h OpeningDisplay).
    const OpeningDisplay& openedDisplay() const { return opened_; }

    //--- fitting (core/plots/fit.h, workspace_fit.cpp) -------------------------------------
    // What B is while it is the fit of A that a Fit command made and neither has changed since:
    // "Blinn-Phong fitted to A, error 23.5%: shininess 67.9, specular × 0.988". Empty otherwise.
    const std::string& fitNote();

    //--- a question for the user: discard unsaved changes? -------------------------------
    const std::optional<std::string>& question() const { return question_; } // "open x.json", "quit"
    void answer(UnsavedAnswer answer);
    bool quit() const { return quit_; }

    //--- what the app shows ---------------------------------------------------------------
    std::vector<Problem> takeProblems() { return std::exchange(problems_, {}); }
    std::vector<std::string> takeNotes() { return std::exchange(notes_, {}); }
    void note(std::string text) { notes_.push_back(std::move(text)); } // for the toast
    std::vector<Download> takeDownloads() { return std::exchange(downloads_, {}); }

    // The mesh of A's or B's model. A model edit that cannot load is undone with a problem.
    std::shared_ptr<const Mesh> mesh(Side side);

    // The current scene as a preset link, recomputed only when the scene changed.
    const std::string& link();
    // Whether that link can be shared (at most kMaxLinkChars); when not, a problem says why and
    // how long it is (the page keeps such a scene in its saved state only).
    bool linkShareable();

private:
    struct Resolved {
        Model model;
        std::filesystem::path folder;
        std::shared_ptr<const Mesh> mesh;
    };
    std::shared_ptr<const Mesh> resolve(Model& model, Resolved& resolved, const char* which);
    bool waitsFor(const std::filesystem::path& file, std::string title, std::function<void()> again);
    bool waitsFor(const Model& model, const std::filesystem::path& folder, std::string title, std::function<void()> again);
    bool runEdit(Command command);
    void stepPreset(int delta);
    void openFile(const std::filesystem::path& file, bool asSlide);
    void openDeck(const std::filesystem::path& file);
    // The slide `key` becomes the scene: its kept edits, else `loaded` as opened.
    void enterSlide(const std::string& key, const LoadedPreset& loaded, const OpeningDisplay& display,
                    const std::filesystem::path& folder);
    void keepSlide();
    void stepTo(int index); // goToSlide once nothing would be lost
    std::string slideKeyOf(const std::filesystem::path& file) const;
    int slidesEdited() const; // the slides kept with unsaved edits, and the document if it is one
    bool saveEverySlide();
    bool save(const std::string& saveAsField);
    bool isShipped(const std::filesystem::path& file) const;
    void download();
    void refreshPresetList();
    // `action` now when nothing would be lost (a slide's edits are kept), else after the question.
    // `replacesScene`: the action opens another scene (quitting does not).
    void whenChangesAreSafe(std::string what, std::function<void()> action, bool replacesScene = true);
    void adopt(Preset preset, std::filesystem::path file, std::filesystem::path folder,
               std::optional<Preset> compare = {});
    void adopt(const LoadedPreset& loaded);
    void problem(std::string title, Diagnostics diagnostics);
    void problem(std::string title, std::string message);
    std::filesystem::path bundledFolder() const;
    bool runExercise(const Request& request);
    bool runFit(const Request& request);
    void keepExercise();
    void saveExercise(const std::string& path);

    WorkspaceOptions options_;
    Document doc_;
    MeshCache meshes_;
    std::array<Resolved, 2> resolved_; // A's and B's
    std::vector<std::filesystem::path> presetFiles_;
    std::vector<std::filesystem::path> exerciseFiles_;
    // The shipped presets as start() found them: only these are linked by name (the page moves an
    // uploaded file into the same folder, and no one else's page has it).
    std::vector<std::filesystem::path> shipped_;
    int currentPreset_ = -1;
    std::optional<Deck> deck_;
    int currentDeckSlide_ = -1;
    std::string slideKey_; // the slide the document is ("" when it is not one)
    struct KeptSlide {
        Document doc;
        DisplaySettings view;
        OpeningDisplay opened;
    };
    std::map<std::string, KeptSlide> slides_; // the slides left with their edits, by key
    OpeningDisplay opened_;                   // the display the document was opened with
    std::optional<std::string> question_;
    std::function<void()> pending_;
    struct Waiting {
        std::filesystem::path file; // the site's file being fetched
        std::string title;          // the problem's title if it cannot be
        std::function<void()> again;
    };
    std::optional<Waiting> waiting_;
    bool quit_ = false;
    std::vector<Problem> problems_;
    std::vector<std::string> notes_;
    std::vector<Download> downloads_;
    int screenshots_ = 0;
    int figureFolders_ = 0;
    unsigned scenesOpened_ = 0;
    std::optional<ExerciseSession> exercise_;
    unsigned exercisesOpened_ = 0;
    Preset kept_; // the attempt as last checked against the exercise's open fields
    std::string exerciseLink_;
    unsigned exerciseLinkFor_ = 0; // ExerciseSession::opened of exerciseLink_
    std::optional<ExerciseDraft> draft_;
    struct {
        SurfaceUniforms a; // A's material and BRDF the fit was made from
        Preset b;          // the fit, as it went into B
        std::string note;  // empty: no fit
    } fit_;
    struct {
        std::string text;
        Preset preset;
        std::filesystem::path file;
        bool valid = false;
    } link_;
};

} // namespace lab
