#include "app/panels/property_fields.hpp"

#include <algorithm>
#include <cmath>

namespace jt::view {

FieldBounds field_bounds(const ValueRange& range) {
    if (!std::isfinite(range.low) && !std::isfinite(range.high)) return {};
    constexpr double open_step = 1e-4;  // relative to the bound's size
    constexpr double far = 3.0e38;      // an infinite bound: as far as a float field reaches
    FieldBounds b{-far, far};
    if (std::isfinite(range.low))
        b.min = range.low + (range.low_open ? open_step * std::max(1.0, std::abs(range.low)) : 0.0);
    if (std::isfinite(range.high))
        b.max =
            range.high - (range.high_open ? open_step * std::max(1.0, std::abs(range.high)) : 0.0);
    return b;
}

float field_speed(const ValueRange& range, std::string_view unit, double size) {
    if (std::isfinite(range.low) && std::isfinite(range.high))
        return static_cast<float>((range.high - range.low) / 200.0);
    if (unit == "degrees") return 0.5f;
    return static_cast<float>(std::max(0.01, 0.01 * std::abs(size)));
}

}  // namespace jt::view
