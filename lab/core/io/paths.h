// paths.h — whether a path lies inside a folder, asked one way everywhere.
//
// Presets may only name models in or below their own folder, a glTF file may only read buffers
// in or below its folder, and the GUI keeps a dropped model's path relative to the preset's. All
// of them ask here. "Inside" is decided on canonical paths (symbolic links and ".." resolved, as
// far as the path exists) compared component by component, so /a/bc is not inside /a/b and a
// link that points out of the folder leads out of it.
//
// It also answers whether two paths lead to one file (sameFile), which the commands ask of their
// inputs and outputs before they write anything (cli/run_files.h), where a write to a path lands
// when the path is a symbolic link (linkTarget: its target, which core/io/file_io.h writes), and
// what a path is from the root (absolutePath). None of them throws: a path the file system cannot
// answer for is a value (nullopt, or an error), never a std::filesystem exception.
//
// This file owns those questions and nothing else: it does not open files or check that they
// exist or are regular files (the callers say what they need).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>

namespace lab {

// `path` from the root, lexically normal ("a/../b" is "<working folder>/b"; "" is the working
// folder); nullopt when it is relative and the working folder cannot be named (it was removed).
std::optional<std::filesystem::path> absolutePath(const std::filesystem::path& path);

// Where a write to `path` lands: `path` itself, or, when it is a symbolic link, the file its links
// lead to (a relative link taken from its own folder; links to links followed). Nullopt with
// `error` when the links loop or lead into /proc — a process's open file (`/dev/stdout` is
// /proc/self/fd/1), which the lab cannot replace as it replaces a file. The target need not exist.
std::optional<std::filesystem::path> linkTarget(const std::filesystem::path& path, std::string& error);

// The canonical form of `folder` (weakly_canonical, "." for empty).
std::filesystem::path canonicalFolder(const std::filesystem::path& folder);

// `path` relative to `folder` when it lies in or below it (symbolic links resolved, both
// weakly_canonical), else nullopt. The folder itself is ".". A relative `path` is taken from the
// working folder, not from `folder`. Nullopt too when either cannot be resolved.
std::optional<std::filesystem::path> relativeInside(const std::filesystem::path& folder,
                                                    const std::filesystem::path& path);

// relativeInside(folder, path).has_value().
bool isInside(const std::filesystem::path& folder, const std::filesystem::path& path);

// Which file a path leads to: for one that exists, its device and inode (symbolic links followed,
// so hard links and links are one file); for one that does not exist yet, its canonical folder
// and name (a file that two paths would create; a link to it is it). Equal identities are one file.
struct FileIdentity {
    bool exists = false;
    std::uint64_t device = 0, inode = 0; // when it exists
    std::string path;                    // when it does not: weakly_canonical, absolute
    bool operator==(const FileIdentity&) const = default;
    bool operator<(const FileIdentity& o) const { // (the page's libc++ 13 has no <=> for strings)
        return std::tie(exists, device, inode, path) < std::tie(o.exists, o.device, o.inode, o.path);
    }
};
FileIdentity fileIdentity(const std::filesystem::path& path);

// fileIdentity(a) == fileIdentity(b).
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b);

} // namespace lab
