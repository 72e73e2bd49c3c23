#include "render/direction_table.hpp"

#include "render/prepared_scene.hpp"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace jt {

namespace {

// Past this many shapes (in a table, or in the tables of all lights) the
// tables cost more to build than they save, and the BVH's culling beats a
// cell's long list anyway.
constexpr std::size_t max_table_work = std::size_t{1} << 16;

// Past this many listings (shapes around the point, listed in every cell)
// the cells are too full to beat the BVH, and the table would take hundreds
// of MB: no table then.
constexpr std::size_t max_listed = std::size_t{1} << 22;

// Bounding spheres wider than this many radians, seen from the light, go in
// every cell rather than being rasterised.
constexpr double max_cone_angle = 1.2;

// Slack on every angle and cell coordinate: far beyond the rounding of the
// double computations that decide a direction's cell or a hit, so that a ray
// on a cell's edge still finds every shape that may block it.
constexpr double angle_slack = 1e-7;
constexpr double coordinate_slack = 1e-6;

// On a face of the cube map, the face's axis is the largest component of a
// unit direction, so it is at least 1/sqrt(3).
constexpr double min_face_component = 0.57735026918962576 - 1e-6;

struct BoundingSphere {
    Vec3 center;
    double radius;
};

// prepare_scene gives every shape a bounding sphere around its padded box.
BoundingSphere bounding_sphere(const TransformedShape& s) {
    return {s.bounding_center, std::sqrt(s.bounding_radius_sq)};
}

}  // namespace

int table_resolution(std::size_t shapes) {
    // Some 24 cells a shape (six faces of (2 sqrt N)^2), so that most cells list
    // none or one. The cap was measured on the benchmark scenes: finer tables
    // cost more to build than they save (128 cells an edge: 15% slower on
    // lattice and nested_shells, 5% faster on spheres_5761).
    const double per_edge = std::ceil(2.0 * std::sqrt(static_cast<double>(shapes)));
    return static_cast<int>(std::clamp(per_edge, 8.0, 64.0));
}

namespace {

// Face 2k (+axis k) or 2k+1 (-axis k); u and v run along axes k+1 and k+2.
struct FaceAxes {
    int k, j, l;
};
FaceAxes face_axes(int k) {
    return {k, (k + 1) % 3, (k + 2) % 3};
}

// Each cell's cone: its centre direction (face-local, unit) and the cosine and
// sine of the angle to its farthest corner. The same for all six faces.
struct CellCone {
    double u, v, w;  // unit centre direction, w along the face's axis
    double cos_radius, sin_radius;
};

std::vector<CellCone> cell_cones(int resolution) {
    std::vector<CellCone> cones(static_cast<std::size_t>(resolution) * resolution);
    const double step = 2.0 / resolution;
    for (int iv = 0; iv < resolution; ++iv)
        for (int iu = 0; iu < resolution; ++iu) {
            const double u0 = -1.0 + iu * step, v0 = -1.0 + iv * step;
            const Vec3 centre = glm::normalize(Vec3(u0 + 0.5 * step, v0 + 0.5 * step, 1.0));
            double radius = 0.0;
            for (double du : {0.0, step})
                for (double dv : {0.0, step}) {
                    Vec3 corner = glm::normalize(Vec3(u0 + du, v0 + dv, 1.0));
                    radius = std::max(radius,
                                      std::acos(std::clamp(glm::dot(centre, corner), -1.0, 1.0)));
                }
            radius += angle_slack;
            cones[static_cast<std::size_t>(iv) * resolution + iu] = {
                centre.x, centre.y, centre.z, std::cos(radius), std::sin(radius)};
        }
    return cones;
}

// Calls add(cell) for every cell whose cone meets the cone of directions
// within `angle` of the unit `axis`.
template <typename Add>
void rasterise_cone(const Vec3& axis, double angle, int resolution,
                    const std::vector<CellCone>& cones, Add&& add) {
    const double cos_angle = std::cos(angle), sin_angle = std::sin(angle);
    // The range of each component of a direction in the cone.
    std::array<double, 3> lo{}, hi{};
    for (int i = 0; i < 3; ++i) {
        const double theta = std::acos(std::clamp(axis[i], -1.0, 1.0));
        lo[i] = std::cos(std::min(std::numbers::pi, theta + angle)) - angle_slack;
        hi[i] = std::cos(std::max(0.0, theta - angle)) + angle_slack;
    }
    for (int face = 0; face < 6; ++face) {
        const auto [k, j, l] = face_axes(face / 2);
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        const double w_lo = std::max(sign > 0 ? lo[k] : -hi[k], min_face_component);
        const double w_hi = sign > 0 ? hi[k] : -lo[k];
        if (w_hi < w_lo) continue;
        // u = d_j / w over the box of components: the extremes are at corners.
        auto range = [&](int axis_index, int& first, int& last) {
            const double a = lo[axis_index], b = hi[axis_index];
            const double low = std::min(a / w_lo, a / w_hi) - coordinate_slack;
            const double high = std::max(b / w_lo, b / w_hi) + coordinate_slack;
            first = cell_coordinate(low, resolution);
            last = cell_coordinate(high, resolution);
        };
        int u0, u1, v0, v1;
        range(j, u0, u1);
        range(l, v0, v1);
        const std::size_t face_base = static_cast<std::size_t>(face) * resolution * resolution;
        for (int iv = v0; iv <= v1; ++iv)
            for (int iu = u0; iu <= u1; ++iu) {
                const std::size_t local = static_cast<std::size_t>(iv) * resolution + iu;
                const CellCone& c = cones[local];
                // Cones meet when the angle between their axes is at most the
                // sum of their angles: compare cosines.
                const double cos_between = c.u * axis[j] + c.v * axis[l] + c.w * sign * axis[k];
                const double cos_sum = cos_angle * c.cos_radius - sin_angle * c.sin_radius;
                if (cos_between >= cos_sum - angle_slack) add(face_base + local);
            }
    }
}

}  // namespace

DirectionTable build_direction_table(const Geometry& geometry, const Vec3& position,
                                     int resolution) {
    DirectionTable table;
    const std::size_t shapes = geometry.spheres.size() + geometry.shapes.size();
    if (shapes == 0 || shapes > max_table_work || resolution < 1) return table;
    const int r = resolution;
    const std::size_t cells = 6 * static_cast<std::size_t>(r) * r;
    const std::vector<CellCone> cones = cell_cones(r);

    // (cell, candidate) pairs, then a counting sort by cell, then each cell
    // nearest first.
    struct Listing {
        std::uint32_t cell, candidate;
    };
    std::vector<Listing> pairs;
    std::vector<double> nearest_of(shapes);  // by sphere index, then shape index
    auto add_shape = [&](const BoundingSphere& b, std::uint32_t candidate, std::size_t slot) {
        const Vec3 offset = b.center - position;
        const PaddedBound padded = padded_bound(b.center, b.radius, position);
        const double distance = padded.distance, radius = padded.radius;
        nearest_of[slot] = padded.nearest;
        const bool everywhere = !(distance > radius) || !std::isfinite(distance) ||
                                radius / distance > std::sin(max_cone_angle);
        if (everywhere) {
            for (std::size_t cell = 0; cell < cells; ++cell)
                pairs.push_back({static_cast<std::uint32_t>(cell), candidate});
            return;
        }
        const double angle = std::asin(radius / distance) + angle_slack;
        rasterise_cone(offset / distance, angle, r, cones, [&](std::size_t cell) {
            pairs.push_back({static_cast<std::uint32_t>(cell), candidate});
        });
    };
    for (std::uint32_t i = 0; i < geometry.spheres.size(); ++i) {
        add_shape({geometry.spheres[i].center, geometry.spheres[i].radius}, i, i);
        if (pairs.size() > max_listed) return {};
    }
    for (std::uint32_t i = 0; i < geometry.shapes.size(); ++i) {
        add_shape(bounding_sphere(geometry.shapes[i]), i | shape_flag, geometry.spheres.size() + i);
        if (pairs.size() > max_listed) return {};
    }
    auto nearest = [&](std::uint32_t candidate) {
        return candidate & shape_flag
                   ? nearest_of[geometry.spheres.size() + (candidate & ~shape_flag)]
                   : nearest_of[candidate];
    };

    table.resolution = r;
    table.cell_start.assign(cells + 1, 0);
    for (const Listing& p : pairs) ++table.cell_start[p.cell + 1];
    for (std::size_t c = 0; c < cells; ++c) table.cell_start[c + 1] += table.cell_start[c];
    std::vector<Listing> sorted(pairs.size());
    std::vector<std::uint32_t> fill(table.cell_start.begin(), table.cell_start.end() - 1);
    for (const Listing& p : pairs) sorted[fill[p.cell]++] = p;
    for (std::size_t c = 0; c < cells; ++c)
        std::stable_sort(sorted.begin() + table.cell_start[c],
                         sorted.begin() + table.cell_start[c + 1],
                         [&](const Listing& a, const Listing& b) {
                             return nearest(a.candidate) < nearest(b.candidate);
                         });
    table.listed.resize(sorted.size());
    for (std::size_t i = 0; i < sorted.size(); ++i)
        table.listed[i] = {sorted[i].candidate, float_below(nearest(sorted[i].candidate))};
    return table;
}

std::vector<DirectionTable> build_light_tables(const Geometry& geometry,
                                               const std::vector<PointLight>& lights) {
    const std::size_t shapes = geometry.spheres.size() + geometry.shapes.size();
    if (lights.empty() || shapes == 0 || shapes * lights.size() > max_table_work) return {};
    std::vector<DirectionTable> tables(lights.size());
    tbb::parallel_for(std::size_t{0}, lights.size(), [&](std::size_t i) {
        tables[i] = build_direction_table(geometry, lights[i].position, table_resolution(shapes));
    });
    return tables;
}

}  // namespace jt
