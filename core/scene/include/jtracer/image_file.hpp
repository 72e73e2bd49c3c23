#pragma once
// Choosing an image format from a file name.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"

#include <filesystem>
#include <string>

namespace jt {

enum class ImageFormat { bmp, png };

// PNG when the name ends in ".png" (any case), else BMP. Only for names the
// user typed on a command line: the scene's `filename` is always BMP.
ImageFormat format_from_extension(const std::filesystem::path& path);

// Atomic write in the given format.
Expected<void> write_image(const std::filesystem::path& path, const Image8& image,
                           ImageFormat format);

// Reads a BMP or PNG, told apart by their first bytes.
Expected<Image8> read_image(const std::filesystem::path& path);

}  // namespace jt
