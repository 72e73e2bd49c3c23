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

}  // namespace jt::test
