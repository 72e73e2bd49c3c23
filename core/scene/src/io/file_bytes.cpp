#include "io/file_bytes.hpp"

#include "io/link_cycle.hpp"
#include "jtracer/bmp.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <string>

namespace jt {

namespace {

// A pipe has no size to check in advance: past this it is refused rather than
// read on into all the memory there is. 1 GiB, as for scene files, holds any
// image a pipe reasonably carries (a 65535 x 4096 BMP is 805 MB).
constexpr std::size_t kMaxStreamBytes = std::size_t{1} << 30;
// No file read whole is larger than the largest BMP: PNGs and JPEGs are read
// under 2 GiB, and models are refused past 512 MiB before they are read. A
// larger file is refused by its size, not read into memory first.
constexpr std::uint64_t kMaxFileBytes = kMaxBmpFileBytes;

class FileDescriptor {
  public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return fd_; }

  private:
    int fd_;
};

Error read_error(const std::filesystem::path& path, const std::string& reason) {
    return Error{"cannot read " + file_message(path, reason)};
}

}  // namespace

std::string read_failure_reason(const std::filesystem::path& path, int error) {
    switch (error) {
        case ENOENT:
            return "no such file";
        case EACCES:
            return "permission denied";
        case EISDIR:
            return "it is a directory, not a file";
        default:
            return open_failure_reason(path, error);
    }
}

std::string file_message(const std::filesystem::path& path, const std::string& message) {
    std::string s = "'";
    s += path.string();
    s += "': ";
    s += message;
    return s;
}

Expected<std::vector<std::uint8_t>> read_file_bytes(const std::filesystem::path& path) {
    // O_NONBLOCK so that opening a named pipe does not wait for a writer that
    // may never come; reads block again below, once the file is open.
    FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
    if (file.get() < 0) return read_error(path, read_failure_reason(path, errno));
    struct stat status {};
    if (::fstat(file.get(), &status) != 0)
        return read_error(path, read_failure_reason(path, errno));
    if (S_ISDIR(status.st_mode)) return read_error(path, read_failure_reason(path, EISDIR));
    // A device never ends (/dev/zero, /dev/urandom) or waits for a person
    // (a terminal): it would be read until memory runs out, or forever.
    if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode))
        return read_error(path, "it is a device, not a file");
    const bool regular = S_ISREG(status.st_mode);
    if (regular && static_cast<std::uint64_t>(status.st_size) > kMaxFileBytes)
        return read_error(path, "it is " + std::to_string(status.st_size) +
                                    " bytes, larger than any image JTracer reads (" +
                                    std::to_string(kMaxFileBytes) + " bytes, the largest BMP)");
    if (!regular) {
        const int flags = ::fcntl(file.get(), F_GETFL);
        if (flags < 0 || ::fcntl(file.get(), F_SETFL, flags & ~O_NONBLOCK) < 0)
            return read_error(path, read_failure_reason(path, errno));
    }
    std::vector<std::uint8_t> bytes;
    if (regular) bytes.reserve(static_cast<std::size_t>(status.st_size));
    std::uint8_t buffer[65536];
    for (;;) {
        const ssize_t n = ::read(file.get(), buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR) continue;
            return read_error(path, read_failure_reason(path, errno));
        }
        if (n == 0) break;
        bytes.insert(bytes.end(), buffer, buffer + n);
        if (!regular && bytes.size() > kMaxStreamBytes)
            return read_error(
                path, "a pipe that gives more than " + std::to_string(kMaxStreamBytes) + " bytes");
    }
    // A pipe with no writer reads as empty: say so rather than let the
    // caller call nothing at all a broken image.
    if (S_ISFIFO(status.st_mode) && bytes.empty())
        return read_error(path, "a named pipe (FIFO) with nothing written to it");
    return bytes;
}

}  // namespace jt
