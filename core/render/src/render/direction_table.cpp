#include "render/direction_table.hpp"

#include "render/prepared_scene.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

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

// The narrowest face window: the slack twice over.
constexpr double min_window = 4.0 * coordinate_slack;

// Shapes a task takes when a table's cones and cells are worked out in
// parallel: a few hundred trigonometric calls, well above a task's cost.
constexpr std::size_t shapes_a_task = 256;

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

// The cones of one face's cells, row by row, over its window.
std::vector<CellCone> cell_cones(int resolution, const FaceWindow& window) {
    std::vector<CellCone> cones(static_cast<std::size_t>(resolution) * resolution);
    const double u_step = 1.0 / window.u_scale, v_step = 1.0 / window.v_scale;
    tbb::parallel_for(0, resolution, [&](int iv) {
        for (int iu = 0; iu < resolution; ++iu) {
            const double u0 = window.u0 + iu * u_step, v0 = window.v0 + iv * v_step;
            const Vec3 centre = glm::normalize(Vec3(u0 + 0.5 * u_step, v0 + 0.5 * v_step, 1.0));
            // The farthest corner is the one of the smallest cosine: one arc
            // cosine, of that, gives the largest angle.
            double cos_farthest = 1.0;
            for (double du : {0.0, u_step})
                for (double dv : {0.0, v_step}) {
                    Vec3 corner = glm::normalize(Vec3(u0 + du, v0 + dv, 1.0));
                    cos_farthest = std::min(cos_farthest, glm::dot(centre, corner));
                }
            const double radius = std::acos(std::clamp(cos_farthest, -1.0, 1.0)) + angle_slack;
            cones[static_cast<std::size_t>(iv) * resolution + iu] = {
                centre.x, centre.y, centre.z, std::cos(radius), std::sin(radius)};
        }
    });
    return cones;
}

// A face coordinate range, clamped to the face.
struct Range {
    double low, high;
};

// The face coordinates that a table's shapes reach on one face; none yet
// when low > high.
struct FaceSpan {
    Range u{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    Range v = u;
    void add(const Range& u_range, const Range& v_range) {
        u = {std::min(u.low, u_range.low), std::max(u.high, u_range.high)};
        v = {std::min(v.low, v_range.low), std::max(v.high, v_range.high)};
    }
    void add(const FaceSpan& other) { add(other.u, other.v); }
};
using FaceSpans = std::array<FaceSpan, 6>;

// Every face whole: a shape around the point is listed in every cell.
FaceSpans whole_faces() {
    FaceSpans spans;
    for (FaceSpan& s : spans) s = {{-1.0, 1.0}, {-1.0, 1.0}};
    return spans;
}

// A cone of directions: those within `angle` of the unit `axis`, with the
// angle's cosine and sine, which is how the tests below use it.
struct Cone {
    Vec3 axis;
    double cos_angle, sin_angle;
};

// Calls visit(face, u, v) with the ranges of face coordinates that directions
// in the cone may take on each face they may lie on.
template <typename Visit>
void face_ranges(const Cone& cone, Visit&& visit) {
    // The range of each component of a direction in the cone: from the cosine
    // of the axis's angle theta to component i, cos(theta +- angle) by the sum
    // formula, or -1 and 1 where theta + angle reaches pi and theta - angle 0.
    // Its rounding (~1e-8 where the axis lies along i) is far inside the slack.
    const double ca = cone.cos_angle, sa = cone.sin_angle;
    std::array<double, 3> lo{}, hi{};
    for (int i = 0; i < 3; ++i) {
        const double c = std::clamp(cone.axis[i], -1.0, 1.0);
        const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
        lo[i] = (ca <= -c ? -1.0 : c * ca - s * sa) - angle_slack;
        hi[i] = (ca <= c ? 1.0 : c * ca + s * sa) + angle_slack;
    }
    for (int face = 0; face < 6; ++face) {
        const auto [k, j, l] = face_axes(face / 2);
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        const double w_lo = std::max(sign > 0 ? lo[k] : -hi[k], min_face_component);
        const double w_hi = sign > 0 ? hi[k] : -lo[k];
        if (w_hi < w_lo) continue;
        // u = d_j / w over the box of components: the extremes are at corners.
        auto range = [&](int axis_index) {
            const double a = lo[axis_index], b = hi[axis_index];
            const double low = std::min(a / w_lo, a / w_hi) - coordinate_slack;
            const double high = std::max(b / w_lo, b / w_hi) + coordinate_slack;
            return Range{std::clamp(low, -1.0, 1.0), std::clamp(high, -1.0, 1.0)};
        };
        visit(face, range(j), range(l));
    }
}

// Calls add(cell) for every cell whose cone meets `cone`. `cones`: each
// face's cells' cones.
template <typename Add>
void rasterise_cone(const Cone& cone, int resolution, const std::array<FaceWindow, 6>& windows,
                    const std::array<std::vector<CellCone>, 6>& cones, Add&& add) {
    const Vec3& axis = cone.axis;
    const double cos_angle = cone.cos_angle, sin_angle = cone.sin_angle;
    face_ranges(cone, [&](int face, Range u, Range v) {
        const FaceWindow& w = windows[static_cast<std::size_t>(face)];
        const auto [k, j, l] = face_axes(face / 2);
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        const int u0 = cell_coordinate((u.low - w.u0) * w.u_scale, resolution);
        const int u1 = cell_coordinate((u.high - w.u0) * w.u_scale, resolution);
        const int v0 = cell_coordinate((v.low - w.v0) * w.v_scale, resolution);
        const int v1 = cell_coordinate((v.high - w.v0) * w.v_scale, resolution);
        const std::size_t face_base = static_cast<std::size_t>(face) * resolution * resolution;
        const std::vector<CellCone>& face_cones = cones[static_cast<std::size_t>(face)];
        for (int iv = v0; iv <= v1; ++iv)
            for (int iu = u0; iu <= u1; ++iu) {
                const std::size_t local = static_cast<std::size_t>(iv) * resolution + iu;
                const CellCone& c = face_cones[local];
                // Cones meet when the angle between their axes is at most the
                // sum of their angles: compare cosines.
                const double cos_between = c.u * axis[j] + c.v * axis[l] + c.w * sign * axis[k];
                const double cos_sum = cos_angle * c.cos_radius - sin_angle * c.sin_radius;
                if (cos_between >= cos_sum - angle_slack) add(face_base + local);
            }
    });
}

// A face window over the union of ranges [u_low, u_high] x [v_low, v_high]
// (nothing when u_low > u_high), `resolution` cells along each edge.
FaceWindow window_over(double u_low, double u_high, double v_low, double v_high, int resolution) {
    if (u_low > u_high || v_low > v_high) return {};
    // Cells of a width, even where a range shrank to a face's edge.
    auto widen = [](double& low, double& high) {
        if (high - low >= min_window) return;
        low = std::max(-1.0, low - min_window);
        high = std::min(1.0, high + min_window);
    };
    widen(u_low, u_high);
    widen(v_low, v_high);
    return {
        u_low, u_high, v_low, v_high, resolution / (u_high - u_low), resolution / (v_high - v_low)};
}

}  // namespace

DirectionTable build_direction_table(const Geometry& geometry, const Vec3& position,
                                     int resolution) {
    DirectionTable table;
    const std::size_t shapes = geometry.spheres.size() + geometry.shapes.size();
    if (shapes == 0 || shapes > max_table_work || resolution < 1) return table;
    const int r = resolution;
    const std::size_t cells = 6 * static_cast<std::size_t>(r) * r;

    // Each shape's cone of directions seen from the point, or none for a
    // shape listed in every cell; then each face's window over the cones
    // that reach it, a whole face where a shape is listed everywhere.
    struct ShapeCone {
        Cone cone;
        bool everywhere;
    };
    std::vector<ShapeCone> shape_cones(shapes);
    std::vector<double> nearest_of(shapes);                 // by sphere index, then shape index
    std::vector<ListedDistance> listed_nearest_of(shapes);  // as the lists hold them
    auto cone_of = [&](const BoundingSphere& b, std::size_t slot) {
        const PaddedBound padded = padded_bound(b.center, b.radius, position);
        const double distance = padded.distance, radius = padded.radius;
        nearest_of[slot] = padded.nearest;
        listed_nearest_of[slot] = listed_distance(padded.nearest);
        const bool everywhere = !(distance > radius) || !std::isfinite(distance) ||
                                radius / distance > std::sin(max_cone_angle);
        if (everywhere) {
            shape_cones[slot] = {{Vec3(0.0), 1.0, 0.0}, true};
            return;
        }
        const double angle = std::asin(radius / distance) + angle_slack;
        shape_cones[slot] = {{(b.center - position) / distance, std::cos(angle), std::sin(angle)},
                             false};
    };
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, shapes, shapes_a_task),
        [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i)
                cone_of(i < geometry.spheres.size()
                            ? BoundingSphere{geometry.spheres[i].center, geometry.spheres[i].radius}
                            : bounding_sphere(geometry.shapes[i - geometry.spheres.size()]),
                        i);
        });
    // Each face's span of the cones, as a minimum and maximum: the same
    // whatever order the threads join them in.
    const FaceSpans spans = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, shapes, shapes_a_task), FaceSpans{},
        [&](const tbb::blocked_range<std::size_t>& range, FaceSpans spans) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                const ShapeCone& c = shape_cones[i];
                if (c.everywhere) return whole_faces();
                face_ranges(c.cone, [&](int face, Range u, Range v) {
                    spans[static_cast<std::size_t>(face)].add(u, v);
                });
            }
            return spans;
        },
        [](FaceSpans a, const FaceSpans& b) {
            for (std::size_t face = 0; face < 6; ++face) a[face].add(b[face]);
            return a;
        });
    // Faces of the same window (whole faces, round a light among the shapes)
    // share their cells' cones: five normalisations and a few trigonometric
    // calls a cell.
    std::array<std::vector<CellCone>, 6> cones;
    for (std::size_t face = 0; face < 6; ++face) {
        const FaceSpan& s = spans[face];
        const FaceWindow w = window_over(s.u.low, s.u.high, s.v.low, s.v.high, r);
        table.windows[face] = w;
        if (!(w.u_scale > 0.0)) continue;
        for (std::size_t other = 0; other < face && cones[face].empty(); ++other) {
            const FaceWindow& o = table.windows[other];
            if (!cones[other].empty() && o.u0 == w.u0 && o.u1 == w.u1 && o.v0 == w.v0 &&
                o.v1 == w.v1)
                cones[face] = cones[other];
        }
        if (cones[face].empty()) cones[face] = cell_cones(r, w);
    }

    // (cell, candidate) pairs, the shapes taken nearest first (ties in index
    // order), then a stable counting sort by cell: each cell's list comes out
    // nearest first without a sort of its own.
    struct Listing {
        std::uint32_t cell, candidate;
    };
    std::vector<std::uint32_t> order(shapes);
    for (std::uint32_t slot = 0; slot < shapes; ++slot) order[slot] = slot;
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return nearest_of[a] < nearest_of[b];
    });
    // Runs of shapes in that order are rasterised in parallel, each into its
    // own pairs; taken run by run, the pairs are in the order a single pass
    // would give.
    const auto spheres = static_cast<std::uint32_t>(geometry.spheres.size());
    std::vector<std::vector<Listing>> runs((shapes + shapes_a_task - 1) / shapes_a_task);
    std::atomic<std::size_t> listed{0};
    tbb::parallel_for(std::size_t{0}, runs.size(), [&](std::size_t run) {
        std::vector<Listing>& pairs = runs[run];
        const std::size_t end = std::min(shapes, (run + 1) * shapes_a_task);
        for (std::size_t at = run * shapes_a_task; at < end; ++at) {
            if (listed.load(std::memory_order_relaxed) > max_listed) return;
            const std::size_t before = pairs.size();
            const std::uint32_t slot = order[at];
            const std::uint32_t candidate = slot < spheres ? slot : (slot - spheres) | shape_flag;
            const ShapeCone& c = shape_cones[slot];
            if (c.everywhere) {
                for (std::size_t cell = 0; cell < cells; ++cell)
                    pairs.push_back({static_cast<std::uint32_t>(cell), candidate});
            } else {
                rasterise_cone(c.cone, r, table.windows, cones, [&](std::size_t cell) {
                    pairs.push_back({static_cast<std::uint32_t>(cell), candidate});
                });
            }
            listed.fetch_add(pairs.size() - before, std::memory_order_relaxed);
        }
    });
    if (listed.load() > max_listed) return {};

    table.resolution = r;
    table.cell_start.assign(cells + 1, 0);
    for (const std::vector<Listing>& pairs : runs)
        for (const Listing& p : pairs) ++table.cell_start[p.cell + 1];
    for (std::size_t c = 0; c < cells; ++c) table.cell_start[c + 1] += table.cell_start[c];
    std::vector<std::uint32_t> fill(table.cell_start.begin(), table.cell_start.end() - 1);
    table.shapes.resize(listed.load());
    table.nearest.resize(listed.load());
    for (const std::vector<Listing>& pairs : runs)
        for (const Listing& p : pairs) {
            const std::uint32_t at = fill[p.cell]++;
            table.shapes[at] = p.candidate;
            table.nearest[at] =
                listed_nearest_of[p.candidate & shape_flag ? spheres + (p.candidate & ~shape_flag)
                                                           : p.candidate];
        }
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
