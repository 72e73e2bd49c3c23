#include "jtracer/region.hpp"

#include "jtracer/check.hpp"

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
    if (r.left < 0 || r.top < 0) {
        return Error{quoted + ": X0 and Y0 must not be negative"};
    }
    if (r.right <= r.left || r.bottom <= r.top) {
        return Error{quoted +
                     " is empty: the bounds are half-open, so X1 must exceed X0 and Y1 Y0"};
    }
    return r;
}

std::string format_frame_region(const FrameRegion& r) {
    std::string text = std::to_string(r.left);
    for (int v : {r.top, r.right, r.bottom}) text.append(",").append(std::to_string(v));
    return text;
}

Expected<void> check_region_in_frame(const FrameRegion& r, int frame_width, int frame_height) {
    std::string message = "region ";
    message += format_frame_region(r);
    const std::string frame = std::to_string(frame_width) + "x" + std::to_string(frame_height);
    if (r.left < 0 || r.top < 0 || r.right <= r.left || r.bottom <= r.top)
        return Error{message + " is empty or has negative bounds"};
    if (r.right > frame_width)
        return Error{message + " reaches past the right edge of the " + frame +
                     " image (X1 may be at most " + std::to_string(frame_width) + ")"};
    if (r.bottom > frame_height)
        return Error{message + " reaches past the bottom edge of the " + frame +
                     " image (Y1 may be at most " + std::to_string(frame_height) + ")"};
    return {};
}

// A half-open span of rows [first, end) counted from one edge is
// [flipped_row(end - 1), flipped_row(first) + 1) counted from the other.
PixelRect to_image_rect(const FrameRegion& r, int frame_height) {
    return {r.left, flipped_row(r.bottom - 1, frame_height), r.right,
            flipped_row(r.top, frame_height) + 1};
}

FrameRegion to_frame_region(const PixelRect& r, int frame_height) {
    return {r.x0, flipped_row(r.y1 - 1, frame_height), r.x1, flipped_row(r.y0, frame_height) + 1};
}

Image8 crop_image(const Image8& image, const PixelRect& rect) {
    JT_DCHECK(rect.x0 >= 0 && rect.y0 >= 0 && rect.x1 <= image.width && rect.y1 <= image.height &&
                  !rect.empty(),
              "the rectangle lies inside the image");
    Image8 part(rect.width(), rect.height());
    const std::size_t row_bytes = static_cast<std::size_t>(rect.width()) * 3;
    for (int y = 0; y < rect.height(); ++y)
        std::copy_n(image.pixel(rect.x0, rect.y0 + y), row_bytes, part.pixel(0, y));
    return part;
}

void paste_image(Image8& frame, const Image8& part, int x0, int y0) {
    JT_DCHECK(
        x0 >= 0 && y0 >= 0 && x0 + part.width <= frame.width && y0 + part.height <= frame.height,
        "the part fits inside the frame");
    const std::size_t row_bytes = static_cast<std::size_t>(part.width) * 3;
    for (int y = 0; y < part.height; ++y)
        std::copy_n(part.pixel(0, y), row_bytes, frame.pixel(x0, y0 + y));
}

}  // namespace jt
