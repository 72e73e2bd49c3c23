#include "image_files.hpp"

#include "jtracer/atomic_file.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <span>

namespace jt::view {

ImageFormat image_format_for(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") return ImageFormat::png;
    if (ext == ".bmp") return ImageFormat::bmp;
    return ImageFormat::unknown;
}

Expected<void> write_text_atomically(const std::filesystem::path& path, const std::string& text) {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()),
                                              text.size());
    return write_file_atomically(path, bytes);
}

Expected<void> save_image(const std::filesystem::path& path, const Image8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
        return Error{"there is no image to save yet"};
    switch (image_format_for(path)) {
        case ImageFormat::png:
            return write_png(path, image);
        case ImageFormat::bmp:
            return write_bmp(path, image);
        case ImageFormat::unknown:
            break;
    }
    return Error{"cannot tell the image format of " + path.string() + ": name it .png or .bmp"};
}

}  // namespace jt::view
