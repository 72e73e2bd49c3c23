#pragma once
// PNG pixels read by libpng straight into the rows a Texture or an Image8
// keeps, the bottom row first, so that a picture is held once while it is
// read: a large sky map (16-bit, 8192 x 4096: 200 MB of texels) would
// otherwise be held two or three times at the peak, as stb_image keeps the
// inflated data and the unfiltered image at once, and its top-down rows must
// then be turned round.
//
// It reads as stb_image did, so that no picture changes: palette and grey
// pictures are expanded to RGB, alpha and tRNS are dropped (not blended),
// gAMA, sRGB, iCCP and sBIT are ignored, and chunk CRCs are not checked.

#include "jtracer/error.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace jt {

struct PngPixels {
    int width = 0;
    int height = 0;
    // RGB samples, the bottom row first: rgb16 (native byte order) for a
    // 16-bit PNG read with `keep_16_bits`, else rgb8 (16-bit samples cut to
    // their high byte, as stb_image does).
    std::vector<std::uint8_t> rgb8;
    std::vector<std::uint16_t> rgb16;
};

// The pixels of the PNG `bytes`, or why they cannot be read ("its data is
// damaged (...)", "its data ends early ...", "too large (...)" past
// kMaxTextureTexels pixels, the image maps' limit).
Expected<PngPixels> read_png_pixels(std::span<const std::uint8_t> bytes, bool keep_16_bits);

}  // namespace jt
