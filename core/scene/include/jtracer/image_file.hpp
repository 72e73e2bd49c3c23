#pragma once
// Choosing an image format from a file name.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace jt {

enum class ImageFormat { bmp, png };

// The format a file's name asks for: ".png" or ".bmp" in any case; none for
// any other name (for a program that must refuse a name it cannot honour).
std::optional<ImageFormat> format_named_by(const std::filesystem::path& path);

// PNG when the name ends in ".png" (any case), else BMP. Only for names the
// user typed on a command line: the scene's `filename` is always BMP.
ImageFormat format_from_extension(const std::filesystem::path& path);

// The file's bytes in the given format.
std::vector<std::uint8_t> encode_image(const Image8& image, ImageFormat format);

// Atomic write in the given format.
Expected<void> write_image(const std::filesystem::path& path, const Image8& image,
                           ImageFormat format);

// Reads a BMP or PNG, told apart by their first bytes.
Expected<Image8> read_image(const std::filesystem::path& path);

// Reads a BMP, PNG or JPEG, told apart by their first bytes, as an image map
// shows it: a JPEG turned upright by its EXIF orientation, a CMYK one made
// RGB. For pictures looked at, not references: a JPEG is lossy.
Expected<Image8> read_shown_image(const std::filesystem::path& path);

}  // namespace jt
