#pragma once
// PNG output (and input, for tests and reference images) through stb.
// Image8 rows run bottom-up; PNG rows run top-down: both functions flip.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace jt {

std::vector<std::uint8_t> encode_png(const Image8& image);
// Refuses anything that does not start with the PNG signature.
Expected<Image8> decode_png(std::span<const std::uint8_t> bytes);

bool has_png_signature(std::span<const std::uint8_t> bytes);

// Atomic write (atomic_file.hpp).
Expected<void> write_png(const std::filesystem::path& path, const Image8& image);
Expected<Image8> read_png(const std::filesystem::path& path);

}  // namespace jt
