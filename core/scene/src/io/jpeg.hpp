#pragma once
// JPEG pictures, read by libjpeg-turbo (its TurboJPEG API) rather than by
// stb_image: a fuzzed JPEG led stb_image 2.27 (Debian 12's) to write past its
// Huffman tables and to shift by the width of an int, where libjpeg-turbo, the
// reference decoder and fuzzed without end upstream, reports the damage. Its
// SIMD code gives the same texels as its plain C code (the accurate integer
// DCT and fancy upsampling are exact), so the pixels do not depend on the CPU.

#include "jtracer/error.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace jt {

// Whether `bytes` start as a JPEG does (the start-of-image marker).
bool has_jpeg_signature(std::span<const std::uint8_t> bytes);

struct JpegSize {
    int width = 0;
    int height = 0;
};

// The size the frame header gives; an error for a header libjpeg-turbo cannot
// read or colours it does not turn into RGB (CMYK).
Expected<JpegSize> read_jpeg_size(std::span<const std::uint8_t> bytes);

// 8-bit RGB texels, the bottom row first (as a Texture keeps them, with no
// copy to turn them round), of a JPEG whose header gave `size`. A
// damaged file (even one libjpeg would only warn about: data that ends early)
// is an error, never a picture made up in part.
Expected<std::vector<std::uint8_t>> decode_jpeg(std::span<const std::uint8_t> bytes, JpegSize size);

}  // namespace jt
