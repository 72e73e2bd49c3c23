#pragma once
// 24-bit uncompressed Windows BMP (BITMAPINFOHEADER, BI_RGB): rows bottom-up,
// each padded to 4 bytes, BGR byte order; the first stored row is y = 0.

#include "jtracer/image.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace jt {

std::vector<std::uint8_t> encode_bmp(const Image8& image);

// Reads 24-bit BI_RGB BMPs, bottom-up or top-down. Returns an empty string on
// success, else what is wrong with the bytes.
std::string decode_bmp(std::span<const std::uint8_t> bytes, Image8& image);

// Atomic write (atomic_file.hpp). Empty string on success, else the error.
std::string write_bmp(const std::filesystem::path& path, const Image8& image);
std::string read_bmp(const std::filesystem::path& path, Image8& image);

}  // namespace jt
