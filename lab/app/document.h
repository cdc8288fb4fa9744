// document.h — the preset being edited: where it lives, what is on disk, and its history.
//
// The GUI edits `preset` (set A) and `compare` (set B, compare mode's second set) in place, every
// frame, through plain references. The document turns those edits into undo steps by comparing
// snapshots of both: commit() at the end of a frame records the change since the last step,
// unless the user is still in the middle of a gesture (a slider drag, a camera orbit), so one
// drag is one step, and undo walks back through A's and B's edits in the order they were made.
// Only A is saved: dirty() looks at A alone, and not at its camera: looking around is not an
// unsaved change (it is still undoable, and saved with the next save). No GL and no ImGui here.
#pragma once

#include "core/scene/preset.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab {

class Document {
public:
    Document();

    // Replaces everything: a freshly opened file (or the defaults when `file` is empty); B becomes
    // `compare` when given (a prepared comparison), else a copy of A. The history starts anew.
    // `folder` is where glTF paths resolve when untitled.
    void reset(Preset preset, std::filesystem::path file, std::filesystem::path folder = {},
               std::optional<Preset> compare = {});

    Preset preset;  // set A, edited in place by the UI; what is saved
    Preset compare; // set B, compare mode's second set; never saved

    const std::filesystem::path& file() const { return file_; }
    std::filesystem::path folder() const;
    std::string displayName() const; // file name, or the preset's name when untitled
    bool dirty() const;
    // Whether A or B differs from what was opened (the camera aside): the caption's "(edited)".
    bool edited() const;
    const Preset& saved() const { return saved_; }
    const Preset& savedCompare() const { return savedCompare_; }

    // Records the edits since the last step as one undo step, unless `gestureInProgress`.
    // Returns true if a step was recorded.
    bool commit(bool gestureInProgress);

    bool canUndo() const { return !undo_.empty() || current() != committed_; }
    bool canRedo() const { return !redo_.empty(); }
    bool undo();
    bool redo();
    std::size_t undoDepth() const { return undo_.size(); }

    // After a successful save to `file` (which may be a new path: save-as).
    void markSaved(std::filesystem::path file);

    // Back to what is on disk (or the defaults), as one undoable step; `andCompare`: B too, to
    // what it was opened as (a deck's "Reset slide").
    void revert(bool andCompare = false);

    void setFolder(std::filesystem::path folder) { folder_ = std::move(folder); }

    static constexpr std::size_t kMaxHistory = 500;

private:
    struct Snapshot {
        Preset a, b;
        bool operator==(const Snapshot&) const = default;
    };
    Snapshot current() const { return {preset, compare}; }
    void restore(const Snapshot& s);
    // Moves the current state onto `to` and the top of `from` into the current state.
    bool step(std::vector<Snapshot>& from, std::vector<Snapshot>& to);

    std::filesystem::path file_;
    std::filesystem::path folder_; // for untitled documents
    Preset saved_;
    Preset savedCompare_; // B as it was opened
    Snapshot committed_; // the state after the last recorded step
    std::vector<Snapshot> undo_, redo_;
};

} // namespace lab
