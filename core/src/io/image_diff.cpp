#include "jtracer/image_diff.hpp"

#include <algorithm>
#include <cstdlib>

namespace jt {

ImageDiff diff_images(const Image8& expected, const Image8& actual, int threshold) {
    ImageDiff d;
    d.same_size = expected.width == actual.width && expected.height == actual.height &&
                  expected.rgb.size() == actual.rgb.size();
    if (!d.same_size) {
        d.max_channel_difference = 255;
        d.pixels_over = static_cast<std::size_t>(std::max(expected.width, 0)) *
                        static_cast<std::size_t>(std::max(expected.height, 0));
        d.percent_over = 100.0;
        return d;
    }
    d.image = Image8(expected.width, expected.height);
    const std::size_t pixels = expected.rgb.size() / 3;
    for (std::size_t i = 0; i < pixels; ++i) {
        int worst = 0;
        int diff[3];
        for (int c = 0; c < 3; ++c) {
            diff[c] = std::abs(int{expected.rgb[3 * i + c]} - int{actual.rgb[3 * i + c]});
            worst = std::max(worst, diff[c]);
        }
        d.max_channel_difference = std::max(d.max_channel_difference, worst);
        bool over = worst > threshold;
        if (over) ++d.pixels_over;
        for (int c = 0; c < 3; ++c)
            d.image.rgb[3 * i + c] =
                over ? static_cast<std::uint8_t>(std::min(255, 64 + diff[c] * 8))
                     : static_cast<std::uint8_t>(expected.rgb[3 * i + c] / 4);
    }
    d.percent_over = pixels == 0 ? 0.0 : 100.0 * static_cast<double>(d.pixels_over) / pixels;
    return d;
}

}  // namespace jt
