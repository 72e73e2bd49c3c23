#pragma once
// The file each frame of a sequence is written to (docs/language.md §15.4):
// -o's pattern with one %d or %0Nd field (N 1..9; %% a percent sign), or,
// without -o, the scene's filename with "-" and the frame number (at least
// four digits) before the extension of its last path component.

#include "jtracer/error.hpp"

#include <string>
#include <string_view>

namespace jt::frontend {

struct FrameNamePattern {
    std::string before;  // the text before the field, %% already made %
    std::string after;   // and after it
    int digits = 0;      // %0Nd: N (zero-padded); %d: 0
};

// Reads -o's pattern. Fails, saying what is wrong, on a second field, no
// field, %0d or %00d, a width over 9, or any other use of %.
Expected<FrameNamePattern> parse_frame_name_pattern(std::string_view pattern);

// The pattern with `frame` in its field.
std::string frame_file_name(const FrameNamePattern& pattern, int frame);

// "out/shot.bmp", 7 -> "out/shot-0007.bmp"; "out/shot" -> "out/shot-0007";
// "a.d/shot" -> "a.d/shot-0007". Never reads % in `filename`.
std::string numbered_file_name(std::string_view filename, int frame);

}  // namespace jt::frontend
