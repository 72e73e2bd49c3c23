#pragma once
// PNG output (and input, for tests and reference images) through stb.
// Image8 rows run bottom-up; PNG rows run top-down: both functions flip.

#include "jtracer/image.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace jt {

std::vector<std::uint8_t> encode_png(const Image8& image);
std::string decode_png(std::span<const std::uint8_t> bytes, Image8& image);

// Atomic write (atomic_file.hpp). Empty string on success, else the error.
std::string write_png(const std::filesystem::path& path, const Image8& image);
std::string read_png(const std::filesystem::path& path, Image8& image);

}  // namespace jt
