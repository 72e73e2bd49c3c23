#include "jtracer/image_file.hpp"

#include "io/file_bytes.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"

#include <algorithm>
#include <cctype>

namespace jt {

ImageFormat format_from_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png" ? ImageFormat::png : ImageFormat::bmp;
}

std::string write_image(const std::filesystem::path& path, const Image8& image,
                        ImageFormat format) {
    return format == ImageFormat::png ? write_png(path, image) : write_bmp(path, image);
}

std::string read_image(const std::filesystem::path& path, Image8& image) {
    std::vector<std::uint8_t> bytes;
    if (std::string error = read_file_bytes(path, bytes); !error.empty()) return error;
    std::string error = bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M'
                            ? decode_bmp(bytes, image)
                            : decode_png(bytes, image);
    return error.empty() ? error : file_message(path, error);
}

}  // namespace jt
