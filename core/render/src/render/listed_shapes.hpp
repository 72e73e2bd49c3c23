#pragma once
// A short list of the shapes a ray may meet, from a table built around the
// ray's origin or end (view_table.hpp, direction_table.hpp): testing those,
// exactly as the BVH callbacks would, gives the same answer bit for bit.

#include <cstddef>
#include <cstdint>
#include <span>

namespace jt {

// A listed shape is an index into Geometry::spheres, or into Geometry::shapes
// with `shape_flag` set.
inline constexpr std::uint32_t shape_flag = 0x80000000u;

// No point of shapes[i] is nearer the table's point than nearest[i], and
// nearest never decreases along the list: a walk stops at the first shape that
// lies beyond the hit it has (or beyond the light).
struct ListedShapes {
    std::span<const std::uint32_t> shapes;
    std::span<const double> nearest;
    // The list holds a sphere that every ray it serves meets: a walk of even
    // a long list ends at that sphere's hit or soon after.
    bool covered = false;
    std::size_t size() const { return shapes.size(); }
};

}  // namespace jt
