// file_io_test.cpp — what keeps a write from starting where it cannot succeed, or where it would
// replace something that is not a file (writeProblem). Atomic writes themselves: preset_test.cpp.
#include "core/io/file_io.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

namespace lab {
namespace {

namespace fs = std::filesystem;

TEST(WriteProblem, ANewOrExistingFileInAWritableFolderCanBeWritten) {
    TempFolder dir;
    EXPECT_EQ(writeProblem(dir.path() / "new.png"), "");
    writeText(dir.path() / "old.png", "x");
    EXPECT_EQ(writeProblem(dir.path() / "old.png"), "");
    fs::path before = fs::current_path();
    fs::current_path(dir.path());
    EXPECT_EQ(writeProblem("here.png"), ""); // no folder: the working folder
    fs::current_path(before);
}

TEST(WriteProblem, FoldersDevicesAndFifosAreRefusedUntouched) {
    TempFolder dir;
    fs::create_directory(dir.path() / "folder");
    EXPECT_EQ(writeProblem(dir.path() / "folder"), "is a folder");
    ASSERT_EQ(::mkfifo((dir.path() / "fifo").c_str(), 0600), 0);
    EXPECT_NE(writeProblem(dir.path() / "fifo").find("is not a regular file"), std::string::npos);
    // The rename of an atomic write would replace the device itself (as root, /dev/null).
    EXPECT_NE(writeProblem("/dev/null").find("is not a regular file"), std::string::npos);
    EXPECT_TRUE(fs::is_fifo(dir.path() / "fifo"));
}

TEST(WriteProblem, AMissingOrUnusableFolderIsNamed) {
    TempFolder dir;
    EXPECT_EQ(writeProblem(dir.path() / "none" / "x.png"), "no such folder " + (dir.path() / "none").string());
    writeText(dir.path() / "file", "x");
    EXPECT_EQ(writeProblem(dir.path() / "file" / "x.png"), (dir.path() / "file").string() + " is not a folder");
    if (::geteuid() != 0) { // root writes anywhere
        fs::create_directory(dir.path() / "locked");
        fs::permissions(dir.path() / "locked", fs::perms::owner_read | fs::perms::owner_exec);
        EXPECT_EQ(writeProblem(dir.path() / "locked" / "x.png").rfind("cannot write in ", 0), 0u);
        fs::permissions(dir.path() / "locked", fs::perms::owner_all);
    }
}

} // namespace
} // namespace lab
