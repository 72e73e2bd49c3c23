#pragma once
// Images as plain pixel arrays.
//
// Pixel (x, y) follows docs/language.md §7.3: x from the left, y from the
// bottom. Row 0 is the bottom row, as in a BMP and an OpenGL texture. Files
// that store the top row first, screens and the regions users type count
// rows from the top (region.hpp's FrameRegion): flipped_row below is the one
// conversion between the two.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace jt {

// 8-bit RGB, tightly packed, 3 bytes a pixel.
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;

    Image8() = default;
    Image8(int w, int h);  // black
    std::uint8_t* pixel(int x, int y) {
        return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    }
    const std::uint8_t* pixel(int x, int y) const {
        return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    }
    bool operator==(const Image8&) const = default;
};

// Half-open pixel rectangle [x0, x1) x [y0, y1) in the coordinates above:
// y0 is its bottom row. (A FrameRegion, counted from the top, names its
// bounds left, top, right, bottom instead.)
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool operator==(const PixelRect&) const = default;
};

// Row `row` counted from the other edge of an image `height` rows high:
// bottom-up (Image8, PixelRect) to top-down (files stored top row first,
// screens, FrameRegion) and back. The one place the two conventions meet.
constexpr int flipped_row(int row, int height) {
    return height - 1 - row;
}

// The smallest rectangle holding `a` (when there is one) and `b`: how the
// pixels changed since the last look accumulate.
inline PixelRect holding_both(const std::optional<PixelRect>& a, const PixelRect& b) {
    if (!a) return b;
    return {std::min(a->x0, b.x0), std::min(a->y0, b.y0), std::max(a->x1, b.x1),
            std::max(a->y1, b.y1)};
}

// The value docs/language.md §8.6 writes for a channel: floor(clamp(c, 0, 1) * 255 + 0.5).
// Inside (0, 1) the sum is positive, where truncation is floor: the library's
// floor is a call on the x86-64 baseline, and this runs three times a pixel.
inline std::uint8_t quantize_channel(double c) {
    // NaN compares false everywhere; it must still never reach a pixel as garbage.
    if (!(c > 0.0)) return 0;
    if (c >= 1.0) return 255;
    return static_cast<std::uint8_t>(static_cast<int>(c * 255.0 + 0.5));
}

}  // namespace jt
