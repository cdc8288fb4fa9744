// slides_test.cpp — stepping through a lecture (app/workspace_slides.cpp), headless: a folder's
// presets and a deck's slides open without a question, each keeps its live edits for the session,
// R brings back the file's, and opening a preset or a slide shows it as its file says.
#include "app/workspace.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <string>

namespace lab {
namespace {

namespace fs = std::filesystem;

const fs::path kPresets = fs::path(LAB_SOURCE_DIR) / "presets";

// Three presets in a folder (a.json, b.json, c.json), the lab opened on a.json by path.
struct Slides {
    TempFolder dir;
    Workspace ws{WorkspaceOptions{{}, {}, false, {}}};
    fs::path a, b, c;

    Slides() {
        a = dir.path() / "a.json";
        b = dir.path() / "b.json";
        c = dir.path() / "c.json";
        writeText(a, R"({"format": "lighting-lab-preset", "version": 1, "name": "A", "notes": "Say A."})");
        writeText(b, R"({"format": "lighting-lab-preset", "version": 1, "name": "B", "shading": "gouraud",
                         "display": {"view": "n-dot-l", "wireframe": true}})");
        writeText(c, R"({"format": "lighting-lab-preset", "version": 1, "name": "C", "normal_matrix": "model-view",
                         "compare": {"normal_matrix": "inverse-transpose"}})");
        ws = Workspace(WorkspaceOptions{{}, dir.path() / "shots", false, dir.path() / "user"});
        ws.start(dir.path(), a);
        EXPECT_TRUE(ws.takeProblems().empty());
    }
    std::string name() const { return ws.document().file().filename().string(); }
};

TEST(Slides, SteppingNeverAsksAndEachSlideKeepsItsEditsAndHistory) {
    Slides s;
    s.ws.a().material.shininess = 5.0f; // a live edit on the slide opened by path
    s.ws.endFrame(false);
    s.ws.run({Command::NextPreset});
    EXPECT_FALSE(s.ws.question());
    EXPECT_EQ(s.name(), "b.json");
    s.ws.run({Command::ShadingPhong});
    s.ws.endFrame(false);
    s.ws.run({Command::NextPreset});
    EXPECT_FALSE(s.ws.question());
    EXPECT_EQ(s.name(), "c.json");
    s.ws.run({Command::FirstSlide});
    EXPECT_FALSE(s.ws.question());
    EXPECT_EQ(s.name(), "a.json");
    EXPECT_EQ(s.ws.a().material.shininess, 5.0f); // back to a slide: as it was left
    EXPECT_TRUE(s.ws.document().edited());
    s.ws.run({Command::ResetSlide});
    EXPECT_FALSE(s.ws.document().dirty());
    EXPECT_EQ(s.ws.a().material.shininess, Preset{}.material.shininess);
    s.ws.run({Command::Undo}); // Reset slide is one undo step
    EXPECT_EQ(s.ws.a().material.shininess, 5.0f);
    s.ws.run({Command::Undo}); // and the slide's own history came back with it
    EXPECT_EQ(s.ws.a().material.shininess, Preset{}.material.shininess);
    s.ws.run({Command::OpenPresetAt, {}, 1}); // the list steps too
    EXPECT_FALSE(s.ws.question());
    EXPECT_EQ(s.ws.a().shading, Shading::Phong);
    // Nothing was written unasked.
    Diagnostics d;
    EXPECT_EQ(loadPreset(s.b, d)->preset.shading, Shading::Gouraud);
    EXPECT_EQ(loadPreset(s.a, d)->preset.material.shininess, Preset{}.material.shininess);
}

TEST(Slides, QuittingAsksForEverySlideLeftWithEditsAndSaveFirstSavesThemAll) {
    Slides s;
    s.ws.a().material.shininess = 5.0f;
    s.ws.run({Command::NextPreset});
    s.ws.requestQuit(); // b.json is not edited, but a.json's edits would be lost
    ASSERT_TRUE(s.ws.question());
    EXPECT_FALSE(s.ws.quit());
    s.ws.answer(UnsavedAnswer::SaveFirst);
    EXPECT_TRUE(s.ws.quit());
    Diagnostics d;
    EXPECT_EQ(loadPreset(s.a, d)->preset.material.shininess, 5.0f);
}

TEST(Slides, AnUntitledSceneIsNotASlideAndStillAsks) {
    TempFolder dir;
    writeText(dir.path() / "a.json", R"({"format": "lighting-lab-preset", "version": 1})");
    Workspace ws(WorkspaceOptions{{dir.path()}, dir.path() / "shots", false, dir.path() / "user"});
    ws.start(dir.path());
    ws.a().material.shininess = 5.0f;
    ws.run({Command::NextPreset});
    ASSERT_TRUE(ws.question());
    ws.answer(UnsavedAnswer::Discard);
    EXPECT_EQ(ws.document().file().filename(), "a.json");
}

TEST(Slides, OpeningAPresetShowsItAsItsFileSays) {
    Slides s;
    s.ws.view.mode = ViewMode::Normals; // chosen on a.json: must not stick to the next
    s.ws.view.wipe = true;
    s.ws.run({Command::ToggleCompare});
    s.ws.run({Command::NextPreset});
    EXPECT_EQ(s.ws.view.mode, ViewMode::NdotL); // b.json's display
    EXPECT_TRUE(s.ws.view.wireframe);
    EXPECT_FALSE(s.ws.view.wipe);
    EXPECT_FALSE(s.ws.view.compare);
    s.ws.run({Command::NextPreset}); // c.json: a prepared comparison
    EXPECT_EQ(s.ws.view.mode, ViewMode::Lit);
    EXPECT_FALSE(s.ws.view.wireframe);
    EXPECT_TRUE(s.ws.view.compare);
    EXPECT_EQ(s.ws.a().normalMatrix, NormalMatrixMode::ModelView);
    EXPECT_EQ(s.ws.b().normalMatrix, NormalMatrixMode::InverseTranspose);
    EXPECT_FALSE(s.ws.document().edited()); // B as prepared is not an edit
    s.ws.view.editingB = true;
    s.ws.run({Command::ShadingFlat});
    EXPECT_TRUE(s.ws.document().edited());
    EXPECT_FALSE(s.ws.document().dirty()); // only A is saved
    s.ws.run({Command::ResetSlide});
    EXPECT_EQ(s.ws.b().shading, Shading::Phong);
    EXPECT_FALSE(s.ws.document().edited());
    // Going back to b.json shows the display it was left with.
    s.ws.view.mode = ViewMode::Normals;
    s.ws.run({Command::PreviousPreset});
    s.ws.view.mode = ViewMode::Diffuse;
    s.ws.run({Command::NextPreset});
    EXPECT_EQ(s.ws.view.mode, ViewMode::Normals);
}

TEST(Slides, AFolderGivenToOpenIsADeckOfItsPresets) {
    Slides s;
    Workspace ws(WorkspaceOptions{{}, s.dir.path() / "shots", false, s.dir.path() / "user"});
    ws.start(s.dir.path(), s.dir.path());
    EXPECT_TRUE(ws.takeProblems().empty());
    EXPECT_EQ(ws.document().file().filename(), "a.json");
    EXPECT_TRUE(ws.onSlide());
    EXPECT_EQ(ws.notes(), "Say A.");
    EXPECT_EQ(ws.nextSlideTitle(), "b");
}

TEST(Slides, ADeckStepsThroughItsSlidesAndStopsAtItsEnds) {
    Slides s;
    const fs::path deck = s.dir.path() / "decks" / "lecture.json";
    fs::create_directories(deck.parent_path());
    writeText(deck, R"({"format": "lighting-lab-deck", "version": 1, "title": "Lecture", "slides": [
        {"preset": "../b.json", "title": "First", "notes": "One.", "display": {"view": "lit", "wireframe": false}},
        {"preset": {"name": "Inline", "brdf": "blinn-phong"}, "notes": ["Two.", "Three."]},
        {"preset": "../a.json", "compare": {"shading": "flat"}}]})");
    s.ws.open(deck);
    EXPECT_TRUE(s.ws.takeProblems().empty());
    ASSERT_TRUE(s.ws.deck());
    EXPECT_EQ(s.ws.slideNames(), (std::vector<std::string>{"First", "Inline", "A"}));
    EXPECT_EQ(s.ws.currentSlide(), 0);
    EXPECT_EQ(s.ws.notes(), "One.");
    EXPECT_EQ(s.ws.view.mode, ViewMode::Lit); // the slide's display over the preset's
    EXPECT_FALSE(s.ws.view.wireframe);
    EXPECT_EQ(s.ws.nextSlideTitle(), "Inline");
    s.ws.a().material.shininess = 7.0f;
    s.ws.run({Command::PreviousPreset}); // the first slide: nowhere to go, nothing changes
    EXPECT_EQ(s.ws.currentSlide(), 0);
    EXPECT_EQ(s.ws.a().material.shininess, 7.0f);
    s.ws.run({Command::NextPreset});
    EXPECT_FALSE(s.ws.question());
    EXPECT_EQ(s.ws.currentSlide(), 1);
    EXPECT_EQ(s.ws.a().brdf, BrdfModel::BlinnPhong);
    EXPECT_EQ(s.ws.notes(), "Two.\nThree.");
    s.ws.run({Command::LastSlide});
    EXPECT_EQ(s.ws.currentSlide(), 2);
    EXPECT_TRUE(s.ws.view.compare); // the deck's prepared comparison
    EXPECT_EQ(s.ws.b().shading, Shading::Flat);
    EXPECT_EQ(s.ws.nextSlideTitle(), "");
    s.ws.takeNotes();
    s.ws.run({Command::NextPreset});
    EXPECT_EQ(s.ws.currentSlide(), 2);
    EXPECT_FALSE(s.ws.takeNotes().empty()); // "This is the last slide"
    s.ws.run({Command::FirstSlide});
    EXPECT_EQ(s.ws.a().material.shininess, 7.0f); // its edits kept
    Diagnostics d;
    EXPECT_EQ(loadPreset(s.b, d)->preset.material.shininess, Preset{}.material.shininess);
}

TEST(Slides, TheShippedDeckRunsFromFirstToLastWithAnEditOnEverySlideAndNoQuestion) {
    TempFolder dir;
    fs::copy(kPresets, dir.path() / "presets", fs::copy_options::recursive);
    Workspace ws(WorkspaceOptions{{dir.path() / "presets"}, dir.path() / "shots", false, dir.path() / "user"});
    ws.start(dir.path(), dir.path() / "presets" / "decks" / "lecture.json");
    ASSERT_TRUE(ws.takeProblems().empty());
    ASSERT_TRUE(ws.deck());
    const std::size_t n = ws.deck()->slides.size();
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(ws.currentSlide(), static_cast<int>(i));
        EXPECT_FALSE(ws.notes().empty()) << i;
        ws.a().material.specular *= 0.5f; // a live edit on every slide
        ws.run({Command::NextViewMode});
        ws.endFrame(false);
        ws.run({Command::NextPreset});
        EXPECT_FALSE(ws.question()) << i;
        EXPECT_TRUE(ws.takeProblems().empty()) << i;
    }
    EXPECT_EQ(ws.currentSlide(), static_cast<int>(n) - 1);
    EXPECT_FALSE(fs::exists(dir.path() / "user")); // nothing written
}

} // namespace
} // namespace lab
