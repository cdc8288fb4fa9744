// file_io_test.cpp — what keeps a write from starting where it cannot succeed, or where it would
// replace something that is not a file (writeProblem), and where a write lands when its path is a
// symbolic link (through it, to its target). Atomic writes themselves: preset_test.cpp.
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

// Issue 49: the temporary file was renamed over the link itself, which became a file while its
// target kept the old bytes (a dotfiles folder's settings.json, out.json -> real/target.json).
TEST(WriteThroughLinks, AWriteThroughALinkReplacesItsTargetAndKeepsTheLink) {
    TempFolder dir;
    fs::create_directory(dir.path() / "real");
    writeText(dir.path() / "real" / "target.json", "old");
    fs::create_symlink("real/target.json", dir.path() / "out.json"); // relative: from the link's folder
    fs::create_symlink(dir.path() / "out.json", dir.path() / "chain.json"); // a link to a link
    std::string error;
    ASSERT_TRUE(writeFileAtomic(dir.path() / "out.json", "new", error)) << error;
    EXPECT_TRUE(fs::is_symlink(dir.path() / "out.json"));
    EXPECT_EQ(readText(dir.path() / "real" / "target.json"), "new");
    ASSERT_TRUE(writeFileAtomic(dir.path() / "chain.json", "newer", error, WriteSafety::Renewable)) << error;
    EXPECT_TRUE(fs::is_symlink(dir.path() / "chain.json"));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "out.json"));
    EXPECT_EQ(readText(dir.path() / "real" / "target.json"), "newer");
    // No temporary file is left beside the link or the target.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 3);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path() / "real"), fs::directory_iterator()), 1);
}

TEST(WriteThroughLinks, ALinkToAFileNotMadeYetMakesIt) {
    TempFolder dir;
    fs::create_directory(dir.path() / "real");
    fs::create_symlink("real/later.json", dir.path() / "out.json");
    EXPECT_EQ(writeProblem(dir.path() / "out.json"), "");
    std::string error;
    ASSERT_TRUE(writeFileAtomic(dir.path() / "out.json", "made", error)) << error;
    EXPECT_TRUE(fs::is_symlink(dir.path() / "out.json"));
    EXPECT_EQ(readText(dir.path() / "real" / "later.json"), "made");
    // A link into a folder that does not exist names the folder it leads to.
    fs::create_symlink("none/x.json", dir.path() / "lost.json");
    EXPECT_EQ(writeProblem(dir.path() / "lost.json"),
              "leads to " + (dir.path() / "none" / "x.json").string() + ": no such folder " + (dir.path() / "none").string());
    EXPECT_FALSE(writeFileAtomic(dir.path() / "lost.json", "x", error));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "lost.json"));
}

TEST(WriteThroughLinks, ALinkToSomethingThatIsNotAFileOrThatLoopsIsRefusedUntouched) {
    TempFolder dir;
    fs::create_directory(dir.path() / "folder");
    fs::create_symlink("folder", dir.path() / "to-folder.json");
    EXPECT_EQ(writeProblem(dir.path() / "to-folder.json"), "leads to " + (dir.path() / "folder").string() + ": is a folder");
    fs::create_symlink("/dev/null", dir.path() / "to-null.json");
    EXPECT_NE(writeProblem(dir.path() / "to-null.json").find("is not a regular file"), std::string::npos);
    fs::create_symlink("b.json", dir.path() / "a.json");
    fs::create_symlink("a.json", dir.path() / "b.json");
    EXPECT_EQ(writeProblem(dir.path() / "a.json"), "is a symbolic link that leads round in a loop");
    std::string error;
    EXPECT_FALSE(writeFileAtomic(dir.path() / "a.json", "x", error));
    EXPECT_EQ(error, "cannot write " + (dir.path() / "a.json").string() + ": is a symbolic link that leads round in a loop");
    EXPECT_TRUE(fs::is_symlink(dir.path() / "a.json"));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "to-null.json"));
}

// As root (CI's containers), `--out /dev/stdout` with standard output in a file renamed a regular
// file over the system's /dev/stdout link. /dev/stdout leads to /proc/self/fd/1, a process's open
// file: refused, whatever that descriptor is (a terminal, a pipe, a file).
TEST(WriteThroughLinks, AProcessesOpenFileIsRefused) {
    TempFolder dir;
    fs::create_symlink("/proc/self/fd/1", dir.path() / "stdout.json");
    for (const fs::path& p : {fs::path("/dev/stdout"), fs::path("/proc/self/fd/2"), dir.path() / "stdout.json"}) {
        const std::string why = writeProblem(p);
        EXPECT_NE(why.find("a process's open file"), std::string::npos) << p << ": " << why;
        std::string error;
        EXPECT_FALSE(writeFileAtomic(p, "x", error)) << p;
    }
    EXPECT_TRUE(fs::is_symlink("/dev/stdout"));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "stdout.json"));
}

// A removed working folder still answers stat(); a file cannot be made in it.
TEST(WriteProblem, ARemovedWorkingFolderIsNamed) {
    TempFolder dir;
    const fs::path gone = dir.path() / "gone";
    fs::create_directory(gone);
    const fs::path before = fs::current_path();
    fs::current_path(gone);
    fs::remove(gone);
    EXPECT_EQ(writeProblem("fit.json"), "the folder . has been removed");
    fs::current_path(before);
}

} // namespace
} // namespace lab
