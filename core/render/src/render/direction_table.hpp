#pragma once
// Which shapes lie in each direction around a point: for rays that all leave
// (or reach) that point, a table that replaces the BVH walk by a short list.
//
// The directions around the point are cut into the cells of a cube map, and
// each cell lists the shapes whose padded bounding sphere overlaps its cone. A
// ray through the point can only meet shapes listed in its direction's cell,
// so testing those, exactly as the BVH callbacks would, gives the same answer
// bit for bit. Around each light, the table answers shadow rays (the "light
// buffer" of Haines and Greenberg, 1986); around the camera, primary rays (a
// "vista buffer"). On the benchmark scenes shadow rays were 40-65% of the
// render time, mostly in Embree's per-ray set-up and traversal.

#include "jtracer/scene.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace jt {

struct Geometry;

// A listed shape is an index into Geometry::spheres, or into Geometry::shapes
// with `shape_flag` set.
inline constexpr std::uint32_t shape_flag = 0x80000000u;

struct DirectionTable {
    int resolution = 0;                     // cells along a cube face's edge; 0: no table
    std::vector<std::uint32_t> cell_start;  // 6 * resolution^2 + 1 offsets into `shapes`
    std::vector<std::uint32_t> shapes;      // each cell's nearest first
    std::vector<double> nearest;            // parallel to `shapes`: see ListedShapes
    // Per cell: the list holds, among its first max_covered_position shapes, a
    // sphere whose cone holds the cell's: every ray of the cell meets it, so a
    // walk of even a long list ends soon after it.
    std::vector<std::uint8_t> covered;
};

inline constexpr std::size_t max_covered_position = 256;

// A cell's list. No point of shapes[i] is nearer the table's point than
// nearest[i], and nearest never decreases along the list: a walk stops at the
// first shape that lies beyond the hit it has (or beyond the light).
struct ListedShapes {
    std::span<const std::uint32_t> shapes;
    std::span<const double> nearest;
    bool covered = false;  // see DirectionTable::covered
    std::size_t size() const { return shapes.size(); }
};

// Cells along a cube face's edge for a table of `shapes` shapes, around a
// light or (`for_camera`) a camera.
int table_resolution(std::size_t shapes, bool for_camera);

// The table around `point`, or none (resolution 0) when the geometry has too
// many shapes for a table to pay for its building.
DirectionTable build_direction_table(const Geometry& geometry, const Vec3& point, int resolution);

// The shapes that a ray leaving the point in `direction` (any length) may
// meet: all of them are in the list. Nothing when there is no table or the
// direction is zero or not finite.
std::optional<ListedShapes> shapes_toward(const DirectionTable& table, const Vec3& direction);

// One table a light, parallel to `lights`; none when no table pays.
std::vector<DirectionTable> build_light_tables(const Geometry& geometry,
                                               const std::vector<PointLight>& lights);

}  // namespace jt
