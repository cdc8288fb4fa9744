// paths.h — whether a path lies inside a folder, asked one way everywhere.
//
// Presets may only name models in or below their own folder, a glTF file may only read buffers
// in or below its folder, and the GUI keeps a dropped model's path relative to the preset's. All
// of them ask here. "Inside" is decided on canonical paths (symbolic links and ".." resolved, as
// far as the path exists) compared component by component, so /a/bc is not inside /a/b and a
// link that points out of the folder leads out of it.
//
// This file owns that question and nothing else: it does not open files or check that they
// exist or are regular files (the callers say what they need).
#pragma once

#include <filesystem>
#include <optional>

namespace lab {

// The canonical form of `folder` (weakly_canonical, "." for empty).
std::filesystem::path canonicalFolder(const std::filesystem::path& folder);

// `path` relative to `folder` when it lies in or below it (symbolic links resolved, both
// weakly_canonical), else nullopt. The folder itself is ".". A relative `path` is taken from the
// working folder, not from `folder`. Nullopt too when either cannot be resolved.
std::optional<std::filesystem::path> relativeInside(const std::filesystem::path& folder,
                                                    const std::filesystem::path& path);

// relativeInside(folder, path).has_value().
bool isInside(const std::filesystem::path& folder, const std::filesystem::path& path);

} // namespace lab
