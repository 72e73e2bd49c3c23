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

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace jt {

struct Geometry;

// The part of a cube face that a table's cells cover: face coordinates u, v
// (along axes k+1 and k+2 of face axis k) in [u0, u1] x [v0, v1], scale cells
// a unit. Where the shapes seen from the point lie within a small part of a
// face, the face's cells span only that part, so that each is finer and lists
// fewer; directions outside it meet no shape. A face without shapes covers
// nothing (u0 > u1).
struct FaceWindow {
    double u0 = 1.0, u1 = -1.0, v0 = 1.0, v1 = -1.0;
    double u_scale = 0.0, v_scale = 0.0;  // cells a unit of u and of v
};

struct DirectionTable {
    int resolution = 0;  // cells along a face window's edge; 0: no table
    std::array<FaceWindow, 6> windows;
    std::vector<std::uint32_t> cell_start;  // 6 * resolution^2 + 1 offsets into `shapes`
    std::vector<std::uint32_t> shapes;      // each cell's nearest first
    std::vector<ListedDistance> nearest;    // parallel to `shapes`: see ListedShapes
};

// Cells along a cube face's edge for a table of `shapes` shapes.
int table_resolution(std::size_t shapes);

// The table around `point`, or none (resolution 0) when the geometry has too
// many shapes for a table to pay for its building.
DirectionTable build_direction_table(const Geometry& geometry, const Vec3& point, int resolution);

// The cell index along a window's edge of x, the coordinate from the
// window's start in cells.
inline int cell_coordinate(double x, int resolution) {
    if (!(x > 0.0)) return 0;
    if (x >= resolution) return resolution - 1;
    return static_cast<int>(x);
}

// The shapes that a ray leaving the point in `direction` (any length) may
// meet: all of them are in the list. Nothing when there is no table or the
// direction is zero or not finite. Inline: every hard shadow ray asks, and
// the call and the optional's trip through memory showed in profiles.
inline std::optional<ListedShapes> shapes_toward(const DirectionTable& table,
                                                 const Vec3& direction) {
    const int r = table.resolution;
    if (r == 0) return std::nullopt;
    const Vec3 a(std::abs(direction.x), std::abs(direction.y), std::abs(direction.z));
    int k = 0;
    if (a.y > a[k]) k = 1;
    if (a.z > a[k]) k = 2;
    const double m = a[k];
    if (!(m > 0.0) || !std::isfinite(a.x + a.y + a.z)) return std::nullopt;
    // Face 2k (+axis k) or 2k+1 (-axis k); u and v run along axes k+1 and k+2.
    const int j = (k + 1) % 3, l = (k + 2) % 3;
    const int face = 2 * k + (direction[k] < 0.0 ? 1 : 0);
    const FaceWindow& w = table.windows[face];
    const double u = direction[j] / m, v = direction[l] / m;
    // No shape lies outside the window.
    if (!(u >= w.u0 && u <= w.u1 && v >= w.v0 && v <= w.v1)) return ListedShapes{};
    const std::size_t cell =
        (static_cast<std::size_t>(face) * r + cell_coordinate((v - w.v0) * w.v_scale, r)) * r +
        cell_coordinate((u - w.u0) * w.u_scale, r);
    const std::size_t first = table.cell_start[cell];
    const std::size_t count = table.cell_start[cell + 1] - first;
    return ListedShapes{std::span(table.shapes).subspan(first, count),
                        std::span(table.nearest).subspan(first, count)};
}

// One table a light, parallel to `lights`; none when no table pays.
std::vector<DirectionTable> build_light_tables(const Geometry& geometry,
                                               const std::vector<PointLight>& lights);

}  // namespace jt
