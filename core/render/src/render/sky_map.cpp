#include "render/sky_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jt {

Uv sky_uv(const Vec3& d) {
    return {0.5 + std::atan2(d.x, -d.z) / (2.0 * std::numbers::pi),
            0.5 + std::asin(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi};
}

Colour sky_colour(const Texture& map, const Vec3& d) {
    return sample_bilinear_rows_clamped(map, sky_uv(d));
}

}  // namespace jt
