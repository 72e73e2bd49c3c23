#pragma once
// Assimp's reasons for a model it cannot read, in words that name the cause:
// it says "Failed to open file" for a zip it cannot open, "no valid file" or
// nothing at all for UTF-16 text, and quotes 200 bytes of the file where a
// number should be. These read the file's bytes and say what is wrong there.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace jt {

// Why a file whose text starts with a UTF-16 or UTF-32 byte order mark cannot
// be read, or "" when it does not start with one.
std::string wide_text_problem(std::span<const std::uint8_t> bytes);

// Why a file whose first bytes name a format this Assimp was built without
// (VRML, Model 3D: Debian's has neither) cannot be read, or "". Assimp would
// take such a file for another format and fail in that format's words, or
// read it as a model of nothing.
std::string unread_format_problem(std::span<const std::uint8_t> head, bool reads_vrml,
                                  bool reads_m3d);

// A file the reader read for the model: an OBJ's material library, named as
// the model's `mtllib` line names it.
struct ReadAlongside {
    std::string name;
    std::vector<std::uint8_t> bytes;
};

// Assimp's `reason` for refusing `bytes`, reworded when the bytes tell the
// cause better: a compressed or zip file it does not open, and a number that
// does not parse, located by line, column and byte in the model or in one of
// the `libraries` it read. Otherwise `reason`.
std::string import_failure(const std::string& reason, std::span<const std::uint8_t> bytes,
                           std::span<const ReadAlongside> libraries = {});

}  // namespace jt
