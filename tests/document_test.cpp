// document_test.cpp — undo/redo as snapshots: one gesture is one step, saved state and revert.
#include "app/document.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

TEST(Document, EditsBecomeStepsWhenTheGestureEnds) {
    Document doc;
    EXPECT_FALSE(doc.canUndo());
    // A slider drag: many frames of edits while the gesture is in progress...
    for (int frame = 1; frame <= 10; ++frame) {
        doc.preset.material.shininess = 32.0f + float(frame);
        EXPECT_FALSE(doc.commit(true));
    }
    // ...then the release: exactly one step.
    EXPECT_TRUE(doc.commit(false));
    EXPECT_EQ(doc.undoDepth(), 1u);
    EXPECT_FALSE(doc.commit(false)); // nothing new
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset.material.shininess, 32.0f);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.preset.material.shininess, 42.0f);
}

TEST(Document, UndoRedoWalkTheHistoryAndANewEditDropsTheRedoBranch) {
    Document doc;
    doc.preset.shading = Shading::Flat;
    doc.commit(false);
    doc.preset.brdf = BrdfModel::BlinnPhong;
    doc.commit(false);
    doc.preset.material.diffuse = glm::vec3(0.1f);
    doc.commit(false);
    EXPECT_EQ(doc.undoDepth(), 3u);
    doc.undo();
    doc.undo();
    EXPECT_EQ(doc.preset.shading, Shading::Flat);
    EXPECT_EQ(doc.preset.brdf, BrdfModel::Phong);
    EXPECT_TRUE(doc.canRedo());
    doc.preset.lights.clear(); // a new edit
    doc.commit(false);
    EXPECT_FALSE(doc.canRedo());
    doc.undo();
    EXPECT_EQ(doc.preset.lights.size(), 1u);
    EXPECT_EQ(doc.preset.shading, Shading::Flat);
}

TEST(Document, UndoRecordsAnEditNotYetCommitted) {
    Document doc;
    doc.preset.terms.specular = false; // edited this frame, no commit yet
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.preset.terms.specular);
    ASSERT_TRUE(doc.redo());
    EXPECT_FALSE(doc.preset.terms.specular);
}

TEST(Document, DirtyFollowsTheSavedStateAndRevertIsUndoable) {
    Document doc;
    Preset p;
    p.name = "on disk";
    doc.reset(p, "some/file.json");
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(doc.displayName(), "file.json");
    EXPECT_EQ(doc.folder(), "some");
    doc.preset.material.shininess = 5.0f;
    EXPECT_TRUE(doc.dirty());
    doc.markSaved("some/other.json");
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(doc.file(), "some/other.json");
    doc.preset.material.shininess = 7.0f;
    doc.revert();
    EXPECT_EQ(doc.preset.material.shininess, 5.0f);
    EXPECT_FALSE(doc.dirty());
    doc.undo();
    EXPECT_EQ(doc.preset.material.shininess, 7.0f); // the revert itself can be undone
}

TEST(Document, HistoryIsBounded) {
    Document doc;
    for (std::size_t i = 0; i < Document::kMaxHistory + 50; ++i) {
        doc.preset.plotIncidentDeg = float(i % 90);
        doc.preset.material.shininess = float(i + 1);
        doc.commit(false);
    }
    EXPECT_EQ(doc.undoDepth(), Document::kMaxHistory);
}

TEST(Document, UndoWalksBackThroughEditsOfBothSetsInOrder) {
    Document doc;
    doc.preset.shading = Shading::Flat; // A
    doc.commit(false);
    doc.compare.brdf = BrdfModel::CookTorrance; // B
    doc.commit(false);
    doc.preset.material.shininess = 90.0f; // A again
    doc.commit(false);
    EXPECT_FALSE(doc.saved() == doc.preset);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset.material.shininess, 32.0f);
    EXPECT_EQ(doc.compare.brdf, BrdfModel::CookTorrance);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.compare.brdf, BrdfModel::Phong);
    EXPECT_EQ(doc.preset.shading, Shading::Flat);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.compare.brdf, BrdfModel::CookTorrance);
}

TEST(Document, OnlySetADecidesWhetherThereIsSomethingToSave) {
    Document doc;
    doc.compare.shading = Shading::Gouraud;
    doc.commit(false);
    EXPECT_FALSE(doc.dirty());
    EXPECT_TRUE(doc.canUndo());
}

TEST(Document, ResetStartsANewHistory) {
    Document doc;
    doc.preset.shading = Shading::Gouraud;
    doc.commit(false);
    doc.reset(Preset{}, "a.json");
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.canRedo());
}

} // namespace
} // namespace lab
