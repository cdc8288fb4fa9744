// file_io.h — the only way lab/core reads and writes files.
//
// Reads refuse anything that is not a regular file and anything larger than the caller's
// limit before allocating. Writes are atomic: a temporary file in the same folder, flushed to
// disk, then renamed over the target, so a failed write leaves the old file intact.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

// The whole file, or nullopt with `error` saying why (missing, not a regular file, too large,
// unreadable).
std::optional<std::string> readFile(const std::filesystem::path& path, std::size_t maxBytes,
                                    std::string& error);

// Writes `bytes` to `path` atomically; false with `error` on any failure, the old file intact.
bool writeFileAtomic(const std::filesystem::path& path, std::string_view bytes, std::string& error);

} // namespace lab
