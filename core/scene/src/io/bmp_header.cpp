#include "io/bmp_header.hpp"

#include <array>
#include <cstdint>

namespace jt {

namespace {

std::uint32_t little16(std::span<const std::uint8_t> b, std::size_t at) {
    return b[at] | std::uint32_t{b[at + 1]} << 8;
}

std::uint32_t little32(std::span<const std::uint8_t> b, std::size_t at) {
    return little16(b, at) | little16(b, at + 2) << 16;
}

// The fields read here: the file header (14 bytes), then the info header's
// size, width, height, planes and bits a pixel, and its compression.
constexpr std::size_t core_header_end = 14 + 12;
constexpr std::size_t info_header_end = 14 + 20;
constexpr std::uint32_t core_header_size = 12;

}  // namespace

bool has_bmp_signature(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M';
}

std::optional<BmpHeader> read_bmp_header(std::span<const std::uint8_t> bytes) {
    if (!has_bmp_signature(bytes) || bytes.size() < core_header_end) return std::nullopt;
    BmpHeader h;
    h.info_size = little32(bytes, 14);
    if (h.info_size == core_header_size) {
        h.width = little16(bytes, 18);
        h.height = little16(bytes, 20);
        h.bits_per_pixel = little16(bytes, 24);
        return h;
    }
    if (bytes.size() < info_header_end) return std::nullopt;
    h.width = static_cast<std::int32_t>(little32(bytes, 18));
    h.height = static_cast<std::int32_t>(little32(bytes, 22));
    h.bits_per_pixel = little16(bytes, 28);
    h.compression = little32(bytes, 30);
    return h;
}

std::string bmp_header_problem(const BmpHeader& h) {
    static constexpr std::array<std::uint32_t, 5> info_sizes = {12, 40, 56, 108, 124};
    bool known_size = false;
    for (std::uint32_t size : info_sizes) known_size = known_size || h.info_size == size;
    if (!known_size)
        return "a BMP whose info header is " + std::to_string(h.info_size) +
               " bytes long is not supported (only 12, 40, 56, 108 and 124)";
    switch (h.compression) {
        case 0:
        case 3:
            break;
        case 1:
        case 2:
            return "RLE-compressed BMP is not supported";
        case 4:
            return "JPEG-compressed BMP is not supported";
        case 5:
            return "PNG-compressed BMP is not supported";
        default:
            return "BMP compression type " + std::to_string(h.compression) + " is not supported";
    }
    static constexpr std::array<std::uint32_t, 6> depths = {1, 4, 8, 16, 24, 32};
    bool known_depth = false;
    for (std::uint32_t bits : depths) known_depth = known_depth || h.bits_per_pixel == bits;
    if (!known_depth)
        return "a BMP of " + std::to_string(h.bits_per_pixel) +
               " bits a pixel is not supported (only 1, 4, 8, 16, 24 and 32)";
    if (h.compression == 3 && h.bits_per_pixel != 16 && h.bits_per_pixel != 32)
        return "a BMP with bit-field masks must have 16 or 32 bits a pixel, not " +
               std::to_string(h.bits_per_pixel);
    return "";
}

}  // namespace jt
