// file_io.h — the only way lab/core reads and writes files.
//
// Reads refuse anything that is not a regular file and anything larger than the caller's
// limit before allocating. Writes are atomic: a temporary file in the same folder, flushed to
// disk (unless the caller says the file can be made again), then renamed over the target, so a
// failed write leaves the old file intact. A path that is a symbolic link is written through: the
// file it leads to is replaced and the link stays (core/io/paths.h linkTarget), as an ordinary
// write would; a link into /proc (`/dev/stdout`) or one that loops is refused.
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

// How far a write goes before the rename. Both are atomic: anyone reading the path, and a write
// that fails, see the old file or the whole new one.
enum class WriteSafety {
    Durable,   // fsync first: also a crash of the machine leaves the old file or the whole new
               // one. For what the user made: presets, screenshots, goldens, CSV.
    Renewable, // no fsync: for output that is made again by running the command again
               // (`lab render`'s PNGs), which the flush would hold up for nothing.
};

// Why writeFileAtomic(path, ...) could not succeed, found without writing anything; "" when it
// can: the path (or the file its links lead to: "leads to T: ...") is a folder, or is something
// other than a regular file (a device such as /dev/null, a FIFO: the rename would replace it), or
// its folder does not exist, is not a folder, has been removed or cannot be written in; or its
// links loop or lead into /proc. Commands ask this of every output before they write any.
std::string writeProblem(const std::filesystem::path& path);

// Writes `bytes` to `path` atomically; false with `error` on any failure, the old file intact.
bool writeFileAtomic(const std::filesystem::path& path, std::string_view bytes, std::string& error,
                     WriteSafety safety = WriteSafety::Durable);

} // namespace lab
