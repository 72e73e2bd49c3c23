#pragma once
// Which shapes lie in each direction around a light: for shadow rays, which
// all reach that point, a table that replaces the BVH walk by a short list
// (the "light buffer" of Haines and Greenberg, 1986).
//
// The directions around the point are cut into the cells of a cube map, and
// each cell lists the shapes whose padded bounding sphere overlaps its cone. A
// ray through the point can only meet shapes listed in its direction's cell,
// so testing those, exactly as the BVH callbacks would, gives the same answer
// bit for bit. On the benchmark scenes shadow rays were 40-65% of the render
// time, mostly in Embree's per-ray set-up and traversal.

#include "jtracer/scene.hpp"
#include "render/listed_shapes.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace jt {

struct Geometry;

struct DirectionTable {
    int resolution = 0;                     // cells along a cube face's edge; 0: no table
    std::vector<std::uint32_t> cell_start;  // 6 * resolution^2 + 1 offsets into `shapes`
    std::vector<std::uint32_t> shapes;      // each cell's nearest first
    std::vector<double> nearest;            // parallel to `shapes`: see ListedShapes
};

// Cells along a cube face's edge for a table of `shapes` shapes.
int table_resolution(std::size_t shapes);

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
