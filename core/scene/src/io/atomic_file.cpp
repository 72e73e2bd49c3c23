#include "jtracer/atomic_file.hpp"

#include "io/file_bytes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace jt {

namespace {

Error failure(const std::filesystem::path& target, int error) {
    return Error{"cannot write " + file_message(target, std::strerror(error))};
}

// 0 when every byte was written, else the errno of the failure.
int write_all(int fd, std::span<const std::uint8_t> bytes) {
    std::size_t written = 0;
    while (written < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        written += static_cast<std::size_t>(n);
    }
    return 0;
}

// A device or pipe (/dev/stdout, /dev/full) is written in place: renaming over
// it would not reach the reader, and as root would replace the device node.
Expected<void> write_in_place(const std::filesystem::path& target,
                              std::span<const std::uint8_t> bytes) {
    int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return failure(target, errno);
    int error = write_all(fd, bytes);
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) return failure(target, error);
    return {};
}

}  // namespace

Expected<void> write_file_atomically(const std::filesystem::path& target,
                                     std::span<const std::uint8_t> bytes) {
    if (target.empty()) return Error{"cannot write an image to an empty file name"};
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(target, ec);
    if (std::filesystem::is_directory(status))
        return Error{"cannot write " + file_message(target, "it is a directory")};
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        return write_in_place(target, bytes);
    // A symbolic link stays a link: the file it names is the one replaced.
    std::filesystem::path real = target;
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(target, ec))) {
        real = std::filesystem::weakly_canonical(target, ec);
        if (ec) return failure(target, ec.value());
    }
    // Beside the target, so the rename stays within one file system.
    std::string pattern = real.string() + ".tmp-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = ::mkstemp(name.data());
    if (fd < 0) return failure(target, errno);
    auto abandon = [&](int error) {
        ::close(fd);
        ::unlink(name.data());
        return failure(target, error);
    };
    if (int error = write_all(fd, bytes); error != 0) return abandon(error);
    // mkstemp creates the file 0600; an image is an ordinary readable file.
    ::fchmod(fd, 0644);
    if (::fsync(fd) != 0 && errno != EINVAL) return abandon(errno);
    if (::close(fd) != 0) {
        int error = errno;
        ::unlink(name.data());
        return failure(target, error);
    }
    if (std::rename(name.data(), real.c_str()) != 0) {
        int error = errno;
        ::unlink(name.data());
        return failure(target, error);
    }
    return {};
}

}  // namespace jt
