#include "jtracer/atomic_file.hpp"

#include "io/file_bytes.hpp"
#include "io/link_cycle.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace jt {

namespace {

// The temporary file a write has made and not yet renamed or removed, for
// remove_unfinished_file; a lock-free atomic, so a signal handler may read it.
std::atomic<const char*> unfinished{nullptr};
static_assert(std::atomic<const char*>::is_always_lock_free);

Error failure(const std::filesystem::path& target, int error) {
    return Error{"cannot write " + file_message(target, open_failure_reason(target, error))};
}

// A failure to make the temporary file beside `real`. A file that may be
// written in a folder that may not (a shared render folder whose files are
// group-writable) gives "Permission denied", which then seems to be about the
// file: say that it is the folder. A read-only file system is no folder's
// fault, and "Read-only file system" says what to change: no such word there.
Error temporary_failure(const std::filesystem::path& target, const std::filesystem::path& real,
                        int error) {
    if (error != EACCES && error != EPERM) return failure(target, error);
    const std::filesystem::path folder =
        real.parent_path().empty() ? std::filesystem::path(".") : real.parent_path();
    return Error{"cannot write " + file_message(target, std::strerror(error)) +
                 ": the image is written to a temporary file in '" + folder.string() +
                 "', then renamed, so that folder must be writable"};
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

int write_all(int fd, const BytePieces& next_piece) {
    for (std::span<const std::uint8_t> piece = next_piece(); !piece.empty(); piece = next_piece())
        if (const int error = write_all(fd, piece); error != 0) return error;
    return 0;
}

// The whole of `bytes` as one piece.
BytePieces one_piece(std::span<const std::uint8_t> bytes) {
    return [bytes, given = false]() mutable {
        const std::span<const std::uint8_t> piece = given ? std::span<const std::uint8_t>() : bytes;
        given = true;
        return piece;
    };
}

// A device or pipe (/dev/stdout, /dev/full) is written in place: renaming over
// it would not reach the reader, and as root would replace the device node.
Expected<void> write_in_place(const std::filesystem::path& target, const BytePieces& next_piece) {
    int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return failure(target, errno);
    int error = write_all(fd, next_piece);
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) return failure(target, error);
    return {};
}

// A temporary file beside `real` holding the bytes, written, synced and
// closed: its name, or the errno of the failure (then nothing is left).
struct Temporary {
    std::vector<char> name;  // NUL-terminated, for the system calls
    int error = 0;
};

// The name mkstemp makes the temporary file from: beside the target, so that
// the rename or link stays within one file system.
std::vector<char> temporary_pattern(const std::filesystem::path& real) {
    const std::string pattern = real.string() + ".tmp-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    return name;
}

// `mode`: the permissions the file gets (a replaced file keeps its own).
Temporary write_temporary(const std::filesystem::path& real, const BytePieces& next_piece,
                          mode_t mode) {
    Temporary t{temporary_pattern(real)};
    const int fd = ::mkstemp(t.name.data());
    if (fd < 0) return {{}, errno};
    // The name's buffer moves with `t` to the caller, who clears this once
    // the file is renamed or removed.
    unfinished.store(t.name.data());
    int error = write_all(fd, next_piece);
    // mkstemp creates the file 0600.
    ::fchmod(fd, mode);
    // EINVAL: the file system cannot sync (a pipe-like or special one); the bytes are written.
    if (error == 0 && ::fsync(fd) != 0 && errno != EINVAL) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) {
        ::unlink(t.name.data());
        unfinished.store(nullptr);
        return {{}, error};
    }
    return t;
}

}  // namespace

void remove_unfinished_file() noexcept {
    // Removed after the rename, the name is gone: unlink then fails harmlessly.
    if (const char* name = unfinished.load()) ::unlink(name);
}

std::filesystem::path file_behind_links(const std::filesystem::path& path) {
    std::filesystem::path file = path;
    for (int followed = 0; followed < kMostLinksFollowed; ++followed) {
        std::error_code error;
        if (!std::filesystem::is_symlink(std::filesystem::symlink_status(file, error))) return file;
        const std::filesystem::path link = std::filesystem::read_symlink(file, error);
        if (error) return file;
        file = link_destination(file, link);
    }
    return path;
}

namespace {

// Where write_file_atomically puts the bytes: in place (a device or pipe),
// or through a temporary file beside the regular file behind `target`'s
// links; or why it cannot.
struct WriteTarget {
    bool in_place = false;
    std::filesystem::path file;
};

Expected<WriteTarget> write_target(const std::filesystem::path& target) {
    if (target.empty()) return Error{"cannot write an image to an empty file name"};
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(target, ec);
    if (std::filesystem::is_directory(status))
        return Error{"cannot write " + file_message(target, "it is a directory")};
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        return WriteTarget{true, target};
    std::filesystem::path real = file_behind_links(target);
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(real, ec)))
        return failure(target, ELOOP);
    return WriteTarget{false, std::move(real)};
}

}  // namespace

Expected<void> check_atomic_write(const std::filesystem::path& target) {
    const Expected<WriteTarget> place = write_target(target);
    if (!place) return place.error();
    if (place->in_place) return {};
    std::vector<char> probe = temporary_pattern(place->file);
    const int fd = ::mkstemp(probe.data());
    if (fd < 0) return temporary_failure(target, place->file, errno);
    ::close(fd);
    ::unlink(probe.data());
    return {};
}

Expected<void> write_file_atomically(const std::filesystem::path& target,
                                     std::span<const std::uint8_t> bytes) {
    return write_file_atomically(target, one_piece(bytes));
}

Expected<void> write_file_atomically(const std::filesystem::path& target,
                                     const BytePieces& next_piece) {
    const Expected<WriteTarget> place = write_target(target);
    if (!place) return place.error();
    if (place->in_place) return write_in_place(target, next_piece);
    const std::filesystem::path& real = place->file;
    // The file replaced keeps its permissions: a private scene stays
    // private, an executable script executable (never set-id bits, which
    // the new file, of another owner perhaps, must not take). A new one is
    // an ordinary readable file.
    struct stat existing {};
    const mode_t mode = ::stat(real.c_str(), &existing) == 0 ? existing.st_mode & 0777 : 0644;
    const Temporary temp = write_temporary(real, next_piece, mode);
    if (temp.error != 0) return temporary_failure(target, real, temp.error);
    const int error = std::rename(temp.name.data(), real.c_str()) != 0 ? errno : 0;
    if (error != 0) ::unlink(temp.name.data());
    unfinished.store(nullptr);
    if (error != 0) return failure(target, error);
    return {};
}

Expected<bool> write_new_file(const std::filesystem::path& target,
                              std::span<const std::uint8_t> bytes) {
    if (target.empty()) return Error{"cannot write an image to an empty file name"};
    const Temporary temp = write_temporary(target, one_piece(bytes), 0644);
    if (temp.error != 0) return failure(target, temp.error);
    // The whole file is there under its temporary name, then linked to its own:
    // readers never see it partial, and link fails if the name is taken.
    const int error = ::link(temp.name.data(), target.c_str()) != 0 ? errno : 0;
    ::unlink(temp.name.data());
    unfinished.store(nullptr);
    if (error == EEXIST) return false;
    if (error != 0) return failure(target, error);
    return true;
}

}  // namespace jt
