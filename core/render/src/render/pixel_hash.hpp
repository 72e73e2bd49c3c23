#pragma once
// The per-pixel angle that turns a fixed sampling pattern (a light's disk, the
// lens) differently in every pixel, so that the pattern's regularity shows as
// fine noise rather than as bands (docs/language.md §14.0). It depends only on
// the pixel's place in the whole image and the sample's index, never on the
// tile, region, thread or rank that renders it.

#include <cstdint>
#include <numbers>

namespace jt {

// The golden angle, 2 pi (1 - 1/phi) radians: successive points of a spiral
// turned by it fill a disk evenly (Vogel's sunflower), for every prefix.
inline constexpr double kGoldenAngle = 2.399963229728653;

// Which pixel sample a ray descends from: (i, j) in the whole image, j from the
// bottom; k the pixel sample's index. Reflected, refracted and shadow rays
// carry their primary ray's.
struct PixelSample {
    std::uint32_t i = 0;
    std::uint32_t j = 0;
    std::uint32_t k = 0;
    // False in the preview passes, which may show hard shadows.
    bool soft_shadows = true;
};

// Unsigned 32-bit arithmetic, wrapping: a spatial hash of (i, j, s) finished
// with a multiply-xorshift mix so that neighbouring pixels differ in every bit.
constexpr std::uint32_t pixel_hash(std::uint32_t i, std::uint32_t j, std::uint32_t s) {
    std::uint32_t h = (i * 73856093u) ^ (j * 19349663u) ^ (s * 83492791u);
    h = h ^ (h >> 16);
    h = h * 0x45d9f3bu;
    return h ^ (h >> 16);
}

// 2 pi h / 2^32, in radians: [0, 2 pi).
inline double pixel_angle(std::uint32_t i, std::uint32_t j, std::uint32_t s) {
    return 2.0 * std::numbers::pi * static_cast<double>(pixel_hash(i, j, s)) / 4294967296.0;
}

}  // namespace jt
