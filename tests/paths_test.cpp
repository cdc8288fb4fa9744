// paths_test.cpp — folder containment: canonical paths, components, symbolic links.
#include "core/io/paths.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace lab {
namespace {

namespace fs = std::filesystem;

// dir/a/model.glb, dir/a/sub/deep.glb, dir/ab/other.glb, dir/outside.glb; dir/a/out.glb links to
// dir/outside.glb, dir/a/subLink to dir/a/sub and dir/a/upLink to dir.
class Paths : public testing::Test {
protected:
    void SetUp() override {
        ASSERT_FALSE(dir.path().empty());
        a = dir.path() / "a";
        fs::create_directories(a / "sub");
        fs::create_directories(dir.path() / "ab");
        writeText(a / "model.glb", "x");
        writeText(a / "sub" / "deep.glb", "x");
        writeText(dir.path() / "ab" / "other.glb", "x");
        writeText(dir.path() / "outside.glb", "x");
        fs::create_symlink(dir.path() / "outside.glb", a / "out.glb");
        fs::create_directory_symlink(a / "sub", a / "subLink");
        fs::create_directory_symlink(dir.path(), a / "upLink");
    }

    TempFolder dir;
    fs::path a;
};

TEST_F(Paths, AFileInOrBelowTheFolderIsInsideWithItsRelativePath) {
    EXPECT_EQ(relativeInside(a, a / "model.glb"), fs::path("model.glb"));
    EXPECT_EQ(relativeInside(a, a / "sub" / "deep.glb"), fs::path("sub/deep.glb"));
    EXPECT_EQ(relativeInside(a, a / "sub" / ".." / "model.glb"), fs::path("model.glb"));
    EXPECT_TRUE(isInside(a, a / "model.glb"));
}

TEST_F(Paths, AFileThatDoesNotExistYetCanBeInside) {
    EXPECT_EQ(relativeInside(a, a / "new" / "later.glb"), fs::path("new/later.glb"));
    EXPECT_FALSE(isInside(a, a / "new" / ".." / ".." / "later.glb"));
}

TEST_F(Paths, TheFolderItselfIsInsideAsDot) {
    EXPECT_EQ(relativeInside(a, a), fs::path("."));
    EXPECT_EQ(relativeInside(a, a / "."), fs::path("."));
    EXPECT_EQ(relativeInside(a / "", a), fs::path("."));
}

TEST_F(Paths, DotDotThatLeavesTheFolderIsOutside) {
    EXPECT_EQ(relativeInside(a, a / ".." / "outside.glb"), std::nullopt);
    EXPECT_FALSE(isInside(a, a / "sub" / ".." / ".." / "outside.glb"));
    EXPECT_FALSE(isInside(a / "sub", a));
}

TEST_F(Paths, SymbolicLinksAreFollowed) {
    EXPECT_FALSE(isInside(a, a / "out.glb"));                  // a file link pointing out
    EXPECT_FALSE(isInside(a, a / "upLink" / "outside.glb"));   // a folder link pointing out
    EXPECT_EQ(relativeInside(a, a / "upLink" / "a" / "model.glb"), fs::path("model.glb")); // out and back in
    EXPECT_EQ(relativeInside(a, a / "subLink" / "deep.glb"), fs::path("sub/deep.glb"));
    EXPECT_EQ(relativeInside(a / "subLink", a / "sub" / "deep.glb"), fs::path("deep.glb")); // the folder a link
}

TEST_F(Paths, ASiblingWhoseNameSharesAPrefixIsOutside) {
    EXPECT_FALSE(isInside(a, dir.path() / "ab" / "other.glb"));
    EXPECT_FALSE(isInside(a, dir.path() / "ab"));
    EXPECT_FALSE(isInside(dir.path() / "ab", a / "model.glb"));
}

TEST_F(Paths, AFolderThatDoesNotExistHasNoTrailingSeparator) {
    fs::path missing = a / "missing" / "";
    EXPECT_EQ(canonicalFolder(missing), fs::weakly_canonical(a) / "missing");
    EXPECT_EQ(relativeInside(missing, a / "missing" / "x.glb"), fs::path("x.glb"));
}

TEST_F(Paths, AnEmptyFolderIsTheWorkingFolder) {
    fs::path before = fs::current_path();
    fs::current_path(a);
    EXPECT_EQ(canonicalFolder(""), fs::weakly_canonical(a));
    EXPECT_EQ(relativeInside("", "model.glb"), fs::path("model.glb"));
    EXPECT_EQ(relativeInside("", a / "sub" / "deep.glb"), fs::path("sub/deep.glb"));
    EXPECT_FALSE(isInside("", "../outside.glb"));
    EXPECT_FALSE(isInside("", dir.path() / "outside.glb"));
    fs::current_path(before);
}

TEST_F(Paths, CanonicalFolderResolvesLinksAndDots) {
    EXPECT_EQ(canonicalFolder(a / "subLink"), fs::weakly_canonical(a / "sub"));
    EXPECT_EQ(canonicalFolder(a / "sub" / ".."), fs::weakly_canonical(a));
    EXPECT_TRUE(canonicalFolder(a).is_absolute());
}

// Two paths are one file when they lead to the same inode (links, hard links, dots), or, for a file
// that does not exist yet, to the same name in the same real folder.
TEST_F(Paths, SameFileFollowsLinksAndComparesNamesOfFilesToCome) {
    fs::create_hard_link(a / "model.glb", a / "hard.glb");
    EXPECT_TRUE(sameFile(a / "model.glb", a / "sub" / ".." / "model.glb"));
    EXPECT_TRUE(sameFile(a / "out.glb", dir.path() / "outside.glb"));           // a link to a file
    EXPECT_TRUE(sameFile(a / "upLink" / "outside.glb", dir.path() / "outside.glb")); // through a folder link
    EXPECT_TRUE(sameFile(a / "hard.glb", a / "model.glb"));                     // a hard link
    EXPECT_FALSE(sameFile(a / "model.glb", a / "sub" / "deep.glb"));
    EXPECT_TRUE(sameFile(a / "new.png", a / "subLink" / ".." / "new.png"));    // both still to come
    EXPECT_TRUE(sameFile(a / "sub" / "new.png", a / "subLink" / "new.png"));
    EXPECT_FALSE(sameFile(a / "new.png", a / "sub" / "new.png"));
    EXPECT_FALSE(sameFile(a / "model.glb", a / "model.glb.png"));
    fs::path before = fs::current_path();
    fs::current_path(a);
    EXPECT_TRUE(sameFile("model.glb", a / "model.glb")); // relative to the working folder
    EXPECT_TRUE(sameFile("later.png", a / "later.png"));
    fs::current_path(before);
}

// A link to a file still to come is that file: two outputs, one through the link, write one file.
TEST_F(Paths, ALinkToAFileToComeIsThatFile) {
    fs::create_symlink("later.json", a / "link.json");
    EXPECT_TRUE(sameFile(a / "link.json", a / "later.json"));
    EXPECT_FALSE(sameFile(a / "link.json", a / "link2.json"));
}

// Issue 49: `lab fit` aborted (filesystem_error from std::filesystem::absolute) for a preset named
// without a folder ("" is its folder) and for a relative path in a removed working folder.
TEST_F(Paths, AbsolutePathNeverThrows) {
    const fs::path before = fs::current_path();
    fs::current_path(a);
    EXPECT_EQ(absolutePath(""), fs::current_path());
    EXPECT_EQ(absolutePath("x/../model.glb"), fs::current_path() / "model.glb");
    EXPECT_EQ(absolutePath("/abs/./x"), fs::path("/abs/x"));
    fs::create_directory(dir.path() / "gone");
    fs::current_path(dir.path() / "gone");
    fs::remove(dir.path() / "gone");
    EXPECT_EQ(absolutePath("fit.json"), std::nullopt);
    EXPECT_EQ(absolutePath(""), std::nullopt);
    EXPECT_EQ(absolutePath("/abs/x"), fs::path("/abs/x")); // an absolute path needs no working folder
    fs::current_path(before);
}

} // namespace
} // namespace lab
