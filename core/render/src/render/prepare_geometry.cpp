#include "render/prepare_geometry.hpp"

#include "geometry/bounds.hpp"
#include "render/embree_device.hpp"
#include "render/far_ray.hpp"
#include "render/listed_shapes.hpp"
#include "render/ray_queries.hpp"
#include "render/shadow_spheres.hpp"
#include "render/shape_groups.hpp"
#include "render/user_geometry.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

namespace jt {

Geometry::~Geometry() {
    if (bvh) rtcReleaseScene(bvh);
    if (shadow.bvh) rtcReleaseScene(shadow.bvh);
}

namespace {

// Past this many bounded primitives, a faster Morton build pays off more than a
// better tree: the render of a large scene is short next to its build, and the
// build is all of the wait for its first preview. Measured on spheres_100k
// (docs/benchmarks.md §4.1): the Morton build takes a quarter of the CPU time of
// the binned SAH build, and the whole render no more.
constexpr std::size_t fast_build_threshold = 50000;

// Up to this many bounded shapes, the ray queries test every one instead of
// walking a BVH: on the showcase (6 shapes) that halves the time a ray.
constexpr std::size_t brute_force_limit = 8;

// Spreads the 10 low bits of v to every third bit.
std::uint32_t spread_bits(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

// Puts the spheres in Morton order of their centres. Embree's Morton builder
// asks for the boxes in that order, and rays meet neighbours together: in
// source order both jumped about a 40 MB array. Which sphere a ray meets
// first never depends on this order (ties go to the lower source).
void sort_spheres_along_a_curve(std::vector<WorldSphere>& spheres) {
    glm::dvec3 low(std::numeric_limits<double>::infinity());
    glm::dvec3 high(-std::numeric_limits<double>::infinity());
    for (const WorldSphere& s : spheres) {
        low = glm::min(low, s.center);
        high = glm::max(high, s.center);
    }
    const glm::dvec3 extent = high - low;
    if (!all_finite(extent)) return;  // past double's range: left in source order
    const glm::dvec3 scale(extent.x > 0 ? 1023.0 / extent.x : 0.0,
                           extent.y > 0 ? 1023.0 / extent.y : 0.0,
                           extent.z > 0 ? 1023.0 / extent.z : 0.0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> keys(spheres.size());
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const glm::dvec3 cell = (spheres[i].center - low) * scale;
        const auto bits = [](double c) { return static_cast<std::uint32_t>(c); };
        keys[i] = {spread_bits(bits(cell.x)) | (spread_bits(bits(cell.y)) << 1) |
                       (spread_bits(bits(cell.z)) << 2),
                   static_cast<std::uint32_t>(i)};
    }
    tbb::parallel_sort(keys.begin(), keys.end());
    std::vector<WorldSphere> sorted(spheres.size());
    for (std::size_t i = 0; i < keys.size(); ++i) sorted[i] = spheres[keys[i].second];
    spheres = std::move(sorted);
}

// The world spheres' boxes and their magnitude are worked out on every core
// in ranges of at least this many spheres: a sphere's box takes about 70 ns,
// so a range is worth handing to another thread, and a million spheres make
// enough of them for any number of threads.
constexpr std::size_t spheres_a_task = 16384;

void add_sphere(Geometry& g, const Sphere& sphere, const ObjectTransform* transform,
                std::uint32_t source) {
    if (!all_finite(sphere.center) || !(sphere.radius > 0.0) || !std::isfinite(sphere.radius))
        return;
    if (!transform) {
        g.spheres.push_back({sphere.center, sphere.radius, source});
        return;
    }
    // A rotation times a uniform scale keeps a sphere a sphere: trace it as one.
    if (auto scale = similarity_scale(transform->to_world.linear)) {
        g.spheres.push_back(
            {apply_point(transform->to_world, sphere.center), sphere.radius * *scale, source});
        return;
    }
    // Its rays are taken to its object space moved to its centre, with the
    // centre folded into the map's translation once: the ray's origin there
    // is then of the sphere's own size and rounds at it. Taken to the object
    // space as written, it rounds at the size of the centre there, which a
    // map may make 1e7 radii or more (a translate by nearly minus the centre,
    // then a large scale): about the lift of §8.5, so that a ray leaving the
    // sphere met it again. The fold's own rounding moves the sphere once, for
    // every ray alike.
    TransformedShape s;
    s.to_object = transform->to_object;
    s.to_object.translation -= sphere.center;
    s.normal_matrix = transform->normal_matrix;
    s.center = Vec3(0.0);
    s.radius = sphere.radius;
    s.kind = TransformedShape::Kind::sphere;
    s.source = source;
    s.bounds = padded_float_bounds(
        transformed_sphere_box(sphere.center, sphere.radius, transform->to_world), 0.0);
    g.shapes.push_back(s);
}

void add_cylinder(Geometry& g, const Cylinder& cylinder, const ObjectTransform& transform,
                  std::uint32_t source) {
    if (!(cylinder.radius > 0.0) || !(cylinder.height > 0.0) || !std::isfinite(cylinder.radius) ||
        !std::isfinite(cylinder.height))
        return;
    TransformedShape s;
    s.to_object = transform.to_object;
    s.normal_matrix = transform.normal_matrix;
    s.radius = cylinder.radius;
    s.height = cylinder.height;
    s.kind = TransformedShape::Kind::cylinder;
    s.source = source;
    s.bounds = padded_float_bounds(
        transformed_cylinder_box(cylinder.radius, cylinder.height, transform.to_world), 0.0);
    g.shapes.push_back(s);
}

// A plane stays a plane under any invertible affine map: move it to world space
// once, so that it costs one dot product a ray.
void add_plane(Geometry& g, const Plane& plane, const ObjectTransform& transform,
               std::uint32_t source) {
    auto n = unit_length(plane.normal);
    if (!n || !std::isfinite(plane.distance)) return;
    auto world_normal = unit_length(transform.normal_matrix * *n);
    if (!world_normal) return;
    double distance = glm::dot(*world_normal, apply_point(transform.to_world, *n * plane.distance));
    if (!std::isfinite(distance)) return;
    g.planes.push_back({*world_normal, distance, source});
}

// The sphere through the corners of the shape's box, grown by a margin far
// above any rounding of the test that uses it, so that it never rejects a hit.
void add_bounding_sphere(TransformedShape& s) {
    Vec3 lower(s.bounds.lower_x, s.bounds.lower_y, s.bounds.lower_z);
    Vec3 upper(s.bounds.upper_x, s.bounds.upper_y, s.bounds.upper_z);
    s.bounding_center = 0.5 * (lower + upper);
    Vec3 half = 0.5 * (upper - lower);
    double margin = 1e-6 * std::max({1.0, glm::length(s.bounding_center), glm::length(half)});
    double radius = glm::length(half) + margin;
    s.bounding_radius_sq = radius * radius;
}

// The largest coordinate any box reaches: float rays that travel this far
// drift from their double originals by about 2^-24 of it. A maximum is the
// same however its values are grouped, so the spheres' share is taken in
// parallel.
double scene_magnitude(const Geometry& g) {
    auto grow = [](double& m, const Vec3& v) {
        m = std::max({m, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    };
    double m = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, g.spheres.size(), spheres_a_task), 0.0,
        [&](const tbb::blocked_range<std::size_t>& range, double most) {
            for (std::size_t i = range.begin(); i != range.end(); ++i)
                grow(most, glm::abs(g.spheres[i].center) + Vec3(g.spheres[i].radius));
            return most;
        },
        [](double a, double b) { return std::max(a, b); });
    const auto grow_m = [&](const Vec3& v) { grow(m, v); };
    for (const TransformedShape& s : g.shapes) {
        grow_m(Vec3(s.bounds.lower_x, s.bounds.lower_y, s.bounds.lower_z));
        grow_m(Vec3(s.bounds.upper_x, s.bounds.upper_y, s.bounds.upper_z));
    }
    return m;
}

// The gathered shapes as the BVH and the tables read them: in the order the
// BVH builder wants, each transformed shape's box grown by the slack and its
// bounding sphere around that box. The scene's magnitude before the slack,
// which the BVH needs; none for a handful of shapes, which need no BVH.
std::optional<double> finish_shapes(Geometry& g) {
    const std::size_t bounded = g.spheres.size() + g.shapes.size();
    if (bounded <= brute_force_limit) {
        for (TransformedShape& s : g.shapes) add_bounding_sphere(s);
        return std::nullopt;
    }
    if (bounded > fast_build_threshold) sort_spheres_along_a_curve(g.spheres);
    const double magnitude = scene_magnitude(g);
    g.bounds_slack = 1e-6 * magnitude;
    for (TransformedShape& s : g.shapes) {
        s.bounds.lower_x -= static_cast<float>(g.bounds_slack);
        s.bounds.lower_y -= static_cast<float>(g.bounds_slack);
        s.bounds.lower_z -= static_cast<float>(g.bounds_slack);
        s.bounds.upper_x += static_cast<float>(g.bounds_slack);
        s.bounds.upper_y += static_cast<float>(g.bounds_slack);
        s.bounds.upper_z += static_cast<float>(g.bounds_slack);
        add_bounding_sphere(s);  // for the direction tables' lists, which have no boxes
    }
    return magnitude;
}

// The BVH over finished shapes (finish_shapes), with the lists it needs. It
// leaves the shapes as they are, so the light tables may be built beside it.
void build_bvh(Geometry& g, double magnitude) {
    const std::size_t bounded = g.spheres.size() + g.shapes.size();
    // Past half of Embree's reach, a padded box may reach beyond it; below,
    // none of the spheres' can (their padding is a few millionths of the
    // magnitude), and the pass is saved. NaN takes the pass.
    std::atomic<bool> spheres_beyond{false};
    if (!(magnitude <= embree_reach / 2))
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, g.spheres.size(), spheres_a_task),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              bool beyond = false;
                              for (std::size_t i = range.begin(); i != range.end(); ++i)
                                  beyond = beyond || !within_reach(padded_sphere_bounds(g, i));
                              if (beyond) spheres_beyond.store(true, std::memory_order_relaxed);
                          });
    // Rare (spheres past float range), so listed in order afterwards.
    if (spheres_beyond.load(std::memory_order_relaxed)) {
        for (std::uint32_t i = 0; i < g.spheres.size(); ++i)
            if (!within_reach(padded_sphere_bounds(g, i))) g.beyond_bvh.push_back(i);
    }
    for (std::uint32_t i = 0; i < g.shapes.size(); ++i)
        if (!within_reach(g.shapes[i].bounds)) g.beyond_bvh.push_back(i | shape_flag);

    if (g.beyond_bvh.empty()) g.groups = group_shapes(g.spheres, g.shapes);

    g.bvh = rtcNewScene(embree_device());
    const RTCBuildQuality quality =
        bounded > fast_build_threshold ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM;
    rtcSetSceneBuildQuality(g.bvh, quality);
    rtcSetSceneFlags(g.bvh, RTC_SCENE_FLAG_ROBUST);
    if (!g.spheres.empty())
        g.sphere_geometry_id = attach_user_geometry(
            g.bvh, &g, g.spheres.size(), quality, sphere_bounds, sphere_intersect, sphere_occluded);
    if (!g.shapes.empty())
        g.shape_geometry_id = attach_user_geometry(g.bvh, &g, g.shapes.size(), quality,
                                                   shape_bounds, shape_intersect, shape_occluded);
    rtcCommitScene(g.bvh);
    g.crowded = spheres_overlap_heavily(g.spheres);
    if (g.crowded) build_shadow_spheres(g, magnitude, quality);
}

}  // namespace

Expected<std::shared_ptr<Geometry>> gather_geometry(const Scene& scene) {
    auto g = std::make_shared<Geometry>();
    auto triangles = build_triangle_geometry(scene);
    if (!triangles) return triangles.error();
    g->triangles = std::move(*triangles);
    // Room for the common case, every primitive a plain sphere: pages never
    // written cost nothing, while growing by copies would touch them all twice.
    g->spheres.reserve(scene.primitives.size());
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        const Primitive& p = scene.primitives[i];
        // Primitives the transform rule leaves out never reach the geometry.
        ObjectTransform transform;
        if (!p.transforms.empty()) {
            auto placed = object_transform(p.transforms);
            if (std::holds_alternative<LeftOut>(placed)) continue;
            transform = std::get<ObjectTransform>(placed);
        }
        auto source = static_cast<std::uint32_t>(i);
        if (const auto* sphere = shape_if<Sphere>(&p.shape))
            add_sphere(*g, *sphere, p.transforms.empty() ? nullptr : &transform, source);
        else if (const auto* cylinder = shape_if<Cylinder>(&p.shape))
            add_cylinder(*g, *cylinder, transform, source);
        else if (const auto* plane = shape_if<Plane>(&p.shape))
            add_plane(*g, *plane, transform, source);
    }
    return g;
}

std::vector<DirectionTable> build_bvh_and_light_tables(Geometry& g,
                                                       const std::vector<PointLight>& lights) {
    const std::optional<double> magnitude = finish_shapes(g);
    if (!magnitude) return build_light_tables(g, lights);
    std::vector<DirectionTable> tables;
    tbb::parallel_invoke([&] { build_bvh(g, *magnitude); },
                         [&] { tables = build_light_tables(g, lights); });
    return tables;
}

}  // namespace jt
