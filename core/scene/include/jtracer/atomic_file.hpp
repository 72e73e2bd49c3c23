#pragma once
// Writing a file so that readers only ever see the old file or the whole new
// one: the bytes go to a temporary file beside the target, which is then
// renamed over it (docs/language.md §10.3), or linked to its name when the
// file must be new. A failure leaves no file behind.

#include "jtracer/error.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace jt {

// On failure the error names the file and the reason ("cannot write
// 'out/x.bmp': No such file or directory").
Expected<void> write_file_atomically(const std::filesystem::path& target,
                                     std::span<const std::uint8_t> bytes);

// Writes a new file `target` and never replaces one: true when written, false
// when something is already there. The check and the creation are one step
// (link(2)), so a file that appears meanwhile is not overwritten either.
Expected<bool> write_new_file(const std::filesystem::path& target,
                              std::span<const std::uint8_t> bytes);

}  // namespace jt
