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

std::string failure(const std::filesystem::path& target, int error) {
    return "cannot write " + file_message(target, std::strerror(error));
}

}  // namespace

std::string write_file_atomically(const std::filesystem::path& target,
                                  std::span<const std::uint8_t> bytes) {
    if (target.empty()) return "cannot write an image to an empty file name";
    std::error_code ec;
    if (std::filesystem::is_directory(target, ec))
        return "cannot write " + file_message(target, "it is a directory");
    // Beside the target, so the rename stays within one file system.
    std::string pattern = target.string() + ".tmp-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = ::mkstemp(name.data());
    if (fd < 0) return failure(target, errno);
    auto abandon = [&](int error) {
        ::close(fd);
        ::unlink(name.data());
        return failure(target, error);
    };
    std::size_t written = 0;
    while (written < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            return abandon(errno);
        }
        written += static_cast<std::size_t>(n);
    }
    // mkstemp creates the file 0600; an image is an ordinary readable file.
    ::fchmod(fd, 0644);
    if (::fsync(fd) != 0 && errno != EINVAL) return abandon(errno);
    if (::close(fd) != 0) {
        int error = errno;
        ::unlink(name.data());
        return failure(target, error);
    }
    if (std::rename(name.data(), target.c_str()) != 0) {
        int error = errno;
        ::unlink(name.data());
        return failure(target, error);
    }
    return {};
}

}  // namespace jt
