// workspace_slides.cpp — the workspace's slides: a deck's, or the preset list's files, stepped
// through without a question; each keeps its live edits for the session (workspace.h).
#include "app/workspace.h"

#include "core/io/safe_text.h"

#include <algorithm>

namespace lab {

namespace fs = std::filesystem;

int Workspace::slideCount() const { return static_cast<int>(deck_ ? deck_->slides.size() : presetFiles_.size()); }

std::string Workspace::slideName(int index) const {
    const std::size_t i = static_cast<std::size_t>(index);
    return deck_ ? slideTitle(deck_->slides[i]) : presetFiles_[i].stem().string();
}

std::vector<std::string> Workspace::slideNames() const {
    std::vector<std::string> names;
    for (int i = 0; i < slideCount(); ++i) {
        names.push_back(slideName(i));
    }
    return names;
}

const std::string& Workspace::notes() const {
    if (deck_ && currentDeckSlide_ >= 0) {
        return deck_->slides[static_cast<std::size_t>(currentDeckSlide_)].notes;
    }
    return doc_.saved().notes;
}

std::string Workspace::nextSlideTitle() const {
    const int next = currentSlide() + 1;
    return onSlide() && next > 0 && next < slideCount() ? slideName(next) : "";
}

std::string Workspace::slideKeyOf(const fs::path& file) const {
    std::error_code ec;
    const fs::path full = fs::weakly_canonical(file, ec);
    return "file:" + (ec ? file : full).string();
}

void Workspace::stepPreset(int delta) {
    const int n = slideCount();
    if (n == 0) {
        return;
    }
    const int at = currentSlide();
    if (deck_) { // a deck stops at its ends: a clicker's extra press does not start the lecture again
        const int next = at < 0 ? (delta > 0 ? 0 : n - 1) : at + delta;
        if (next < 0 || next >= n) {
            notes_.push_back(next < 0 ? "This is the first slide" : "This is the last slide (Home: the first)");
            return;
        }
        goToSlide(next);
        return;
    }
    goToSlide(at < 0 ? (delta > 0 ? 0 : n - 1) : (at + delta + n) % n);
}

void Workspace::goToSlide(int index) {
    if (index < 0 || index >= slideCount()) {
        return;
    }
    doc_.commit(false);
    if (!onSlide() && !deck_ && currentPreset_ >= 0) {
        slideKey_ = slideKeyOf(doc_.file()); // a file of the list opened by path: kept as a slide from now on
    }
    if (onSlide() || !doc_.dirty()) {
        stepTo(index);
        return;
    }
    // Off the list (an untitled scene, a file from elsewhere): nothing would keep its edits.
    pending_ = [this, index] { stepTo(index); };
    question_ = "open " + slideName(index);
}

void Workspace::stepTo(int index) {
    const std::size_t i = static_cast<std::size_t>(index);
    if (!deck_) {
        const std::string key = slideKeyOf(presetFiles_[i]);
        if (slides_.contains(key)) {
            enterSlide(key, {}, {}, {});
        } else {
            openFile(presetFiles_[i], true);
        }
        return;
    }
    const Slide& slide = deck_->slides[i];
    const std::string key = "deck:" + deck_->file.string() + "#" + std::to_string(index);
    if (!slides_.contains(key)) {
        waiting_.reset();
        const std::string title = "Cannot load the model of the slide " + inQuotes(slideTitle(slide)) + " (nothing was changed)";
        if (waitsFor(slide.preset.preset.model, slide.folder, title, [this, index] { stepTo(index); })) {
            return;
        }
        LoadedPreset loaded = slide.preset;
        Diagnostics d;
        if (!(loaded.file.empty() ? meshes_.get(loaded.preset.model, slide.folder, d) : meshes_.get(loaded, d))) {
            problem(title, std::move(d)); // (a file's glTF model without a camera is framed here)
            return;
        }
        loaded.preset.compare = slide.compare; // the deck's prepared comparison, else the preset's
        OpeningDisplay display = slide.display;
        display.compare = display.compare.value_or(!slide.compare.empty());
        enterSlide(key, loaded, display, slide.folder);
    } else {
        enterSlide(key, {}, {}, {});
    }
    currentDeckSlide_ = index;
}

void Workspace::keepSlide() {
    if (slideKey_.empty()) {
        return;
    }
    doc_.commit(false);
    slides_[slideKey_] = {doc_, view, opened_};
    slideKey_.clear();
}

void Workspace::enterSlide(const std::string& key, const LoadedPreset& loaded, const OpeningDisplay& display,
                           const fs::path& folder) {
    keepSlide();
    auto kept = slides_.find(key);
    if (kept == slides_.end()) {
        adopt(loaded.preset, loaded.file, loaded.file.empty() ? folder : fs::path{});
        opened_ = display;
        showAsOpened();
        notes_.push_back("Opened " + (loaded.file.empty() ? loaded.preset.name : loaded.file.filename().string()));
    } else { // back to a slide: as it was left, edits, history and display
        if (exercise_) {
            exercise_.reset();
        }
        doc_ = std::move(kept->second.doc);
        view = kept->second.view;
        opened_ = kept->second.opened;
        slides_.erase(kept);
        ++scenesOpened_;
        refreshPresetList();
        notes_.push_back("Back to " + doc_.displayName() + (doc_.edited() ? " with its edits (R: the file's)" : ""));
    }
    slideKey_ = key;
}

void Workspace::adopt(const LoadedPreset& loaded) { adopt(loaded.preset, loaded.file, {}); }

void Workspace::openDeck(const fs::path& file) {
    Diagnostics d;
    std::optional<Deck> deck = loadDeck(file, d);
    if (!deck) {
        problem("Cannot open the deck " + file.filename().string() + " (nothing was changed)", std::move(d));
        return;
    }
    whenChangesAreSafe("open the deck " + file.filename().string(), [this, deck = std::move(*deck)]() mutable {
        std::erase_if(slides_, [](const auto& kept) { return kept.first.starts_with("deck:"); });
        deck_ = std::move(deck);
        currentDeckSlide_ = -1;
        stepTo(0);
    });
}

void Workspace::resetSlide() {
    doc_.revert(true);
    showAsOpened();
}

void Workspace::showAsOpened() {
    DisplaySettings shown;
    shown.palette = view.palette; // the reader's choice of palette stays
    shown.mode = viewFromName(opened_.view).value_or(ViewMode::Lit);
    shown.light = std::clamp(opened_.light - 1, 0, std::max(0, static_cast<int>(doc_.preset.lights.size()) - 1));
    if (!notApplicable(shown.mode, doc_.preset, shown.light).empty()) {
        notes_.push_back(std::string(toString(shown.mode)) + " does not apply here: the lit model is shown");
        shown.mode = ViewMode::Lit;
    }
    shown.compare = !exercise_ && opened_.compare.value_or(!doc_.saved().compare.empty());
    shown.wipe = opened_.wipe;
    shown.wireframe = opened_.wireframe;
    view = shown;
}

int Workspace::slidesEdited() const {
    const int kept = static_cast<int>(std::count_if(slides_.begin(), slides_.end(), [](const auto& s) { return s.second.doc.dirty(); }));
    return kept + (doc_.dirty() ? 1 : 0);
}

// Quitting after "Save first": the document and every slide left with unsaved edits.
bool Workspace::saveEverySlide() {
    bool saved = !doc_.dirty() || save({});
    for (auto& [key, kept] : slides_) {
        if (kept.doc.dirty()) {
            std::swap(doc_, kept.doc);
            saved = save({}) && saved;
            std::swap(doc_, kept.doc);
        }
    }
    refreshPresetList();
    return saved;
}

} // namespace lab
