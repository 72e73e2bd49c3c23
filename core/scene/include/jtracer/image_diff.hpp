#pragma once
// Comparing two images, for reference-image tests and the tools around them
// (jtracer-cli diff and --expect).

#include "jtracer/image.hpp"

#include <cstddef>

namespace jt {

struct ImageDiff {
    bool same_size = false;
    int max_channel_difference = 0;    // 0..255 over every channel of every pixel
    std::size_t pixels = 0;            // in each image, when they have the same size
    std::size_t pixels_over = 0;       // pixels with some channel differing by > threshold
    double percent_over = 0.0;         // of all pixels
    double mean_absolute_error = 0.0;  // mean |a - b| over every channel, 0..255
    // Peak signal-to-noise ratio in dB, 10 log10(255^2 / mean squared error):
    // +infinity for identical images.
    double psnr = 0.0;
    // A heat map for a person to read: pixels over the threshold from red (a
    // small difference) through yellow to white (255), every other pixel a dim
    // grey copy of `expected`, so that the spots stand out where they are.
    Image8 image;
};

// `threshold`: largest channel difference still counted as equal. Images of
// different sizes compare as entirely different (and get no heat map).
ImageDiff diff_images(const Image8& expected, const Image8& actual, int threshold = 0);

// The heat map colour of a pixel whose largest channel difference is
// `difference` (1..255): red, yellow at about 64, white at 255.
void heat_colour(int difference, std::uint8_t rgb[3]);

}  // namespace jt
