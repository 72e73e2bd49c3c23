#include "common/image_header.hpp"

#include <cstdint>

namespace jt::test {

namespace {

// A big-endian 32-bit number, as PNG stores them.
unsigned be32(std::string_view bytes, std::size_t at) {
    return (unsigned(std::uint8_t(bytes[at])) << 24) |
           (unsigned(std::uint8_t(bytes[at + 1])) << 16) |
           (unsigned(std::uint8_t(bytes[at + 2])) << 8) | unsigned(std::uint8_t(bytes[at + 3]));
}

}  // namespace

PngSize png_size(std::string_view bytes) {
    // 8 bytes of signature, the chunk's length and "IHDR", then width and height.
    if (bytes.size() < 24) return {};
    return {be32(bytes, 16), be32(bytes, 20)};
}

void append_png_chunk(std::vector<std::uint8_t>& png, const char* type,
                      const std::vector<std::uint8_t>& data) {
    const auto length = static_cast<std::uint32_t>(data.size());
    for (int shift : {24, 16, 8, 0}) png.push_back(static_cast<std::uint8_t>(length >> shift));
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    png.insert(png.end(), 4, 0);
}

std::vector<std::uint8_t> png_signature() {
    return {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
}

}  // namespace jt::test
