#include "jtracer/image_file.hpp"

#include "io/bmp_header.hpp"
#include "io/file_bytes.hpp"
#include "io/image_claims.hpp"
#include "io/jpeg.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"
#include "jtracer/texture.hpp"

#include <algorithm>
#include <cctype>
#include <span>
#include <string>
#include <vector>

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

namespace {

// A texture read from a BMP or JPEG, whose samples are 8-bit, as an image:
// both keep the bottom row first.
Image8 image_of(Texture&& texture) {
    Image8 image;
    image.width = texture.width;
    image.height = texture.height;
    image.rgb = std::move(texture.rgb8);
    return image;
}

// decode_bmp reads what JTracer writes, 24 bits a pixel uncompressed behind
// a BITMAPINFOHEADER (or a later one). Any other BMP an image map reads (1,
// 4, 8, 16 or 32 bits, bit-field masks, the OS/2 core header) is decoded as
// an image map is, so that a reference saved by another program compares as
// the picture it is instead of being refused.
Expected<Image8> decode_any_bmp(std::span<const std::uint8_t> bytes) {
    constexpr std::uint32_t info_header_size = 40;
    const std::optional<BmpHeader> header = read_bmp_header(bytes);
    if (!header || (header->info_size >= info_header_size && header->bits_per_pixel == 24 &&
                    header->compression == 0))
        return decode_bmp(bytes);
    Expected<Texture> texture = decode_texture(bytes);
    if (!texture) return texture.error();
    return image_of(std::move(*texture));
}

// A BMP or PNG whose bytes were read from `path`, which names it in errors.
Expected<Image8> decode_bmp_or_png(const std::filesystem::path& path,
                                   std::span<const std::uint8_t> bytes) {
    const bool bmp = has_bmp_signature(bytes);
    // Neither signature: what the name says decides which reader explains why.
    const bool named_bmp = format_named_by(path) == ImageFormat::bmp;
    // Neither a BMP nor a PNG, and a format that tells itself: named.
    if (!bmp && !has_png_signature(bytes)) {
        const std::string format =
            has_jpeg_signature(bytes) ? "a JPEG image" : format_not_read(bytes);
        if (!format.empty())
            return Error{
                file_message(path, "it is " + format + ", not a BMP or PNG image: save it as PNG")};
    }
    Expected<Image8> image =
        bmp || (named_bmp && !has_png_signature(bytes)) ? decode_any_bmp(bytes) : decode_png(bytes);
    if (!image) return Error{file_message(path, image.error().message)};
    return image;
}

Expected<std::vector<std::uint8_t>> read_nonempty_file(const std::filesystem::path& path) {
    Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(path);
    if (bytes && bytes->empty()) return Error{file_message(path, "the file is empty")};
    return bytes;
}

}  // namespace

Expected<Image8> read_image(const std::filesystem::path& path) {
    Expected<std::vector<std::uint8_t>> bytes = read_nonempty_file(path);
    if (!bytes) return bytes.error();
    return decode_bmp_or_png(path, *bytes);
}

Expected<Image8> read_shown_image(const std::filesystem::path& path) {
    Expected<std::vector<std::uint8_t>> bytes = read_nonempty_file(path);
    if (!bytes) return bytes.error();
    if (has_jpeg_signature(*bytes)) {
        // Decoded and turned upright as an image map's texels are.
        Expected<Texture> texture = decode_texture(*bytes, TextureLayout::as_shown);
        if (!texture) return Error{file_message(path, texture.error().message)};
        return image_of(std::move(*texture));
    }
    const bool bmp = has_bmp_signature(*bytes);
    // A format that tells itself is named; for other bytes, a name ending in
    // .bmp or .png lets that reader say what is wrong with the file.
    if (!bmp && !has_png_signature(*bytes)) {
        const std::string format = format_not_read(*bytes);
        if (!format.empty())
            return Error{file_message(
                path, "it is " + format + ", not a BMP, PNG or JPEG image: save it as PNG")};
        if (!format_named_by(path))
            return Error{file_message(path, "it is not a BMP, PNG or JPEG image")};
    }
    return decode_bmp_or_png(path, *bytes);
}

}  // namespace jt
