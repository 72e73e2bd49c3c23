#pragma once
// Comparing two images, for reference-image tests and the tools around them.

#include "jtracer/image.hpp"

#include <cstddef>

namespace jt {

struct ImageDiff {
    bool same_size = false;
    int max_channel_difference = 0;  // 0..255 over every channel of every pixel
    std::size_t pixels_over = 0;     // pixels with some channel differing by > threshold
    double percent_over = 0.0;       // of all pixels
    // Per pixel: the channel differences times 8 where a pixel is over the
    // threshold, else a dim grey copy of `expected`, so the eye finds the spots.
    Image8 image;
};

// `threshold`: largest channel difference still counted as equal.
ImageDiff diff_images(const Image8& expected, const Image8& actual, int threshold = 0);

}  // namespace jt
