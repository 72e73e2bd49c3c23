#pragma once
// Writing a file so that readers only ever see the old file or the whole new
// one: the bytes go to a temporary file beside the target, which is then
// renamed over it (docs/language.md §10.3). A failure leaves no file behind.

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

}  // namespace jt
