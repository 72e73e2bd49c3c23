#pragma once
// The frames of a sequence and their clocks (docs/language.md §15.4): frame f
// of N has clock f / (N - 1), and 0 when N is 1; --frame-range A..B picks the
// frames A to B, both included.

#include "jtracer/error.hpp"

#include <string>
#include <string_view>

namespace jt::frontend {

struct FrameRange {
    int first = 0;  // 0-based, inclusive
    int last = 0;   // inclusive
    bool operator==(const FrameRange&) const = default;
};

// (double) frame / (double) (count - 1); 0 when count is 1.
double frame_clock(int frame, int count);

// The shortest decimal that reads back as `value` ("0.25", "0.3333333333333333"):
// what --clock must be given to render one frame of a sequence alone.
std::string shortest_decimal(double value);

// "A..B" with 0 <= A <= B (decimal digits only). The error says what is
// wrong, without the option's name.
Expected<FrameRange> parse_frame_range(std::string_view text);

// B <= count - 1; the error names the count.
Expected<void> check_frame_range(const FrameRange& range, int count);

}  // namespace jt::frontend
