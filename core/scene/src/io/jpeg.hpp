#pragma once
// JPEG pictures, read by libjpeg-turbo (its TurboJPEG API) rather than by
// stb_image: a fuzzed JPEG led stb_image 2.27 (Debian 12's) to write past its
// Huffman tables and to shift by the width of an int, where libjpeg-turbo, the
// reference decoder and fuzzed without end upstream, reports the damage. Its
// SIMD code gives the same texels as its plain C code (the accurate integer
// DCT and fancy upsampling are exact), so the pixels do not depend on the CPU.

#include "jtracer/error.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace jt {

// Whether `bytes` start as a JPEG does (the start-of-image marker).
bool has_jpeg_signature(std::span<const std::uint8_t> bytes);

struct JpegSize {
    int width = 0;
    int height = 0;
};

// The markers of the application segments read: APP1 holds EXIF, APP14
// Adobe's record of how the colours are stored.
inline constexpr std::uint8_t kJpegApp1 = 0xE1;
inline constexpr std::uint8_t kJpegApp14 = 0xEE;

// The data of the first segment with this marker (kJpegApp1, ...) whose data
// starts with `name`, before the picture's data (SOS); its data past `name`.
// Nothing for a JPEG without one, or whose segments are damaged before it.
std::optional<std::span<const std::uint8_t>> jpeg_segment(std::span<const std::uint8_t> jpeg,
                                                          std::uint8_t marker,
                                                          std::string_view name);

// The size the frame header gives; an error for a header libjpeg-turbo cannot
// read.
Expected<JpegSize> read_jpeg_size(std::span<const std::uint8_t> bytes);

// 8-bit RGB texels, the bottom row first (as a Texture keeps them, with no
// copy to turn them round), of a JPEG whose header gave `size`. A
// damaged file (even one libjpeg would only warn about: data that ends early)
// is an error, never a picture made up in part. A CMYK (or YCCK) JPEG, as
// print work and Photoshop save them, is turned into RGB as browsers, Pillow
// and GIMP without a colour profile show it: each of R, G and B is the white
// its ink (C, M or Y) and the black ink (K) leave, multiplied, R = (1 - C) (1 - K).
// A JPEG with Adobe's APP14 segment stores its inks inverted (255: no ink),
// as Adobe's programs write them; one without stores them as amounts.
Expected<std::vector<std::uint8_t>> decode_jpeg(std::span<const std::uint8_t> bytes, JpegSize size);

}  // namespace jt
