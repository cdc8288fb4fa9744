// paths.cpp — folder containment on canonical paths.
#include "core/io/paths.h"

#include <sys/stat.h>

#include <algorithm>

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

} // namespace

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
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    std::optional<fs::path> c = resolved(ec ? path : absolute);
    id.path = (c ? *c : absolute.lexically_normal()).string();
    return id;
}

bool sameFile(const fs::path& a, const fs::path& b) { return fileIdentity(a) == fileIdentity(b); }

} // namespace lab
