#pragma once
// Regions of a frame as users type them, and cutting and pasting images by
// region.
//
// On command lines and in region files a region is X0,Y0,X1,Y1: half-open pixel
// bounds with the origin at the TOP-LEFT corner, y growing downwards, as image
// viewers and editors show pixels. Image8 and PixelRect count rows from the
// bottom (image.hpp); the functions here convert between the two.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"

#include <string>
#include <string_view>

namespace jt {

// A window of a frame in top-left-origin pixel bounds, half-open: columns
// [left, right), rows [top, bottom) counted from the top row.
struct FrameRegion {
    int left = 0, top = 0, right = 0, bottom = 0;
    int width() const { return right - left; }
    int height() const { return bottom - top; }
    bool operator==(const FrameRegion&) const = default;
};

// Parses "X0,Y0,X1,Y1" (whole numbers, X0 < X1, Y0 < Y1); on failure the
// error says what is wrong with the text.
Expected<FrameRegion> parse_frame_region(std::string_view text);

// "X0,Y0,X1,Y1", the form parse_frame_region reads.
std::string format_frame_region(const FrameRegion& region);

// Whether the region lies inside a frame_width x frame_height frame; the error
// says which bound is out.
Expected<void> check_region_in_frame(const FrameRegion& region, int frame_width, int frame_height);

// The same pixels in Image8 coordinates (row 0 at the bottom) of a frame
// `frame_height` rows high, and back (through flipped_row).
PixelRect to_image_rect(const FrameRegion& region, int frame_height);
FrameRegion to_frame_region(const PixelRect& rect, int frame_height);

// The pixels of `rect` (Image8 coordinates, inside `image`: JT_DCHECK) as an
// image of their own.
Image8 crop_image(const Image8& image, const PixelRect& rect);

// Copies `part` into `frame` with its bottom-left pixel at (x0, y0) (Image8
// coordinates); the part must fit (JT_DCHECK).
void paste_image(Image8& frame, const Image8& part, int x0, int y0);

}  // namespace jt
