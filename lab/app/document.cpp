// document.cpp — snapshot undo/redo and the saved state.
#include "app/document.h"

namespace lab {

namespace fs = std::filesystem;

Document::Document() { reset(Preset{}, {}); }

void Document::reset(Preset p, fs::path file, fs::path folder, std::optional<Preset> b) {
    preset = std::move(p);
    compare = b ? std::move(*b) : preset;
    compare.camera = preset.camera;
    savedCompare_ = compare;
    file_ = std::move(file);
    folder_ = std::move(folder);
    saved_ = preset;
    committed_ = current();
    undo_.clear();
    redo_.clear();
}

fs::path Document::folder() const {
    if (!file_.empty()) {
        return file_.parent_path().empty() ? fs::path(".") : file_.parent_path();
    }
    return folder_.empty() ? fs::path(".") : folder_;
}

bool Document::dirty() const {
    Preset a = preset;
    a.camera = saved_.camera;
    return a != saved_;
}

bool Document::edited() const {
    Preset b = compare;
    b.camera = savedCompare_.camera;
    return dirty() || b != savedCompare_;
}

std::string Document::displayName() const { return file_.empty() ? preset.name : file_.filename().string(); }

bool Document::commit(bool gestureInProgress) {
    if (gestureInProgress || current() == committed_) {
        return false;
    }
    undo_.push_back(std::move(committed_));
    if (undo_.size() > kMaxHistory) {
        undo_.erase(undo_.begin());
    }
    redo_.clear();
    committed_ = current();
    return true;
}

void Document::restore(const Snapshot& s) {
    preset = s.a;
    compare = s.b;
}

bool Document::step(std::vector<Snapshot>& from, std::vector<Snapshot>& to) {
    if (from.empty()) {
        return false;
    }
    to.push_back(std::move(committed_));
    committed_ = std::move(from.back());
    from.pop_back();
    restore(committed_);
    return true;
}

bool Document::undo() {
    commit(false); // an edit not yet recorded is undone first
    return step(undo_, redo_);
}

bool Document::redo() { return step(redo_, undo_); }

void Document::markSaved(fs::path file) {
    file_ = std::move(file);
    saved_ = preset;
}

void Document::revert(bool andCompare) {
    commit(false);
    preset = saved_;
    if (andCompare) {
        compare = savedCompare_;
        compare.camera = preset.camera;
    }
    commit(false);
}

} // namespace lab
