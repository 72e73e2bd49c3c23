#include "model/image_files.hpp"

#include "jtracer/atomic_file.hpp"

#include <cstdint>
#include <cstdio>
#include <span>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace jt::view {

namespace {

std::string unknown_format_message(const std::filesystem::path& path) {
    return "cannot tell the image format of " + path.string() + ": name it .png or .bmp";
}

}  // namespace

Expected<void> write_text_atomically(const std::filesystem::path& path, const std::string& text) {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()),
                                              text.size());
    return write_file_atomically(path, bytes);
}

Expected<void> check_writable(const std::filesystem::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return {};
    // root may write anything: the mode bits alone say the file is read-only.
    if ((st.st_mode & 0222) == 0 || ::access(path.c_str(), W_OK) != 0)
        return Error{"cannot write " + path.string() +
                     ": the file is read-only (Save scene as writes a copy)"};
    return {};
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
    return write_new_file(path, encode_image(image, *format));
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
