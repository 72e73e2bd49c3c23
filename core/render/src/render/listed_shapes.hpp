#pragma once
// A short list of the shapes a ray may meet, from a table built around the
// ray's origin or end (view_table.hpp, direction_table.hpp): testing those,
// exactly as the BVH callbacks would, gives the same answer bit for bit.

#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace jt {

// A listed shape is an index into Geometry::spheres, or into Geometry::shapes
// with `shape_flag` set.
inline constexpr std::uint32_t shape_flag = 0x80000000u;

// One shape of a list and its distance bound side by side, 8 bytes: a walk
// reads both, and one cache line then holds eight of them. No point of the
// shape is nearer the table's point than `nearest`, a float rounded down
// from the double bound: a walk may test a shape or two more than the double
// would let it, never fewer, so every answer stays the exact one.
struct Listed {
    std::uint32_t shape;
    float nearest;
};

// `nearest` never decreases along the list: a walk stops at the first shape
// that lies beyond the hit it has (or beyond the light).
struct ListedShapes {
    std::span<const Listed> entries;
    // The list holds a sphere that every ray it serves meets: a walk of even
    // a long list ends at that sphere's hit or soon after.
    bool covered = false;
    std::size_t size() const { return entries.size(); }
    const Listed& operator[](std::size_t k) const { return entries[k]; }
};

// A float not above the distance `d` (the largest such, for d in float's
// range): a lower bound stays one. Zero for a NaN, which bounds nothing.
inline float float_below(double d) {
    constexpr float largest = std::numeric_limits<float>::max();
    if (!(d > 0.0)) return 0.0f;
    if (!(d < static_cast<double>(largest))) return largest;
    float f = static_cast<float>(d);
    if (static_cast<double>(f) > d) f = std::nextafter(f, 0.0f);
    return f;
}

// A shape's bounding sphere as a table around `point` lists it: the radius
// padded, and the distances shrunk, far beyond the rounding of the double
// computations that decide a hit, so that the lists stay conservative.
struct PaddedBound {
    double radius;    // padded
    double distance;  // from `point` to the centre
    double nearest;   // no point of the shape is nearer `point`
};

inline PaddedBound padded_bound(const Vec3& center, double radius, const Vec3& point) {
    auto max_abs = [](const Vec3& v) {
        return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    };
    PaddedBound b;
    b.radius = radius * (1.0 + 1e-6) + 1e-7 * (max_abs(center) + max_abs(point) + radius);
    b.distance = glm::length(center - point);
    b.nearest = b.distance > b.radius ? (b.distance - b.radius) * (1.0 - 1e-9) : 0.0;
    return b;
}

}  // namespace jt
