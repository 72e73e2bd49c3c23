#include "jtracer/image_diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace jt {

void heat_colour(int difference, std::uint8_t rgb[3]) {
    // The square root spreads the small differences, the usual ones, over most
    // of the ramp; even a difference of 1 is a clear red.
    const double t = std::sqrt(std::clamp(difference, 0, 255) / 255.0);
    rgb[0] = 255;
    rgb[1] = static_cast<std::uint8_t>(std::lround(255.0 * std::min(1.0, 2.0 * t)));
    rgb[2] = static_cast<std::uint8_t>(std::lround(255.0 * std::max(0.0, 2.0 * t - 1.0)));
}

ImageDiff diff_images(const Image8& expected, const Image8& actual, int threshold) {
    ImageDiff d;
    d.same_size = expected.width == actual.width && expected.height == actual.height &&
                  expected.rgb.size() == actual.rgb.size();
    if (!d.same_size) {
        d.max_channel_difference = 255;
        d.pixels_over = static_cast<std::size_t>(std::max(expected.width, 0)) *
                        static_cast<std::size_t>(std::max(expected.height, 0));
        d.percent_over = 100.0;
        d.mean_absolute_error = 255.0;
        return d;
    }
    d.image = Image8(expected.width, expected.height);
    d.pixels = expected.rgb.size() / 3;
    std::uint64_t absolute_sum = 0, squared_sum = 0;
    for (std::size_t i = 0; i < d.pixels; ++i) {
        const std::uint8_t* e = &expected.rgb[3 * i];
        const std::uint8_t* a = &actual.rgb[3 * i];
        std::uint8_t* out = &d.image.rgb[3 * i];
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int diff = std::abs(int{e[c]} - int{a[c]});
            worst = std::max(worst, diff);
            absolute_sum += static_cast<std::uint64_t>(diff);
            squared_sum += static_cast<std::uint64_t>(diff * diff);
        }
        d.max_channel_difference = std::max(d.max_channel_difference, worst);
        if (worst > threshold) {
            ++d.pixels_over;
            heat_colour(worst, out);
        } else {
            const int luma = (77 * e[0] + 150 * e[1] + 29 * e[2]) >> 8;
            std::fill(out, out + 3, static_cast<std::uint8_t>(luma / 3));
        }
    }
    const double channels = 3.0 * static_cast<double>(d.pixels);
    d.percent_over = d.pixels == 0 ? 0.0 : 100.0 * static_cast<double>(d.pixels_over) / d.pixels;
    d.mean_absolute_error = d.pixels == 0 ? 0.0 : static_cast<double>(absolute_sum) / channels;
    d.psnr = squared_sum == 0
                 ? std::numeric_limits<double>::infinity()
                 : 10.0 * std::log10(255.0 * 255.0 * channels / static_cast<double>(squared_sum));
    return d;
}

}  // namespace jt
