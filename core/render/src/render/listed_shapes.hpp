#pragma once
// A short list of the shapes a ray may meet, from a table built around the
// ray's origin or end (view_table.hpp, direction_table.hpp): testing those,
// exactly as the BVH callbacks would, gives the same answer bit for bit.

#include "geometry/float_step.hpp"
#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

namespace jt {

// A listed shape is an index into Geometry::spheres, or into Geometry::shapes
// with `shape_flag` set.
inline constexpr std::uint32_t shape_flag = 0x80000000u;

// How near a listed shape may come to a list's point: a float at or below the
// double bound, so a walk may test a shape more than the double would have
// let it, never one fewer, and the answer stays the same. Half the bytes of a
// double: the tables of nested_shells list some two million shapes, and each
// fresh page they take costs its fault before the first pixel.
using ListedDistance = float;

inline ListedDistance listed_distance(double nearest) {
    return float_at_or_below(nearest);
}

// The sphere a previous walk met first: the primary rays of neighbouring
// pixels mostly meet the same sphere, and offering it before a walk gives the
// walk a near best hit from its start, so that most of the spheres it passes
// are answered by their early tests (where heavily overlapping spheres cover
// a block, a walk found some three nearer hits in turn before its last). Only
// a guess: any sphere, or none, gives the same answer.
struct HitHint {
    static constexpr std::uint32_t none = 0xFFFFFFFFu;
    std::uint32_t sphere = none;  // an index into Geometry::spheres
};

// No point of shapes[i] is nearer the table's point than nearest[i], and
// nearest never decreases along the list: a walk stops at the first shape that
// lies beyond the hit it has (or beyond the light).
struct ListedShapes {
    std::span<const std::uint32_t> shapes;
    std::span<const ListedDistance> nearest;
    // The list holds a sphere that every ray it serves meets: a walk of even
    // a long list ends at that sphere's hit or soon after.
    bool covered = false;
    // A closest-hit walk of a covered list long enough to go in batches
    // offers this hint's sphere first, and leaves it on the sphere met first
    // (closest_hit.cpp); other walks leave it alone.
    HitHint* hint = nullptr;
    std::size_t size() const { return shapes.size(); }
};

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
