#pragma once
// Whole-file reads, with a message instead of an exception.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace jt {

// "'PATH': MESSAGE", built by appending (GCC 12 warns falsely about
// -Wrestrict on chains of operator+ that start from a literal).
std::string file_message(const std::filesystem::path& path, const std::string& message);

// Empty string on success, else "cannot read 'PATH': REASON".
std::string read_file_bytes(const std::filesystem::path& path, std::vector<std::uint8_t>& bytes);

}  // namespace jt
