#pragma once
// What a PNG file's header says, for tests of programs that write one, and
// PNG files put together chunk by chunk, for tests of readers.

#include <cstdint>
#include <string_view>
#include <vector>

namespace jt::test {

struct PngSize {
    unsigned width = 0;
    unsigned height = 0;
};

// The size in the IHDR chunk of a PNG file's bytes; {0, 0} when they are too
// short to hold one.
PngSize png_size(std::string_view bytes);

// Appends a chunk of `type` (four letters) holding `data` to a PNG's bytes,
// with a zero CRC: the readers under test check none.
void append_png_chunk(std::vector<std::uint8_t>& png, const char* type,
                      const std::vector<std::uint8_t>& data);

// The eight bytes every PNG file starts with.
std::vector<std::uint8_t> png_signature();

}  // namespace jt::test
