#include "jtracer/image_file.hpp"

#include "io/file_bytes.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"

#include <algorithm>
#include <cctype>

namespace jt {

std::optional<ImageFormat> format_named_by(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") return ImageFormat::png;
    if (ext == ".bmp") return ImageFormat::bmp;
    return std::nullopt;
}

ImageFormat format_from_extension(const std::filesystem::path& path) {
    return format_named_by(path).value_or(ImageFormat::bmp);
}

std::vector<std::uint8_t> encode_image(const Image8& image, ImageFormat format) {
    return format == ImageFormat::png ? encode_png(image) : encode_bmp(image);
}

Expected<void> write_image(const std::filesystem::path& path, const Image8& image,
                           ImageFormat format) {
    return format == ImageFormat::png ? write_png(path, image) : write_bmp(path, image);
}

Expected<Image8> read_image(const std::filesystem::path& path) {
    Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(path);
    if (!bytes) return bytes.error();
    if (bytes->empty()) return Error{file_message(path, "the file is empty")};
    const bool bmp = bytes->size() >= 2 && (*bytes)[0] == 'B' && (*bytes)[1] == 'M';
    // Neither signature: what the name says decides which reader explains why.
    const bool named_bmp = format_named_by(path) == ImageFormat::bmp;
    Expected<Image8> image =
        bmp || (named_bmp && !has_png_signature(*bytes)) ? decode_bmp(*bytes) : decode_png(*bytes);
    if (!image) return Error{file_message(path, image.error().message)};
    return image;
}

}  // namespace jt
