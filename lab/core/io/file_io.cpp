// file_io.cpp — bounded reads and atomic writes (POSIX).
#include "core/io/file_io.h"

#include "core/io/paths.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lab {

namespace fs = std::filesystem;

namespace {

// A descriptor for `path` (-1 with `error`), only for a regular file of at most `maxBytes`.
// open() first and fstat() the descriptor, so the checks apply to what is actually read; the
// non-blocking open keeps a FIFO from hanging the lab.
int openRegularFile(const fs::path& path, std::size_t maxBytes, std::size_t& size, std::string& error) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        error = errno == ENOENT ? "no such file" : std::strerror(errno);
        return -1;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        error = S_ISDIR(st.st_mode) ? "is a folder, not a file" : "not a regular file";
        return -1;
    }
    if (static_cast<std::uint64_t>(st.st_size) > maxBytes) {
        ::close(fd);
        error = "file is " + std::to_string(st.st_size) + " bytes, more than the limit of " + std::to_string(maxBytes);
        return -1;
    }
    size = static_cast<std::size_t>(st.st_size);
    return fd;
}

} // namespace

std::optional<std::string> readFile(const fs::path& path, std::size_t maxBytes, std::string& error) {
    std::size_t size = 0;
    int fd = openRegularFile(path, maxBytes, size, error);
    if (fd < 0) {
        return std::nullopt;
    }
    std::string bytes(size, '\0');
    std::size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            break; // the file shrank or failed under us: keep what was read and report below
        }
        done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    if (done != bytes.size()) {
        error = "could not read the whole file";
        return std::nullopt;
    }
    return bytes;
}

std::optional<MappedFile> MappedFile::open(const fs::path& path, std::size_t maxBytes, std::string& error) {
    std::size_t size = 0;
    int fd = openRegularFile(path, maxBytes, size, error);
    if (fd < 0) {
        return std::nullopt;
    }
    if (size == 0) {
        ::close(fd);
        return MappedFile(nullptr, 0);
    }
    void* data = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (data == MAP_FAILED) {
        error = std::string("cannot map the file: ") + std::strerror(errno);
        return std::nullopt;
    }
    return MappedFile(static_cast<const char*>(data), size);
}

MappedFile::MappedFile(MappedFile&& other) noexcept : data_(other.data_), size_(other.size_) {
    other.data_ = nullptr;
    other.size_ = 0;
}

MappedFile::~MappedFile() {
    if (data_) {
        ::munmap(const_cast<char*>(data_), size_);
    }
}

namespace {

// writeProblem for a path that is not a symbolic link.
std::string fileWriteProblem(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            return "is a folder";
        }
        if (!S_ISREG(st.st_mode)) {
            return "is not a regular file (the lab writes a new file and renames it over the old one)";
        }
    }
    fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    if (::stat(folder.c_str(), &st) != 0) {
        return errno == ENOENT || errno == ENOTDIR ? "no such folder " + folder.string()
                                                   : "cannot reach " + folder.string() + ": " + std::strerror(errno);
    }
    if (!S_ISDIR(st.st_mode)) {
        return folder.string() + " is not a folder";
    }
    if (st.st_nlink == 0) { // a removed folder (the working folder, say) still answers stat()
        return "the folder " + folder.string() + " has been removed";
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        return "cannot write in " + folder.string() + ": " + std::strerror(errno);
    }
    return "";
}

} // namespace

std::string writeProblem(const fs::path& path) {
    std::string error;
    std::optional<fs::path> target = linkTarget(path, error);
    if (!target) {
        return error;
    }
    std::string why = fileWriteProblem(*target);
    return why.empty() || *target == path ? why : "leads to " + target->string() + ": " + why;
}

bool writeFileAtomic(const fs::path& named, std::string_view bytes, std::string& error, WriteSafety safety) {
    std::optional<fs::path> target = linkTarget(named, error); // through a link: its target is replaced
    if (!target) {
        error = "cannot write " + named.string() + ": " + error;
        return false;
    }
    const fs::path& path = *target;
    fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::string tmpl = (folder / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
    int fd = ::mkstemp(tmpl.data());
    if (fd < 0) {
        error = "cannot create a file in " + folder.string() + ": " + std::strerror(errno);
        return false;
    }
    auto fail = [&](const char* what) {
        error = std::string(what) + " " + path.string() + ": " + std::strerror(errno);
        ::close(fd);
        ::unlink(tmpl.c_str());
        return false;
    };
    std::size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n < 0) {
            return fail("cannot write");
        }
        done += static_cast<std::size_t>(n);
    }
    // mkstemp creates 0600; give the file the usual permissions, as an ordinary write would.
    mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(fd, 0666 & ~mask) != 0 || (safety == WriteSafety::Durable && ::fsync(fd) != 0)) {
        return fail("cannot write");
    }
    if (::close(fd) != 0) {
        error = "cannot write " + path.string() + ": " + std::strerror(errno);
        ::unlink(tmpl.c_str());
        return false;
    }
    if (::rename(tmpl.c_str(), path.c_str()) != 0) {
        error = "cannot replace " + path.string() + ": " + std::strerror(errno);
        ::unlink(tmpl.c_str());
        return false;
    }
    return true;
}

} // namespace lab
