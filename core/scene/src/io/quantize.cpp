#include "jtracer/image.hpp"

#include <cmath>

namespace jt {

std::uint8_t quantize_channel(double c) {
    // NaN compares false everywhere; it must still never reach a pixel as garbage.
    if (!(c > 0.0)) return 0;
    if (c >= 1.0) return 255;
    return static_cast<std::uint8_t>(std::floor(c * 255.0 + 0.5));
}

}  // namespace jt
