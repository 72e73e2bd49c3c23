#pragma once
// What a picture's header claims, weighed before stb_image allocates for it:
// a few bytes claiming millions of pixels would otherwise have it reserve the
// whole image and decode zeros for seconds (found by fuzz/image_map_fuzzer: a
// 90-byte BMP claiming 5x11665411 pixels).

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>

namespace jt {

// The width and height a PNG's IHDR chunk claims, or nothing when the bytes do
// not start like a PNG.
std::optional<std::pair<std::int64_t, std::int64_t>> png_claimed_size(
    std::span<const std::uint8_t> bytes);

// The fewest bytes a PNG, BMP or JPEG of `width` x `height` pixels can take,
// from the header's own pixel format: a BMP stores every pixel (an
// uncompressed one its padded rows from the header's pixel offset on, to the
// byte); deflate packs
// at most 1032 bytes into one; a JPEG spends at least 2 bits on each 8x8
// block. 0 for anything else.
std::uint64_t fewest_bytes_for(std::span<const std::uint8_t> bytes, std::int64_t width,
                               std::int64_t height);

// The format of a picture in a format JTracer does not read (GIF, Netpbm,
// TIFF, WebP, a TGA of version 2), told by its signature, as "a GIF image";
// or "" for any other bytes: stb_image only says "unknown image type".
std::string format_not_read(std::span<const std::uint8_t> bytes);

}  // namespace jt
