#pragma once
// A JPEG's EXIF orientation (tag 274): how the camera held the picture. Every
// image viewer and browser shows a photo turned by it, so a phone photo taken
// upright is stored sideways with orientation 6 and shown upright; an image
// map reads it as it is shown (docs/language.md §13.4). Only this tag is read:
// the rest of EXIF says nothing about the texels.

#include <cstdint>
#include <span>
#include <vector>

namespace jt {

// The orientation of the first APP1 "Exif" segment before the picture's
// data, 1 (as stored) to 8; 1 when there is none, or it is damaged or out of
// range, as viewers then show the picture as stored.
int exif_orientation(std::span<const std::uint8_t> jpeg);

// Whether `orientation` turns the picture a quarter (5 to 8): width and
// height change places.
inline bool swaps_sides(int orientation) {
    return orientation >= 5 && orientation <= 8;
}

// 8-bit RGB texels of a `width` x `height` picture as stored, the bottom row
// first, turned as `orientation` says: the picture as shown, the bottom row
// first, its sides swapped when swaps_sides(orientation).
std::vector<std::uint8_t> turn_upright(const std::vector<std::uint8_t>& stored, int width,
                                       int height, int orientation);

}  // namespace jt
