// workspace_exercise.cpp — the workspace's exercises: open one, keep the attempt to its open
// fields, start again, hints, leave; "Make exercise" and saving the draft (app/workspace.h).
#include "app/workspace.h"

#include "core/io/file_io.h"
#include "core/io/safe_text.h"

namespace lab {

namespace fs = std::filesystem;

bool Workspace::runExercise(const Request& r) {
    switch (r.command) {
    case Command::ExerciseReset:
        if (exercise_) {
            Camera camera = doc_.preset.camera; // looking around is kept
            doc_.preset = exercise_->exercise.start;
            doc_.preset.camera = camera;
            notes_.push_back("Back at the start of the exercise (Undo brings your attempt back)");
        }
        return true;
    case Command::ExerciseHint:
        if (exercise_ && exercise_->hintsShown < static_cast<int>(exercise_->exercise.hints.size())) {
            ++exercise_->hintsShown;
        }
        return true;
    case Command::ExerciseLeave:
        if (exercise_) {
            exercise_.reset();
            view.compare = false;
            notes_.push_back("Left the exercise: the attempt is an ordinary scene now");
        }
        return true;
    case Command::MakeExercise:
        if (draft_) {
            draft_.reset();
        } else {
            draft_ = ExerciseDraft{};
            draft_->target = doc_.preset;
            if (!doc_.preset.name.empty() && doc_.preset.name != "Untitled") {
                draft_->title = doc_.preset.name;
            }
            notes_.push_back("Making an exercise: this scene is the target. Tick the fields students may change, "
                             "set them to where students start, then save.");
        }
        return true;
    case Command::SaveExercise: saveExercise(r.path); return true;
    default: return false;
    }
}

std::shared_ptr<const Mesh> Workspace::exerciseStartMesh() {
    if (!exercise_) {
        return nullptr;
    }
    const Model& start = exercise_->exercise.start.model;
    for (Side side : {Side::A, Side::B}) {
        if (preset(side).model == start) {
            return mesh(side);
        }
    }
    Diagnostics ignored; // (it loaded when the exercise opened; a file gone since scores nothing)
    return meshes_.get(start, doc_.folder(), ignored);
}

void Workspace::openExercise(LoadedExercise loaded, std::optional<std::string> bundledName) {
    whenChangesAreSafe("open the exercise " + loaded.exercise.title,
                       [this, loaded = std::move(loaded), bundledName = std::move(bundledName)]() {
        fs::path folder = loaded.file.empty() ? bundledFolder() : loaded.folder();
        Preset start = loaded.exercise.start;
        start.name = loaded.exercise.title; // (free fields) the header and the caption say what the exercise is
        start.description = loaded.exercise.instructions;
        adopt(start, {}, folder);
        exercise_ = ExerciseSession{loaded.exercise, loaded.file, bundledName, 0, ++exercisesOpened_};
        kept_ = doc_.preset;
        doc_.compare = loaded.exercise.target;
        view.compare = true;
        view.editingB = false;
        draft_.reset();
        notes_.push_back("Exercise: " + loaded.exercise.title);
    });
}

void Workspace::keepExercise() {
    if (!exercise_) {
        return;
    }
    view.compare = true; // the target stays beside the attempt
    view.editingB = false;
    doc_.compare = exercise_->exercise.target;
    if (doc_.preset != kept_) {
        doc_.preset = withLockedFieldsOfStart(exercise_->exercise, doc_.preset);
        kept_ = doc_.preset;
    }
}

std::optional<Exercise> Workspace::draftExercise(Diagnostics& diagnostics) const {
    if (!draft_) {
        return std::nullopt;
    }
    Exercise e;
    e.title = draft_->title;
    e.instructions = draft_->instructions;
    e.start = doc_.preset;
    e.target = draft_->target;
    e.target.camera = e.start.camera; // the camera is always free: the target is seen as the student starts
    e.open = draft_->open;
    std::size_t from = 0;
    while (from <= draft_->hints.size()) {
        std::size_t end = draft_->hints.find('\n', from);
        std::string line = draft_->hints.substr(from, end == std::string::npos ? std::string::npos : end - from);
        if (!line.empty()) {
            e.hints.push_back(line);
        }
        if (end == std::string::npos) {
            break;
        }
        from = end + 1;
    }
    // Read back as a file would be: the same checks, the same messages.
    std::optional<Exercise> checked = parseExercise(exerciseToJson(e), e.title, doc_.folder(), diagnostics);
    return checked;
}

void Workspace::saveExercise(const std::string& path) {
    Diagnostics d;
    std::optional<Exercise> e = draftExercise(d);
    if (!e) {
        problem("Not an exercise yet (nothing was saved)", std::move(d));
        return;
    }
    std::string text = exerciseToJson(*e);
    if (options_.saveByDownload) {
        downloads_.push_back({safeStem(e->title) + ".json", text});
        notes_.push_back("Downloaded the exercise " + e->title);
        draft_.reset();
        openExercise(LoadedExercise{*e, {}}, std::nullopt);
        return;
    }
    if (path.empty()) {
        problem("Save exercise", "type the exercise's path in the field beside the button, e.g. exercises/shininess.json");
        return;
    }
    fs::path file = path;
    if (isShipped(file)) {
        problem("Cannot save " + file.string(), "this folder holds the shipped presets, which stay as they are; save elsewhere");
        return;
    }
    std::string error;
    if (!e->start.model.gltf.empty()) {
        problem("Cannot save " + file.string(), "an exercise made in the lab uses a built-in model; write a glTF exercise by hand (model paths relative to its file)");
        return;
    }
    if (!writeFileAtomic(file, text, error)) {
        problem("Cannot save " + file.string() + " (nothing was written)", error);
        return;
    }
    draft_.reset();
    doc_.markSaved(doc_.file()); // the start's edits belong to the exercise now
    notes_.push_back("Saved the exercise " + file.string() + ": opened as a student sees it");
    openExercise(LoadedExercise{*e, file}, std::nullopt);
}

} // namespace lab
