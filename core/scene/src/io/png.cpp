#include "jtracer/png.hpp"

#include "io/file_bytes.hpp"
#include "io/png_reader.hpp"
#include "jtracer/atomic_file.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <limits>

namespace jt {

namespace {

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* p = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), p, p + size);
}

}  // namespace

bool has_png_signature(std::span<const std::uint8_t> bytes) {
    static constexpr std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    return bytes.size() >= sizeof signature &&
           std::equal(std::begin(signature), std::end(signature), bytes.begin());
}

std::vector<std::uint8_t> encode_png(const Image8& image) {
    std::vector<std::uint8_t> out;
    if (image.width <= 0 || image.height <= 0) return out;
    const int stride = image.width * 3;
    // Start at the top row and step down through memory: PNG stores top first.
    const std::uint8_t* top = image.pixel(0, flipped_row(0, image.height));
    stbi_write_png_to_func(append_bytes, &out, image.width, image.height, 3, top, -stride);
    return out;
}

Expected<Image8> decode_png(std::span<const std::uint8_t> bytes) {
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return Error{"PNG file too large"};
    if (!has_png_signature(bytes))
        return Error{"not a readable PNG: it does not start with the PNG signature"};
    Expected<PngPixels> pixels = read_png_pixels(bytes, false);
    if (!pixels) return Error{"not a readable PNG: " + pixels.error().message};
    Image8 image;
    image.width = pixels->width;
    image.height = pixels->height;
    image.rgb = std::move(pixels->rgb8);
    return image;
}

Expected<void> write_png(const std::filesystem::path& path, const Image8& image) {
    std::vector<std::uint8_t> bytes = encode_png(image);
    if (bytes.empty()) return Error{"cannot encode " + file_message(path, "PNG encoder failed")};
    return write_file_atomically(path, bytes);
}

Expected<Image8> read_png(const std::filesystem::path& path) {
    Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(path);
    if (!bytes) return bytes.error();
    Expected<Image8> image = decode_png(*bytes);
    if (!image) return Error{file_message(path, image.error().message)};
    return image;
}

}  // namespace jt
