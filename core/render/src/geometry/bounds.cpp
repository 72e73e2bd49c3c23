#include "geometry/bounds.hpp"

#include "geometry/float_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jt {

namespace {

// A float ray differs from its double original by about 2^-24 of the origin's
// magnitude plus as much of the distance travelled; 1e-6 of the box's own
// magnitude covers rays that start and travel at the scale of the box.
constexpr double relative_margin = 1e-6;

}  // namespace

Box sphere_box(const Vec3& center, double radius) {
    return Box{center - Vec3(radius), center + Vec3(radius)};
}

Box transformed_sphere_box(const Vec3& center, double radius, const Affine& to_world) {
    Vec3 c = apply_point(to_world, center);
    Vec3 half;
    for (int row = 0; row < 3; ++row) {
        double sum = 0.0;
        for (int col = 0; col < 3; ++col)
            sum += to_world.linear[col][row] * to_world.linear[col][row];
        half[row] = radius * std::sqrt(sum);
    }
    return Box{c - half, c + half};
}

Box transformed_cylinder_box(double radius, double height, const Affine& to_world) {
    Box box{Vec3(std::numeric_limits<double>::infinity()),
            Vec3(-std::numeric_limits<double>::infinity())};
    for (int corner = 0; corner < 8; ++corner) {
        Vec3 p{corner & 1 ? radius : -radius, corner & 2 ? height : 0.0,
               corner & 4 ? radius : -radius};
        Vec3 w = apply_point(to_world, p);
        box.lower = glm::min(box.lower, w);
        box.upper = glm::max(box.upper, w);
    }
    return box;
}

RTCBounds padded_float_bounds(const Box& box, double slack) {
    Vec3 extent = box.upper - box.lower;
    double magnitude =
        std::max({std::abs(box.lower.x), std::abs(box.lower.y), std::abs(box.lower.z),
                  std::abs(box.upper.x), std::abs(box.upper.y), std::abs(box.upper.z)});
    double size = std::max({extent.x, extent.y, extent.z});
    double pad = relative_margin * (magnitude + size) + slack;
    RTCBounds b;
    b.lower_x = float_at_or_below(box.lower.x - pad);
    b.lower_y = float_at_or_below(box.lower.y - pad);
    b.lower_z = float_at_or_below(box.lower.z - pad);
    b.upper_x = float_at_or_above(box.upper.x + pad);
    b.upper_y = float_at_or_above(box.upper.y + pad);
    b.upper_z = float_at_or_above(box.upper.z + pad);
    b.align0 = b.align1 = 0.0f;
    return b;
}

}  // namespace jt
