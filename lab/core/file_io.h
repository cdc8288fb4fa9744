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

// A read-only view of a whole regular file (mmap), for large inputs: no copy and no zero-filled
// buffer, the bytes come straight from the page cache. Same checks and limit as readFile.
class MappedFile {
public:
    static std::optional<MappedFile> open(const std::filesystem::path& path, std::size_t maxBytes, std::string& error);
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&&) = delete;
    ~MappedFile();
    std::string_view bytes() const { return {data_, size_}; }

private:
    MappedFile(const char* data, std::size_t size) : data_(data), size_(size) {}
    const char* data_;
    std::size_t size_;
};

// Writes `bytes` to `path` atomically; false with `error` on any failure, the old file intact.
bool writeFileAtomic(const std::filesystem::path& path, std::string_view bytes, std::string& error);

} // namespace lab
