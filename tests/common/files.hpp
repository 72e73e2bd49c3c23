#pragma once
// Whole-file reads and writes for tests.

#include <filesystem>
#include <string>
#include <string_view>

namespace jt::test {

// The file's bytes; empty when it cannot be read.
std::string read_file(const std::filesystem::path& path);

void write_file(const std::filesystem::path& path, std::string_view bytes);

}  // namespace jt::test
