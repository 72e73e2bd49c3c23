#pragma once
// Which shapes a camera's rays may meet first, block by block of pixels.
//
// The image is cut into square blocks of pixels, and each block lists the
// shapes whose padded bounding sphere may lie across the ray through any point
// of it, nearest first: a primary ray tests its block's list exactly as the
// BVH callbacks would, and stops at the first shape that lies wholly beyond
// its best hit, so the answer is the same bit for bit. A shape's blocks come
// from the exact extent of its bounding sphere on the image plane, less the
// blocks whose cone of rays stays apart from the sphere's. A sphere
// that every ray of a block meets caps the block where all its rays have met
// the sphere (covered_hit_bound): a shape beyond could never be a first hit
// there, and is left out of the list (the nested spheres of `nested_shells`
// then list a handful a block instead of dozens).
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

// Block rows a band: the table is built a band at a time, the bands in
// parallel, and each band keeps the lists it made. Copying them into one array
// would touch as many fresh pages again, and on nested_shells the faults of
// those pages cost more than the copy.
inline constexpr int view_band_rows = 8;

struct ViewBand {
    std::vector<std::uint32_t> shapes;    // each block's nearest first
    std::vector<ListedDistance> nearest;  // parallel to `shapes`: see ListedShapes
};

struct ViewTable {
    bool built = false;         // false: no table
    int columns = 0, rows = 0;  // blocks across and down the image
    // Each band's blocks' offsets into its lists, and one past its last: the
    // list of block b (row by row) of band k starts at list_start[b + k].
    std::vector<std::uint32_t> list_start;
    std::vector<ViewBand> bands;
    // Per block: a sphere that every ray of the block meets is listed.
    std::vector<std::uint8_t> covered;
};

// How far from the camera every ray of a block that a sphere covers first
// meets the sphere: the cap on the block's list, since no shape beyond it can
// be a first hit there. The sphere (radius `radius`, its centre `distance`
// away) covers the block when every ray of it meets the inner sphere
// (`inner_radius`); `cos_farthest` is the cosine of the largest angle between
// a corner of the block and the centre's direction.
double covered_hit_bound(double distance, double inner_radius, double radius, double cos_farthest);

// The table of `camera`'s image, or none (not built) when the geometry has no
// bounded shapes, too many for a table to pay for its building, or the camera
// forms no frame.
ViewTable build_view_table(const Geometry& geometry, const CameraFrame& camera);

// The shapes listed for the block in `column` and `row` of a table that was
// built.
inline ListedShapes block_shapes(const ViewTable& table, int column, int row) {
    JT_DCHECK(column >= 0 && column < table.columns && row >= 0 && row < table.rows,
              "the block lies in the table");
    const std::size_t block = static_cast<std::size_t>(row) * table.columns + column;
    const int band = row / view_band_rows;
    const std::size_t at = block + band;
    const std::uint32_t first = table.list_start[at];
    const std::uint32_t count = table.list_start[at + 1] - first;
    const ViewBand& lists = table.bands[static_cast<std::size_t>(band)];
    return ListedShapes{std::span(lists.shapes).subspan(first, count),
                        std::span(lists.nearest).subspan(first, count), table.covered[block] != 0};
}

// The shapes that the ray through image point (x, y) (pixels from the bottom
// left corner, as camera_direction takes them) may meet first. Call it only
// for points inside the image, and only of a table that was built.
inline ListedShapes shapes_seen(const ViewTable& table, double x, double y) {
    JT_DCHECK(table.columns > 0 && table.rows > 0, "only a table that was built lists shapes");
    JT_DCHECK(x >= 0.0 && y >= 0.0, "the point lies inside the image");
    const int column = std::min(static_cast<int>(x) / view_block, table.columns - 1);
    const int row = std::min(static_cast<int>(y) / view_block, table.rows - 1);
    return block_shapes(table, column, row);
}

}  // namespace jt
