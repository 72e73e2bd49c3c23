#pragma once
// Writes the current render or a screenshot to disk with the core's writers:
// PNG or BMP chosen by the file's extension, written to a temporary name and
// renamed into place so that a failure never leaves a half-written file.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"
#include "jtracer/image_file.hpp"

#include <filesystem>
#include <string>

namespace jt::view {

// The format from the name's extension (format_named_by): a name that is
// neither .png nor .bmp is refused. On failure the target is untouched.
Expected<void> save_image(const std::filesystem::path& path, const Image8& image);

// Writes a new file `path` and never replaces one (core's write_new_file):
// true when written, false when something is already there.
Expected<bool> save_new_image(const std::filesystem::path& path, const Image8& image);

// Saves under `path`, or when that exists under the first free numbered name
// beside it (name-001.png, name-002.png, ...). Returns the name written.
Expected<std::filesystem::path> save_image_numbered(const std::filesystem::path& path,
                                                    const Image8& image);

// Writes `text` to `path` through a temporary file beside it and a rename.
Expected<void> write_text_atomically(const std::filesystem::path& path, const std::string& text);

// An error when `path` is a file the user may not write (no write permission
// for anyone, or none for this user): the rename of an atomic write would
// replace it all the same, as the folder allows, so a save asks this first.
// A file that is not there may be written.
Expected<void> check_writable(const std::filesystem::path& path);

}  // namespace jt::view
