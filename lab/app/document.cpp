// document.cpp — snapshot undo/redo and the saved state.
#include "app/document.h"

namespace lab {

namespace fs = std::filesystem;

Document::Document() { reset(Preset{}, {}); }

void Document::reset(Preset p, fs::path file, fs::path folder) {
    preset = std::move(p);
    file_ = std::move(file);
    folder_ = std::move(folder);
    saved_ = preset;
    committed_ = preset;
    undo_.clear();
    redo_.clear();
}

fs::path Document::folder() const {
    if (!file_.empty()) {
        return file_.parent_path().empty() ? fs::path(".") : file_.parent_path();
    }
    return folder_.empty() ? fs::path(".") : folder_;
}

std::string Document::displayName() const { return file_.empty() ? preset.name : file_.filename().string(); }

bool Document::commit(bool gestureInProgress) {
    if (gestureInProgress || preset == committed_) {
        return false;
    }
    undo_.push_back(committed_);
    if (undo_.size() > kMaxHistory) {
        undo_.erase(undo_.begin());
    }
    redo_.clear();
    committed_ = preset;
    return true;
}

bool Document::undo() {
    commit(false); // an edit not yet recorded is undone first
    if (undo_.empty()) {
        return false;
    }
    redo_.push_back(committed_);
    committed_ = undo_.back();
    undo_.pop_back();
    preset = committed_;
    return true;
}

bool Document::redo() {
    if (redo_.empty()) {
        return false;
    }
    undo_.push_back(committed_);
    committed_ = redo_.back();
    redo_.pop_back();
    preset = committed_;
    return true;
}

void Document::markSaved(fs::path file) {
    file_ = std::move(file);
    saved_ = preset;
}

void Document::revert() {
    commit(false);
    preset = saved_;
    commit(false);
}

} // namespace lab
