#pragma once
// Writes the current render or a screenshot to disk with the core's writers:
// PNG or BMP chosen by the file's extension, written to a temporary name and
// renamed into place so that a failure never leaves a half-written file.

#include "jtracer/image.hpp"

#include <filesystem>
#include <string>

namespace jt::view {

enum class ImageFormat { png, bmp, unknown };
ImageFormat image_format_for(const std::filesystem::path& path);

// Returns false and explains in `error` on failure; the target is untouched then.
bool save_image(const std::filesystem::path& path, const Image8& image, std::string& error);

// Writes `text` to `path` through a temporary file beside it and a rename.
bool write_text_atomically(const std::filesystem::path& path, const std::string& text,
                           std::string& error);

}  // namespace jt::view
