#include "io/image_claims.hpp"

#include "io/bmp_header.hpp"
#include "jtracer/png.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string>
#include <string_view>

namespace jt {

namespace {

std::uint64_t big_endian32(std::span<const std::uint8_t> bytes, std::size_t at) {
    std::uint64_t value = 0;
    for (std::size_t i = at; i < at + 4; ++i) value = value << 8 | bytes[i];
    return value;
}

// Bits a pixel of a PNG's colour type and bit depth (IHDR bytes 24 and 25).
std::uint64_t png_bits_per_pixel(std::uint8_t depth, std::uint8_t colour_type) {
    switch (colour_type) {
        case 0:
            return depth;  // grey
        case 2:
            return 3u * depth;  // RGB
        case 3:
            return depth;  // palette index
        case 4:
            return 2u * depth;  // grey and alpha
        case 6:
            return 4u * depth;  // RGBA
        default:
            return 1;
    }
}

}  // namespace

std::optional<std::pair<std::int64_t, std::int64_t>> png_claimed_size(
    std::span<const std::uint8_t> bytes) {
    // The signature, then the IHDR chunk: its length (13), its type, width, height.
    static constexpr std::uint8_t ihdr[8] = {0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    if (bytes.size() < 26 || !has_png_signature(bytes) ||
        !std::equal(std::begin(ihdr), std::end(ihdr), bytes.begin() + 8))
        return std::nullopt;
    return std::pair{static_cast<std::int64_t>(big_endian32(bytes, 16)),
                     static_cast<std::int64_t>(big_endian32(bytes, 20))};
}

std::uint64_t fewest_bytes_for(std::span<const std::uint8_t> bytes, std::int64_t width,
                               std::int64_t height) {
    if (width <= 0 || height <= 0) return 0;
    const auto w = static_cast<std::uint64_t>(width), h = static_cast<std::uint64_t>(height);
    if (png_claimed_size(bytes)) {
        const std::uint64_t row = (w * png_bits_per_pixel(bytes[24], bytes[25]) + 7) / 8;
        return h * (1 + row) / 1032;  // a filter byte a row
    }
    if (has_bmp_signature(bytes)) {
        // A header cut short before its bit count counts one bit a pixel.
        const std::optional<BmpHeader> header = read_bmp_header(bytes);
        const std::uint64_t bits = header ? std::max<std::uint64_t>(1, header->bits_per_pixel) : 1;
        // Uncompressed (or bit-field) rows fill the file exactly from the
        // offset its header gives, each padded to 4 bytes: one cut short by
        // less than its headers take would read its last rows as zeros.
        if (header && (header->compression == 0 || header->compression == 3)) {
            const std::uint64_t offset = bytes[10] | bytes[11] << 8 | bytes[12] << 16 |
                                         static_cast<std::uint64_t>(bytes[13]) << 24;
            return offset + h * ((w * bits + 31) / 32 * 4);
        }
        return h * ((w * bits + 7) / 8);
    }
    if (bytes.size() >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8)
        return ((w + 7) / 8) * ((h + 7) / 8) / 4;
    return 0;
}

std::string format_not_read(std::span<const std::uint8_t> bytes) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (text.starts_with("GIF87a") || text.starts_with("GIF89a")) return "a GIF image";
    if (text.size() > 2 && text[0] == 'P' && text[1] >= '1' && text[1] <= '7' &&
        std::isspace(static_cast<unsigned char>(text[2])))
        return "a Netpbm image (PBM, PGM or PPM)";
    if (text.starts_with(std::string_view("II*\0", 4)) ||
        text.starts_with(std::string_view("MM\0*", 4)))
        return "a TIFF image";
    if (text.size() >= 12 && text.starts_with("RIFF") && text.substr(8, 4) == "WEBP")
        return "a WebP image";
    if (text.ends_with(std::string_view("TRUEVISION-XFILE.\0", 18))) return "a TGA image";
    return "";
}

}  // namespace jt
