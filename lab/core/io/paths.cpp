// paths.cpp — folder containment on canonical paths.
#include "core/io/paths.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <vector>

namespace lab {

namespace fs = std::filesystem;

namespace {

// weakly_canonical, without the trailing separator it keeps when the last part does not exist
// ("/a/missing/"), which would otherwise count as one more (empty) component.
std::optional<fs::path> resolved(const fs::path& path) {
    std::error_code ec;
    fs::path c = fs::weakly_canonical(path.empty() ? fs::path(".") : path, ec);
    if (ec) {
        return std::nullopt;
    }
    if (!c.has_filename() && c.has_relative_path()) {
        c = c.parent_path();
    }
    return c;
}

// Symbolic links followed before a write gives up: Linux's own limit (MAXSYMLINKS).
constexpr int kMaxLinks = 40;

// /proc and what lies below it, once `folder` is resolved.
bool inProc(const fs::path& folder) {
    std::optional<fs::path> c = resolved(folder);
    if (!c) {
        return false;
    }
    auto it = c->begin();
    return c->is_absolute() && ++it != c->end() && *it == "proc";
}

} // namespace

std::optional<fs::path> absolutePath(const fs::path& path) {
    if (path.is_absolute()) {
        return path.lexically_normal();
    }
    std::error_code ec;
    fs::path working = fs::current_path(ec);
    if (ec || working.empty()) {
        return std::nullopt;
    }
    return path.empty() ? working.lexically_normal() : (working / path).lexically_normal();
}

std::optional<fs::path> linkTarget(const fs::path& path, std::string& error) {
    fs::path at = path;
    for (int links = 0;; ++links) {
        struct stat st {};
        if (at.empty() || ::lstat(at.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
            return at; // not a link (or nothing there yet): the write lands here
        }
        const fs::path folder = at.parent_path().empty() ? fs::path(".") : at.parent_path();
        if (inProc(folder)) {
            error = (at == path ? "is " : "leads to " + at.string() + ", ") +
                    "a process's open file, which the lab cannot replace (it writes a new file and renames it into "
                    "place); name a file";
            return std::nullopt;
        }
        if (links == kMaxLinks) {
            error = "is a symbolic link that leads round in a loop";
            return std::nullopt;
        }
        std::vector<char> text(PATH_MAX + 1);
        ssize_t n = ::readlink(at.c_str(), text.data(), text.size() - 1);
        if (n < 0) {
            error = "cannot read the symbolic link " + at.string();
            return std::nullopt;
        }
        // Not normalized: ".." in a link is the kernel's to resolve, after the folder's own links.
        const fs::path to(std::string(text.data(), static_cast<std::size_t>(n)));
        at = to.is_absolute() ? to : at.parent_path() / to;
    }
}

fs::path canonicalFolder(const fs::path& folder) {
    if (std::optional<fs::path> c = resolved(folder)) {
        return *c;
    }
    // Only where the file system refuses to answer: the folder as written, for messages (what
    // is inside is decided by relativeInside, which then answers "nothing").
    std::error_code ec;
    fs::path absolute = fs::absolute(folder.empty() ? fs::path(".") : folder, ec);
    return (ec ? folder : absolute).lexically_normal();
}

std::optional<fs::path> relativeInside(const fs::path& folder, const fs::path& path) {
    std::optional<fs::path> base = resolved(folder);
    std::optional<fs::path> full = resolved(path);
    if (!base || !full) {
        return std::nullopt;
    }
    auto [baseEnd, rest] = std::mismatch(base->begin(), base->end(), full->begin(), full->end());
    if (baseEnd != base->end()) {
        return std::nullopt;
    }
    fs::path relative;
    for (; rest != full->end(); ++rest) {
        relative /= *rest;
    }
    return relative.empty() ? fs::path(".") : relative;
}

bool isInside(const fs::path& folder, const fs::path& path) { return relativeInside(folder, path).has_value(); }

FileIdentity fileIdentity(const fs::path& path) {
    FileIdentity id;
    struct stat st {};
    if (!path.empty() && ::stat(path.c_str(), &st) == 0) {
        id.exists = true;
        id.device = static_cast<std::uint64_t>(st.st_dev);
        id.inode = static_cast<std::uint64_t>(st.st_ino);
        return id;
    }
    std::string error;
    const fs::path lands = linkTarget(path, error).value_or(path); // a link to a file to come is that file
    std::optional<fs::path> absolute = absolutePath(lands);
    std::optional<fs::path> c = resolved(absolute.value_or(lands));
    id.path = (c ? *c : absolute.value_or(lands)).string();
    return id;
}

bool sameFile(const fs::path& a, const fs::path& b) { return fileIdentity(a) == fileIdentity(b); }

} // namespace lab
