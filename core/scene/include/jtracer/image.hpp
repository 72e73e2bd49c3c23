#pragma once
// Images as plain pixel arrays.
//
// Pixel (x, y) follows docs/language.md §7.3: x from the left, y from the
// bottom. Row 0 is the bottom row, as in a BMP and an OpenGL texture.

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

// Half-open pixel rectangle [x0, x1) x [y0, y1) in the coordinates above.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool operator==(const PixelRect&) const = default;
};

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
