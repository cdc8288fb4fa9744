// workspace.cpp — files, links, commands and meshes of the editing state.
#include "app/workspace.h"

#include "core/exercise/preset_fields.h"
#include "core/gltf/model_loader.h"
#include "core/io/file_io.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"
#include "core/scene/camera.h"
#include "core/scene/preset_choices.h"
#include "core/share/share_link.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace lab {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> listPresets(const fs::path& folder) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
        if (e.is_regular_file(ec) && e.path().extension() == ".json") {
            files.push_back(e.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

bool hasExtension(const fs::path& p, std::initializer_list<const char*> extensions) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return std::any_of(extensions.begin(), extensions.end(), [&](const char* x) { return e == x; });
}

} // namespace

std::string safeStem(const std::string& stem) {
    std::string name;
    for (char c : stem) {
        name += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '-';
    }
    return name;
}

fs::path defaultUserFolder() {
    const char* data = std::getenv("XDG_DATA_HOME");
    if (data && *data == '/') {
        return fs::path(data) / "lighting-lab" / "presets";
    }
    const char* home = std::getenv("HOME");
    if (home && *home == '/') {
        return fs::path(home) / ".local" / "share" / "lighting-lab" / "presets";
    }
    return fs::path("lighting-lab-presets");
}

Workspace::Workspace(WorkspaceOptions options) : options_(std::move(options)) {}

void Workspace::start(const fs::path& folder, const std::optional<fs::path>& preset) {
    Preset defaults;
    defaults.name = "Default";
    doc_.reset(defaults, {}, folder);
    resolved_ = {};
    std::error_code ec;
    shipped_ = fs::is_directory(bundledFolder(), ec) ? listPresets(bundledFolder()) : std::vector<fs::path>{};
    refreshPresetList();
    if (preset && fs::is_directory(*preset, ec)) { // a folder is a deck of its presets, in name order
        std::vector<fs::path> files = listPresets(*preset);
        if (files.empty()) {
            problem("Cannot open " + preset->string(), "the folder holds no preset (.json) files");
        } else {
            openFile(files.front(), true);
        }
    } else if (preset) {
        open(*preset);
    }
}

//----------------------------------------------------------------------------------------
// Problems and questions
//----------------------------------------------------------------------------------------

void Workspace::problem(std::string title, Diagnostics diagnostics) {
    problems_.push_back({std::move(title), std::move(diagnostics)});
}

void Workspace::problem(std::string title, std::string message) {
    problem(std::move(title), Diagnostics{{"", "", std::move(message)}});
}

void Workspace::whenChangesAreSafe(std::string what, std::function<void()> action, bool replacesScene) {
    doc_.commit(false);
    if (replacesScene && onSlide()) { // the slide's edits stay with it (workspace_slides.cpp)
        keepSlide();
        action();
        return;
    }
    if (replacesScene ? !doc_.dirty() : slidesEdited() == 0) {
        action();
        return;
    }
    pending_ = std::move(action);
    question_ = std::move(what);
}

void Workspace::answer(UnsavedAnswer answer) {
    if (!question_) {
        return; // answered already (the canvas's dialog and the page's buttons answer the same question)
    }
    std::function<void()> action = std::exchange(pending_, nullptr);
    const bool quitting = question_ == "quit";
    question_.reset();
    bool saved = answer == UnsavedAnswer::SaveFirst && (quitting ? saveEverySlide() : save({}));
    if (action && (answer == UnsavedAnswer::Discard || saved)) {
        action();
    }
}

void Workspace::requestQuit() {
    whenChangesAreSafe("quit", [this]() { quit_ = true; }, false);
}

//----------------------------------------------------------------------------------------
// Commands
//----------------------------------------------------------------------------------------

bool Workspace::run(const Request& r) {
    switch (r.command) {
    case Command::PreviousPreset: stepPreset(-1); return true;
    case Command::NextPreset: stepPreset(+1); return true;
    case Command::OpenPresetAt: goToSlide(r.index); return true;
    case Command::FirstSlide: goToSlide(0); return true;
    case Command::LastSlide: goToSlide(slideCount() - 1); return true;
    case Command::ResetSlide: resetSlide(); return true;
    case Command::OpenPath: open(r.path); return true;
    case Command::Save: save(r.path); return true;
    case Command::SaveAs:
        if (r.path.empty()) {
            problem("Save as", "type the new path in the \"Save as\" field, then press Enter");
        } else {
            saveTo(r.path);
        }
        return true;
    case Command::LoadModel: useModel(r.path); return true;
    case Command::DownloadPreset: download(); return true;
    case Command::Revert: doc_.revert(true); return true;
    case Command::Undo: doc_.undo(); return true;
    case Command::Redo: doc_.redo(); return true;
    default: return runExercise(r) || runFit(r) || runEdit(r.command);
    }
}

// The commands that edit the scene or how it is shown.
bool Workspace::runEdit(Command command) {
    Preset& e = edited();
    switch (command) {
    case Command::ShadingFlat: e.shading = Shading::Flat; return true;
    case Command::ShadingGouraud: e.shading = Shading::Gouraud; return true;
    case Command::ShadingPhong: e.shading = Shading::Phong; return true;
    case Command::NextBrdf: e.brdf = nextOf(kBrdfModels, e.brdf); return true;
    case Command::ToggleNormalMatrix: e.normalMatrix = nextOf(kNormalMatrixModes, e.normalMatrix); return true;
    case Command::NextViewMode: // the views that apply to the edited set (the lit model always does)
    case Command::PreviousViewMode:
        do {
            view.mode = command == Command::NextViewMode ? nextOf(kViewModes, view.mode) : previousOf(kViewModes, view.mode);
        } while (!notApplicable(view.mode, e, view.light).empty());
        return true;
    case Command::ToggleWireframe: view.wireframe = !view.wireframe; return true;
    case Command::ToggleVertexNormals: view.vertexNormals = !view.vertexNormals; return true;
    case Command::ResetCamera: doc_.preset.camera = doc_.saved().camera; return true;
    case Command::FrameModel: frameModel(); return true;
    // One step of the page's camera buttons: 15 degrees, or a fifth of the distance.
    case Command::OrbitLeft: orbitCamera(doc_.preset.camera, -15.0f, 0.0f); return true;
    case Command::OrbitRight: orbitCamera(doc_.preset.camera, 15.0f, 0.0f); return true;
    case Command::OrbitUp: orbitCamera(doc_.preset.camera, 0.0f, 15.0f); return true;
    case Command::OrbitDown: orbitCamera(doc_.preset.camera, 0.0f, -15.0f); return true;
    case Command::ZoomIn: zoomCamera(doc_.preset.camera, 0.8f); return true;
    case Command::ZoomOut: zoomCamera(doc_.preset.camera, 1.25f); return true;
    case Command::ToggleCompare:
        if (exercise_) {
            notes_.push_back("In an exercise the target stays beside your attempt (Leave exercise to compare freely)");
            return true;
        }
        view.compare = !view.compare;
        view.editingB = false;
        if (view.compare) { // a useful first comparison: the other shading mode
            doc_.compare = doc_.preset;
            doc_.compare.shading = doc_.preset.shading == Shading::Phong ? Shading::Gouraud : Shading::Phong;
        }
        return true;
    default: return false;
    }
}

//----------------------------------------------------------------------------------------
// Files
//----------------------------------------------------------------------------------------

fs::path Workspace::bundledFolder() const {
    return options_.presetFolders.empty() ? fs::path(".") : options_.presetFolders.front();
}

void Workspace::refreshPresetList() {
    presetFiles_.clear();
    std::error_code missing;
    exerciseFiles_ = fs::is_directory(bundledFolder() / "exercises", missing) ? listPresets(bundledFolder() / "exercises")
                                                                             : std::vector<fs::path>{};
    std::vector<fs::path> folders;
    if (!doc_.file().empty()) {
        folders.push_back(doc_.folder());
    }
    folders.insert(folders.end(), options_.presetFolders.begin(), options_.presetFolders.end());
    for (const fs::path& f : folders) {
        std::error_code ec;
        if (fs::is_directory(f, ec) && !(presetFiles_ = listPresets(f)).empty()) {
            break;
        }
    }
    currentPreset_ = -1;
    std::error_code ec;
    for (std::size_t i = 0; i < presetFiles_.size() && !doc_.file().empty(); ++i) {
        if (fs::equivalent(presetFiles_[i], doc_.file(), ec)) {
            currentPreset_ = static_cast<int>(i);
        }
    }
}

// The scene becomes `preset`: a new history, B its prepared comparison (or `compare`, or a copy of
// A), the display as the file asks.
void Workspace::adopt(Preset preset, fs::path file, fs::path folder, std::optional<Preset> compare) {
    if (exercise_) {
        exercise_.reset();
        view.compare = false;
    }
    if (!compare) {
        Diagnostics d; // (checked when the file was read: only a file changed since could fail)
        compare = comparedPreset(preset, file.empty() ? folder : file.parent_path(), d);
        if (!compare) {
            problem("Cannot make the prepared comparison of " + preset.name + " (B is a copy of A)", std::move(d));
        }
    }
    opened_ = preset.display;
    doc_.reset(std::move(preset), std::move(file), std::move(folder), std::move(compare));
    slideKey_.clear();
    currentDeckSlide_ = -1;
    ++scenesOpened_;
    refreshPresetList();
    showAsOpened();
}

// Loads and checks everything first; the scene changes only when all of it worked.
void Workspace::open(const fs::path& file) { openFile(file, false); }

// `asSlide`: a file of the preset list, stepped to (workspace_slides.cpp): opened without asking.
void Workspace::openFile(const fs::path& file, bool asSlide) {
    waiting_.reset();
    Diagnostics d;
    std::string error;
    std::optional<std::string> text = readFile(file, kMaxDeckBytes, error);
    if (text && isDeckText(*text)) {
        openDeck(file);
        return;
    }
    if (text && text->size() <= kMaxExerciseBytes && isExerciseText(*text)) {
        std::optional<LoadedExercise> exercise = loadExercise(file, d);
        if (!exercise) {
            problem("Cannot open " + file.filename().string() + " (nothing was changed)", std::move(d));
            return;
        }
        const std::string title = "Cannot load the model of " + file.filename().string() + " (nothing was changed)";
        if (waitsFor(exercise->exercise.start.model, exercise->folder(), title, [this, file, asSlide] { openFile(file, asSlide); }) ||
            waitsFor(exercise->exercise.target.model, exercise->folder(), title, [this, file, asSlide] { openFile(file, asSlide); })) {
            return;
        }
        if (!meshes_.get(exercise->exercise.start.model, exercise->folder(), d)) {
            problem(title, std::move(d));
            return;
        }
        std::optional<std::string> bundled;
        std::error_code ec;
        if (fs::equivalent(exercise->folder(), bundledFolder() / "exercises", ec)) {
            bundled = file.stem().string();
        }
        openExercise(std::move(*exercise), bundled);
        return;
    }
    std::optional<LoadedPreset> loaded = loadPreset(file, d);
    if (!loaded) {
        problem("Cannot open " + file.filename().string() + " (nothing was changed)", std::move(d));
        return;
    }
    const std::string title = "Cannot load the model of " + file.filename().string() + " (nothing was changed)";
    if (waitsFor(loaded->preset.model, loaded->folder(), title, [this, file, asSlide] { openFile(file, asSlide); })) {
        return;
    }
    if (!meshes_.get(*loaded, d)) { // (a glTF model without a camera in the file is framed here)
        problem(title, std::move(d));
        return;
    }
    if (asSlide) {
        enterSlide(slideKeyOf(file), *loaded, loaded->preset.display, {});
        return;
    }
    whenChangesAreSafe("open " + file.filename().string(), [this, loaded = std::move(*loaded)]() {
        adopt(loaded);
        notes_.push_back("Opened " + loaded.file.filename().string());
    });
}

bool Workspace::saveTo(const fs::path& file) {
    if (isShipped(file)) {
        problem("Cannot save " + file.string(), "this folder holds the shipped presets, which stay as they are; save elsewhere (Save writes a copy to " + options_.userFolder.string() + ")");
        return false;
    }
    doc_.commit(false);
    Preset toSave = doc_.preset;
    if (!toSave.model.gltf.empty()) {
        // glTF paths are relative to the preset: rebase them onto the new folder.
        fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
        std::optional<fs::path> relative = relativeInside(folder, doc_.folder() / toSave.model.gltf);
        if (!relative) {
            problem("Cannot save " + file.string(),
                    "the model " + toSave.model.gltf + " would be outside the preset's folder " +
                        canonicalFolder(folder).string() + "; save the preset in the model's folder or above it");
            return false;
        }
        toSave.model.gltf = relative->generic_string();
    }
    Diagnostics d;
    if (!savePreset(toSave, file, d)) {
        problem("Cannot save " + file.string() + " (the old file is unchanged)", std::move(d));
        return false;
    }
    doc_.preset = toSave;
    doc_.commit(false);
    doc_.markSaved(file);
    refreshPresetList();
    notes_.push_back("Saved " + file.string());
    return true;
}

bool Workspace::isShipped(const fs::path& file) const {
    return std::any_of(options_.presetFolders.begin(), options_.presetFolders.end(),
                       [&](const fs::path& folder) { return isInside(folder, file); });
}

// To the document's file; a shipped preset's edits go to a copy in the user's folder instead.
bool Workspace::save(const std::string& saveAsField) {
    if (options_.saveByDownload) {
        download();
        return true;
    }
    if (!doc_.file().empty() && isShipped(doc_.file()) && !options_.userFolder.empty()) {
        std::error_code ec;
        fs::create_directories(options_.userFolder, ec);
        fs::path copy = options_.userFolder / doc_.file().filename();
        if (!saveTo(copy)) {
            return false;
        }
        notes_.push_back("Shipped presets stay as they are: saved a copy as " + copy.string()); // the toast shows the last note
        return true;
    }
    if (!doc_.file().empty()) {
        return saveTo(doc_.file());
    }
    if (!saveAsField.empty()) {
        return saveTo(saveAsField);
    }
    problem("Nothing to save to", "this preset has no file yet: type a path in the \"Save as\" field");
    return false;
}

void Workspace::download() {
    doc_.commit(false);
    std::string name = safeStem(doc_.file().empty() ? doc_.preset.name : doc_.file().stem().string());
    downloads_.push_back({(name.empty() ? "preset" : name) + ".json", presetToJson(doc_.preset)});
    doc_.markSaved(doc_.file());
    notes_.push_back("Downloaded " + downloads_.back().name);
}

void Workspace::drop(const std::vector<std::string>& files) {
    for (const std::string& f : files) {
        if (hasExtension(f, {".json"})) {
            open(f);
        } else if (hasExtension(f, {".gltf", ".glb"})) {
            useModel(f);
        } else {
            problem("Cannot open " + fs::path(f).filename().string(), "drop a preset (.json) or a glTF model (.gltf, .glb)");
        }
    }
}

namespace {

// The first `folder/<stem>-NNN<extension>` that does not exist, numbering on from `counter`.
fs::path unusedPath(const fs::path& folder, const std::string& stem, const std::string& extension, int& counter) {
    std::error_code ec;
    fs::path path;
    do {
        char number[16];
        std::snprintf(number, sizeof number, "-%03d", ++counter);
        path = folder / (stem + number + extension);
    } while (fs::exists(path, ec));
    return path;
}

} // namespace

void Workspace::saveScreenshot(const Image& image, const std::string& suffix, const std::string& what) {
    std::string stem = (doc_.file().empty() ? "lab" : doc_.file().stem().string()) + suffix;
    std::error_code ec;
    fs::create_directories(options_.screenshotFolder, ec);
    const fs::path file = unusedPath(options_.screenshotFolder, stem, ".png", screenshots_);
    if (options_.saveByDownload) {
        downloads_.push_back({file.filename().string(), encodePng(image)});
        notes_.push_back(what + " " + file.filename().string() + " downloaded");
        return;
    }
    std::string error;
    if (!writePng(image, file, error)) {
        problem(what + " failed", error);
        return;
    }
    notes_.push_back(what + " " + file.string());
}

void Workspace::saveFiles(const std::vector<Download>& files, const std::string& what) {
    std::string stem = doc_.file().empty() ? "lab" : doc_.file().stem().string();
    if (options_.saveByDownload) {
        for (const Download& f : files) {
            downloads_.push_back({stem + "-" + f.name, f.bytes});
        }
        notes_.push_back(what + ": " + std::to_string(files.size()) + " files downloaded");
        return;
    }
    std::error_code ec;
    const fs::path folder = unusedPath(options_.screenshotFolder, stem + "-figures", "", figureFolders_);
    fs::create_directories(folder, ec);
    if (ec) {
        problem(what + " failed", "cannot create " + folder.string() + ": " + ec.message());
        return;
    }
    for (const Download& f : files) {
        std::string error;
        if (!writeFileAtomic(folder / f.name, f.bytes, error)) {
            problem(what + " failed", error);
            return;
        }
    }
    notes_.push_back(what + ": " + std::to_string(files.size()) + " files in " + folder.string());
}

//----------------------------------------------------------------------------------------
// Links (the browser's URL fragment and saved state)
//----------------------------------------------------------------------------------------

void Workspace::openLink(const std::string& fragment, bool saved) {
    waiting_.reset();
    const std::string_view deck = std::string_view(fragment).substr(fragment.starts_with('#') ? 1 : 0);
    if (deck.starts_with("deck=")) { // a bundled deck by name (presets/decks/): the lecture, to step through again
        const std::string name(deck.substr(5));
        std::error_code ec;
        const fs::path file = bundledFolder() / "decks" / (name + ".json");
        if (name.empty() || safeStem(name) != name || !fs::is_regular_file(file, ec)) {
            problem("Cannot open the link (nothing was changed)", "there is no bundled deck " + inQuotes(name, 60));
            return;
        }
        open(file);
        return;
    }
    Diagnostics d;
    OmittedKeys omitted;
    auto parsed = parseLink(fragment, bundledFolder(), d, &omitted, saved ? kMaxSavedLinkChars : kMaxLinkChars);
    if (!parsed) {
        problem("Cannot open the link (nothing was changed)", std::move(d));
        return;
    }
    if (auto* name = std::get_if<LinkedExerciseName>(&*parsed)) {
        fs::path file = bundledFolder() / "exercises" / (name->name + ".json");
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) {
            problem("Cannot open the link (nothing was changed)", "there is no bundled exercise " + inQuotes(name->name));
            return;
        }
        open(file);
        return;
    }
    auto again = [this, fragment, saved] { openLink(fragment, saved); };
    if (auto* exercise = std::get_if<Exercise>(&*parsed)) {
        const char* title = "Cannot load the linked exercise's model (nothing was changed)";
        if (waitsFor(exercise->start.model, bundledFolder(), title, again) || waitsFor(exercise->target.model, bundledFolder(), title, again)) {
            return;
        }
        if (!meshes_.get(exercise->start.model, bundledFolder(), d)) {
            problem(title, std::move(d));
            return;
        }
        openExercise(LoadedExercise{*exercise, {}}, std::nullopt);
        return;
    }
    if (auto* name = std::get_if<LinkedPresetName>(&*parsed)) {
        fs::path file = bundledFolder() / (name->name + ".json");
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) {
            problem("Cannot open the link (nothing was changed)", "there is no bundled preset " + inQuotes(name->name));
            return;
        }
        open(file);
        return;
    }
    LoadedPreset linked{std::get<Preset>(*parsed), {}, omitted};
    const char* title = "Cannot load the linked preset's model (nothing was changed)";
    if (waitsFor(linked.preset.model, bundledFolder(), title, again)) {
        return;
    }
    std::shared_ptr<const Mesh> mesh = meshes_.get(linked.preset.model, bundledFolder(), d);
    if (!mesh) {
        problem(title, std::move(d));
        return;
    }
    frameOmitted(linked, *mesh); // a glTF model without a camera in the link is framed as a file's is
    whenChangesAreSafe("open the link", [this, preset = linked.preset]() { adopt(preset, {}, bundledFolder()); });
}

const std::string& Workspace::link() {
    if (exercise_) { // students open the exercise at its start, not the instructor's attempt
        if (exerciseLinkFor_ != exercise_->opened) {
            exerciseLink_ = exerciseLink(exercise_->exercise, exercise_->bundledName);
            exerciseLinkFor_ = exercise_->opened;
        }
        return exerciseLink_;
    }
    if (!link_.valid || link_.preset != doc_.preset || link_.file != doc_.file()) {
        std::optional<std::string> bundled;
        std::error_code ec;
        bool shipped = std::any_of(shipped_.begin(), shipped_.end(), [&](const fs::path& f) { return fs::equivalent(f, doc_.file(), ec); });
        if (!doc_.dirty() && !doc_.file().empty() && shipped) {
            bundled = doc_.file().stem().string();
        }
        link_ = {presetLink(doc_.preset, bundled), doc_.preset, doc_.file(), true};
    }
    return link_.text;
}

bool Workspace::linkShareable() {
    const std::size_t length = link().size();
    if (length > kMaxLinkChars) {
        problem("Cannot copy the link", "This scene's link would be " + std::to_string(length) + " characters, more than the " +
                                            std::to_string(kMaxLinkChars) + " a link may have. The scene stays in this "
                                            "browser (it comes back on a reload), but it cannot be shared as a link: shorten "
                                            "its description or the exercise's text, or download the file and share that.");
    }
    return length <= kMaxLinkChars;
}

} // namespace lab
