#pragma once
// Whole-file reads and the wording of file errors.

#include "jtracer/error.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace jt {

// "'PATH': MESSAGE", built by appending (GCC 12 warns falsely about
// -Wrestrict on chains of operator+ that start from a literal).
std::string file_message(const std::filesystem::path& path, const std::string& message);

// Why `path` could not be opened or read, from its errno, in the words every
// read of a scene, model or picture uses: "no such file", "permission
// denied", "it is a directory, not a file", the links of a cycle of symbolic
// links; the system's own otherwise.
std::string read_failure_reason(const std::filesystem::path& path, int error);

// The file's bytes, or "cannot read 'PATH': REASON".
Expected<std::vector<std::uint8_t>> read_file_bytes(const std::filesystem::path& path);

}  // namespace jt
