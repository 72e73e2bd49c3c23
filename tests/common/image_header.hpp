#pragma once
// What a PNG file's header says, for tests of programs that write one.

#include <string_view>

namespace jt::test {

struct PngSize {
    unsigned width = 0;
    unsigned height = 0;
};

// The size in the IHDR chunk of a PNG file's bytes; {0, 0} when they are too
// short to hold one.
PngSize png_size(std::string_view bytes);

}  // namespace jt::test
