#pragma once
// Which shapes a camera's rays may meet first, block by block of pixels.
//
// The image is cut into square blocks of pixels, and each block lists the
// shapes whose padded bounding sphere may lie across the ray through any point
// of it, nearest first: a primary ray tests its block's list exactly as the
// BVH callbacks would, and stops at the first shape that lies wholly beyond
// its best hit, so the answer is the same bit for bit. A shape's blocks come
// from the exact extent of its bounding sphere on the image plane. A sphere
// that every ray of a block meets caps the block: a shape beyond its far side
// could never be a first hit there, and is left out of the list (the nested
// spheres of `nested_shells` then list a handful a block instead of dozens).
//
// Blocks of a few pixels give lists of a few shapes even where thousands crowd
// the view, where a cell of a table around the camera (direction_table.hpp)
// spans dozens of pixels and sent its rays to the BVH.

#include "jtracer/check.hpp"
#include "render/camera_rays.hpp"
#include "render/listed_shapes.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace jt {

struct Geometry;

// Pixels along a block's edge: lists of a few shapes where thousands crowd the
// view, in a table of a few hundred thousand blocks at most.
inline constexpr int view_block = 4;

struct ViewTable {
    bool built = false;                      // false: no table
    int columns = 0, rows = 0;               // blocks across and down the image
    std::vector<std::uint32_t> block_start;  // columns * rows + 1 offsets into `shapes`
    std::vector<std::uint32_t> shapes;       // each block's nearest first
    std::vector<ListedDistance> nearest;     // parallel to `shapes`: see ListedShapes
    // Per block: a sphere that every ray of the block meets is listed.
    std::vector<std::uint8_t> covered;
};

// The table of `camera`'s image, or none (not built) when the geometry has no
// bounded shapes, too many for a table to pay for its building, or the camera
// forms no frame.
ViewTable build_view_table(const Geometry& geometry, const CameraFrame& camera);

// The shapes that the ray through image point (x, y) (pixels from the bottom
// left corner, as camera_direction takes them) may meet first. Call it only
// for points inside the image, and only of a table that was built.
inline ListedShapes shapes_seen(const ViewTable& table, double x, double y) {
    JT_DCHECK(table.columns > 0 && table.rows > 0, "only a table that was built lists shapes");
    JT_DCHECK(x >= 0.0 && y >= 0.0, "the point lies inside the image");
    const int column = std::min(static_cast<int>(x) / view_block, table.columns - 1);
    const int row = std::min(static_cast<int>(y) / view_block, table.rows - 1);
    const std::size_t index = static_cast<std::size_t>(row) * table.columns + column;
    const std::uint32_t first = table.block_start[index];
    const std::uint32_t count = table.block_start[index + 1] - first;
    return ListedShapes{std::span(table.shapes).subspan(first, count),
                        std::span(table.nearest).subspan(first, count), table.covered[index] != 0};
}

}  // namespace jt
