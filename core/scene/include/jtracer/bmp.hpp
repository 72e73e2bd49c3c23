#pragma once
// 24-bit uncompressed Windows BMP (BITMAPINFOHEADER, BI_RGB): rows bottom-up,
// each padded to 4 bytes, BGR byte order; the first stored row is y = 0.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace jt {

// The largest BMP file: the format's size fields are 32 bits wide. No image
// JTracer renders, writes or reads is larger.
inline constexpr std::uint64_t kMaxBmpFileBytes = 0xFFFFFFFF;

std::vector<std::uint8_t> encode_bmp(const Image8& image);

// Reads 24-bit BI_RGB BMPs, bottom-up or top-down; on failure the error says
// what is wrong with the bytes.
Expected<Image8> decode_bmp(std::span<const std::uint8_t> bytes);

// Atomic write (atomic_file.hpp).
Expected<void> write_bmp(const std::filesystem::path& path, const Image8& image);
Expected<Image8> read_bmp(const std::filesystem::path& path);

}  // namespace jt
