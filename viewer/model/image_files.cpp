#include "model/image_files.hpp"

#include "jtracer/atomic_file.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace jt::view {

namespace {

std::string unknown_format_message(const std::filesystem::path& path) {
    return "cannot tell the image format of " + path.string() + ": name it .png or .bmp";
}

std::string os_error(const std::filesystem::path& path, int error) {
    return "cannot write " + path.string() + ": " + std::strerror(error);
}

}  // namespace

Expected<void> write_text_atomically(const std::filesystem::path& path, const std::string& text) {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()),
                                              text.size());
    return write_file_atomically(path, bytes);
}

Expected<void> save_image(const std::filesystem::path& path, const Image8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
        return Error{"there is no image to save yet"};
    const std::optional<ImageFormat> format = format_named_by(path);
    if (!format) return Error{unknown_format_message(path)};
    return write_image(path, image, *format);
}

Expected<bool> save_new_image(const std::filesystem::path& path, const Image8& image) {
    if (image.width <= 0 || image.height <= 0) return Error{"there is no image to save yet"};
    const std::optional<ImageFormat> format = format_named_by(path);
    if (!format) return Error{unknown_format_message(path)};
    const std::vector<std::uint8_t> bytes = encode_image(image, *format);
    // The whole file is written under a temporary name, then linked to its
    // name: readers never see it partial, and link fails if the name is taken.
    std::string pattern = path.string() + ".tmp-XXXXXX";
    std::vector<char> temp(pattern.begin(), pattern.end());
    temp.push_back('\0');
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) return Error{os_error(path, errno)};
    std::size_t done = 0;
    int failure = 0;
    while (done < bytes.size() && failure == 0) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno != EINTR) failure = errno;
        if (n > 0) done += static_cast<std::size_t>(n);
    }
    ::fchmod(fd, 0644);
    if (failure == 0 && ::fsync(fd) != 0 && errno != EINVAL) failure = errno;
    if (::close(fd) != 0 && failure == 0) failure = errno;
    if (failure == 0 && ::link(temp.data(), path.c_str()) != 0) failure = errno;
    ::unlink(temp.data());
    if (failure == EEXIST) return false;
    if (failure != 0) return Error{os_error(path, failure)};
    return true;
}

Expected<std::filesystem::path> save_image_numbered(const std::filesystem::path& path,
                                                    const Image8& image) {
    constexpr int most_numbers = 999;
    for (int number = 0; number <= most_numbers; ++number) {
        std::filesystem::path name = path;
        if (number > 0) {
            char suffix[8];
            std::snprintf(suffix, sizeof suffix, "-%03d", number);
            name = path.parent_path() / (path.stem().string() + suffix + path.extension().string());
        }
        Expected<bool> written = save_new_image(name, image);
        if (!written) return written.error();
        if (*written) return name;
    }
    return Error{"every name from " + path.filename().string() +
                 " to -999 is taken: choose another"};
}

}  // namespace jt::view
