#include "app/panels/property_fields.hpp"

#include <algorithm>
#include <cmath>

namespace jt::view {

FieldBounds field_bounds(const ValueRange& range) {
    constexpr double open_step = 1e-4;  // relative to the bound's size
    FieldBounds b{range.low, range.high};
    if (range.low_open) b.min += open_step * std::max(1.0, std::abs(range.low));
    if (range.high_open) b.max -= open_step * std::max(1.0, std::abs(range.high));
    return b;
}

float field_speed(const ValueRange& range, std::string_view unit, double size) {
    // The language's limit on every number is no scale for a drag.
    if (range.low > -kMaxMagnitude && range.high < kMaxMagnitude)
        return static_cast<float>((range.high - range.low) / 200.0);
    if (unit == "degrees") return 0.5f;
    return static_cast<float>(std::max(0.01, 0.01 * std::abs(size)));
}

}  // namespace jt::view
