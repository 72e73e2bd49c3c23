#include "model/ui_rounding.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace jt::view {

double ui_rounded(double value) {
    if (!std::isfinite(value)) return value;
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", kUiDigits, value);
    return std::strtod(text, nullptr);
}

Vec3 ui_rounded(const Vec3& value) {
    return {ui_rounded(value.x), ui_rounded(value.y), ui_rounded(value.z)};
}

}  // namespace jt::view
