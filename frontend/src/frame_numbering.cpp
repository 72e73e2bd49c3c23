#include "jtracer/frontend/frame_numbering.hpp"

#include <charconv>

namespace jt::frontend {

namespace {

// A frame number: decimal digits only (no sign, no spaces), within an int.
bool read_frame(std::string_view text, int& frame) {
    if (text.empty()) return false;
    for (char c : text)
        if (c < '0' || c > '9') return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), frame);
    return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

double frame_clock(int frame, int count) {
    if (count <= 1) return 0.0;
    return static_cast<double>(frame) / static_cast<double>(count - 1);
}

std::string shortest_decimal(double value) {
    char text[64];
    // std::to_chars without a format or precision is the shortest round trip.
    auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return ec == std::errc() ? std::string(text, end) : std::string("nan");
}

Expected<FrameRange> parse_frame_range(std::string_view text) {
    const std::size_t dots = text.find("..");
    FrameRange range;
    if (dots == std::string_view::npos || !read_frame(text.substr(0, dots), range.first) ||
        !read_frame(text.substr(dots + 2), range.last))
        return Error{"expected A..B, two frame numbers counted from 0 (such as 0..11), got '" +
                     std::string(text.substr(0, 40)) + "'"};
    if (range.first > range.last)
        return Error{"the first frame " + std::to_string(range.first) + " comes after the last " +
                     std::to_string(range.last)};
    return range;
}

Expected<void> check_frame_range(const FrameRange& range, int count) {
    if (range.last > count - 1)
        return Error{"frame " + std::to_string(range.last) + " is past the last frame of " +
                     std::to_string(count) + " (frames are 0.." + std::to_string(count - 1) + ")"};
    return {};
}

}  // namespace jt::frontend
