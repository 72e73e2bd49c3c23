#include "jtracer/region.hpp"

#include <algorithm>
#include <charconv>
#include <vector>

namespace jt {

namespace {

// Splits at commas; each piece must be a whole number in int range.
bool parse_ints(std::string_view text, std::vector<int>& values) {
    values.clear();
    std::size_t start = 0;
    while (true) {
        std::size_t comma = text.find(',', start);
        std::string_view piece = text.substr(
            start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        int value = 0;
        auto [end, ec] = std::from_chars(piece.data(), piece.data() + piece.size(), value);
        if (piece.empty() || ec != std::errc() || end != piece.data() + piece.size()) return false;
        values.push_back(value);
        if (comma == std::string_view::npos) return true;
        start = comma + 1;
    }
}

}  // namespace

Expected<FrameRegion> parse_frame_region(std::string_view text) {
    // Messages are built by appending: GCC 12 warns falsely (-Wrestrict) about
    // chains of operator+ that start from a literal.
    std::string quoted = "\"";
    quoted.append(text).append("\"");
    std::vector<int> v;
    if (!parse_ints(text, v) || v.size() != 4) {
        std::string message = "expected X0,Y0,X1,Y1 (four whole numbers separated by commas), got ";
        message += quoted;
        return Error{message};
    }
    FrameRegion r{v[0], v[1], v[2], v[3]};
    if (r.x0 < 0 || r.y0 < 0) {
        return Error{quoted + ": X0 and Y0 must not be negative"};
    }
    if (r.x1 <= r.x0 || r.y1 <= r.y0) {
        return Error{quoted +
                     " is empty: the bounds are half-open, so X1 must exceed X0 and Y1 Y0"};
    }
    return r;
}

std::string format_frame_region(const FrameRegion& r) {
    std::string text = std::to_string(r.x0);
    for (int v : {r.y0, r.x1, r.y1}) text.append(",").append(std::to_string(v));
    return text;
}

Expected<void> check_region_in_frame(const FrameRegion& r, int frame_width, int frame_height) {
    std::string message = "region ";
    message += format_frame_region(r);
    const std::string frame = std::to_string(frame_width) + "x" + std::to_string(frame_height);
    if (r.x0 < 0 || r.y0 < 0 || r.x1 <= r.x0 || r.y1 <= r.y0)
        return Error{message + " is empty or has negative bounds"};
    if (r.x1 > frame_width)
        return Error{message + " reaches past the right edge of the " + frame +
                     " image (X1 may be at most " + std::to_string(frame_width) + ")"};
    if (r.y1 > frame_height)
        return Error{message + " reaches past the bottom edge of the " + frame +
                     " image (Y1 may be at most " + std::to_string(frame_height) + ")"};
    return {};
}

PixelRect to_image_rect(const FrameRegion& r, int frame_height) {
    return {r.x0, frame_height - r.y1, r.x1, frame_height - r.y0};
}

FrameRegion to_frame_region(const PixelRect& r, int frame_height) {
    return {r.x0, frame_height - r.y1, r.x1, frame_height - r.y0};
}

Image8 crop_image(const Image8& image, const PixelRect& rect) {
    Image8 part(rect.width(), rect.height());
    const std::size_t row_bytes = static_cast<std::size_t>(rect.width()) * 3;
    for (int y = 0; y < rect.height(); ++y)
        std::copy_n(image.pixel(rect.x0, rect.y0 + y), row_bytes, part.pixel(0, y));
    return part;
}

void paste_image(Image8& frame, const Image8& part, int x0, int y0) {
    const std::size_t row_bytes = static_cast<std::size_t>(part.width) * 3;
    for (int y = 0; y < part.height; ++y)
        std::copy_n(part.pixel(0, y), row_bytes, frame.pixel(x0, y0 + y));
}

}  // namespace jt
