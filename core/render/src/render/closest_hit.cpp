// closest_hit (render/ray_queries.hpp): the nearest surface along a ray, by
// the shortest of the ways that give the same answer: a table's list, the
// groups of a small scene, every shape, or Embree's BVH walk; and the BVH's
// callbacks for it.

#include "geometry/intersect.hpp"
#include "render/far_ray.hpp"
#include "render/float_ray.hpp"
#include "render/ray_queries.hpp"
#include "render/shape_groups.hpp"
#include "render/shape_tests.hpp"
#include "render/sphere_batch.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace jt {

namespace {

constexpr std::uint32_t no_source = std::numeric_limits<std::uint32_t>::max();

// A closest-hit query that has tested this many shapes of a list that is not
// covered leaves the rest to the BVH: testing each costs more than Embree's
// walk past most of them (a longer walk, 64, cost lattice and sphereflake
// 0.5-1%).
constexpr std::size_t max_closest_walk = 16;
// A covered list is walked however long it is, but only so far: a walk that
// has tested this many without settling the ray hands it to the BVH.
constexpr std::size_t max_covered_position = 256;
// A covered list at least this long is walked in batches (closest_by_listed);
// a shorter one mostly ends at its first shapes, where a batch costs more than
// it decides.
constexpr std::size_t min_batched_list = 16;
// Where the spheres overlap heavily (Geometry::crowded), a covered list's
// walk passes more spheres it enters beyond its hit than it stops at, down
// to lists of a few.
constexpr std::size_t min_crowded_batched_list = 4;

enum class HitKind : std::uint8_t { plane, sphere, shape };

// Embree hands our callbacks the context pointer we passed in; the query
// starts with it so that it can be found again from it.
struct ClosestQuery {
    RTCIntersectContext context;
    const Geometry* geometry;
    Vec3 origin, direction;
    double t_min;
    double t;
    std::uint32_t source;
    // How to find the normal of the best hit once the walk is over.
    HitKind kind;
    std::uint32_t index;
    CylinderPart part;
    // For a ray moved into Embree's reach: how its distances map to Embree's.
    const FarRay* far = nullptr;
};

// Up to and including `t`, for the tie rule.
double just_beyond(double t) {
    if (!(t < no_hit)) return t;
    if (t == 0.0) return std::numeric_limits<double>::denorm_min();
    if (t < 0.0) return std::nextafter(t, no_hit);
    return std::bit_cast<double>(std::bit_cast<std::uint64_t>(t) + 1u);
}

bool better(double t, std::uint32_t source, const ClosestQuery& q) {
    return t < q.t || (t == q.t && source < q.source);
}

void accept(const RTCIntersectFunctionNArguments* args, const ClosestQuery& q) {
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    RTCRayN_tfar(ray, args->N, 0) = q.far ? far_t_up(*q.far, q.t) : float_up(q.t);
    RTCHitN_geomID(hit, args->N, 0) = args->geomID;
    RTCHitN_primID(hit, args->N, 0) = args->primID;
    RTCHitN_instID(hit, args->N, 0, 0) = RTC_INVALID_GEOMETRY_ID;
}

// Tests one sphere or shape against the query; true when it became the best
// hit. The BVH callbacks and the BVH-less walk share these, so that both
// decide hits and ties the same way.
bool offer_sphere(ClosestQuery& q, std::uint32_t index) {
    const WorldSphere& s = q.geometry->spheres[index];
    double t =
        intersect_sphere(q.origin, q.direction, s.center, s.radius, q.t_min, just_beyond(q.t));
    if (t == no_hit || !better(t, s.source, q)) return false;
    q.t = t;
    q.source = s.source;
    q.kind = HitKind::sphere;
    q.index = index;
    return true;
}

bool offer_shape(ClosestQuery& q, std::uint32_t index) {
    const TransformedShape& s = q.geometry->shapes[index];
    CylinderPart part = CylinderPart::side;
    double t = shape_distance(s, q.origin, q.direction, q.t_min, just_beyond(q.t), part);
    if (t == no_hit || !better(t, s.source, q)) return false;
    q.t = t;
    q.source = s.source;
    q.kind = HitKind::shape;
    q.index = index;
    q.part = part;
    return true;
}

// Offers `listed` (a sphere index, or a shape index with shape_flag) to the
// query; a shape's bounding sphere is tried before its exact test.
void offer_listed(ClosestQuery& q, std::uint32_t listed) {
    if (!(listed & shape_flag))
        offer_sphere(q, listed);
    else if (!misses_bounds(q.geometry->shapes[listed & ~shape_flag], q.origin, q.direction))
        offer_shape(q, listed & ~shape_flag);
}

// The queries of a geometry without a BVH: every shape tested, in index order.
void closest_by_testing_all(ClosestQuery& q) {
    const Geometry& g = *q.geometry;
    for (std::uint32_t i = 0; i < g.spheres.size(); ++i) offer_sphere(q, i);
    for (std::uint32_t i = 0; i < g.shapes.size(); ++i)
        if (!misses_bounds(g.shapes[i], q.origin, q.direction)) offer_shape(q, i);
}

// The spheres among the `count` (at most sphere_batch) listed shapes from
// `first`, as lanes of a batch; the bits of the lanes that hold one. Lanes
// past the list, and lanes of transformed shapes, hold the first sphere and
// are not read.
[[gnu::always_inline]] inline unsigned batch_lanes(const Geometry& g, const std::uint32_t* first,
                                                   std::size_t count,
                                                   const WorldSphere* (&lanes)[sphere_batch]) {
    unsigned spheres = 0;
    for (std::size_t j = 0; j < sphere_batch; ++j) {
        const std::uint32_t shape = j < count ? first[j] : shape_flag;
        const bool sphere = !(shape & shape_flag);
        lanes[j] = g.spheres.data() + (sphere ? shape : 0u);
        spheres |= static_cast<unsigned>(sphere) << j;
    }
    return spheres;
}

bool closest_by_listed_in_batches(ClosestQuery& q, const ListedShapes& listed, std::size_t limit,
                                  double length);

// The walk of a direction table's list around the ray's origin: it stops at
// the first shape that lies wholly beyond the best hit so far. True when that
// settles the ray; false when `limit` shapes were tested first, and the rest
// of the list is left to the BVH (the best hit so far stays in the query, and
// the answer is the nearest of all, whichever found it).
//
// A covered list (heavily overlapping spheres) of min_batched_list shapes or
// more, or of min_crowded_batched_list where the spheres are crowded, is
// walked in batches: the spheres among the next few shapes the walk
// may reach are first given the early tests of intersect_sphere together
// (sphere_batch.hpp), against the best hit as it stands. The ones those
// decide would answer no_hit to any nearer best hit too, and are passed over;
// the rest are offered one by one, in list order, each after the walk's own
// test of whether it goes on. Most spheres of such a list lie beyond the
// nearest hit or pass wide of the ray. Other lists, and short covered ones,
// mostly end at their first or second shape, where a batch would only add
// work: they are walked one shape at a time. A batched walk first offers the
// list's hint, if it has one, and leaves the hint on its best hit; in a
// shorter list the hinted sphere is mostly the first, and would be tested
// twice.
bool closest_by_listed(ClosestQuery& q, const ListedShapes& listed, std::size_t limit) {
    const double length = glm::length(q.direction);
    const std::size_t size = listed.size();
    if (!listed.covered ||
        size < (q.geometry->crowded ? min_crowded_batched_list : min_batched_list)) {
        for (std::size_t k = 0; k < size; ++k) {
            if (listed.nearest[k] > q.t * length) return true;
            if (k == limit) return false;
            offer_listed(q, listed.shapes[k]);
        }
        return true;
    }
    if (listed.hint) {
        const std::uint32_t hinted = listed.hint->sphere;
        if (hinted < q.geometry->spheres.size()) offer_sphere(q, hinted);
    }
    const bool settled = closest_by_listed_in_batches(q, listed, limit, length);
    if (listed.hint && q.kind == HitKind::sphere && q.source != no_source)
        listed.hint->sphere = q.index;
    return settled;
}

// closest_by_listed's walk of a covered list in batches; `length` is that of
// the ray's direction.
bool closest_by_listed_in_batches(ClosestQuery& q, const ListedShapes& listed, std::size_t limit,
                                  double length) {
    const std::size_t size = listed.size();
    const BatchRay ray = batch_ray(q.origin, q.direction, q.t_min);
    const bool avx = sphere_batch_avx();
    std::size_t k = 0;
    while (k < size) {
        const double reach = q.t * length;
        if (listed.nearest[k] > reach) return true;
        if (k == limit) return false;
        // The shapes the walk reaches unless a hit among them stops it.
        const std::size_t end = std::min({size, limit, k + sphere_batch});
        std::size_t count = 1;
        while (k + count < end && !(listed.nearest[k + count] > reach)) ++count;
        const WorldSphere* lanes[sphere_batch];
        const unsigned spheres =
            count == 1 ? 0u : batch_lanes(*q.geometry, &listed.shapes[k], count, lanes);
        if (spheres == 0) {
            offer_listed(q, listed.shapes[k]);
            ++k;
            continue;
        }
        const unsigned missed = spheres_missed<true>(avx, lanes, ray, just_beyond(q.t)) & spheres;
        for (std::size_t j = 0; j < count; ++j) {
            if (j > 0 && listed.nearest[k + j] > q.t * length) return true;
            if (!(missed >> j & 1u)) offer_listed(q, listed.shapes[k + j]);
        }
        k += count;
    }
    return true;
}

// Whether the groups of a small scene (render/shape_groups.hpp) take a ray
// from `origin`.
[[gnu::always_inline]] inline bool groups_take(const ShapeGroups& groups, const Vec3& origin) {
    return !groups.empty() && std::abs(origin.x) <= groups.reach &&
           std::abs(origin.y) <= groups.reach && std::abs(origin.z) <= groups.reach;
}

// Every shape of a small scene offered to the query, but for those that the
// early answers decide: four groups' spheres at a time, then the spheres of
// each group the ray may meet, against the best hit as it stands. What is
// offered, and in which order, never changes the answer (closest_hit).
void closest_by_groups(ClosestQuery& q) {
    const ShapeGroups& groups = q.geometry->groups;
    const BatchRay ray = batch_ray(q.origin, q.direction, q.t_min);
    const bool avx = sphere_batch_avx();
    const std::size_t count = groups.count();
    for (std::size_t first = 0; first < count; first += sphere_batch) {
        const unsigned live = count - first >= sphere_batch ? (1u << sphere_batch) - 1u
                                                            : (1u << (count - first)) - 1u;
        unsigned open =
            ~lanes_missed<false>(avx, groups.bounds[first / sphere_batch], ray, 0.0) & live;
        while (open != 0) {
            const std::size_t group = first + static_cast<std::size_t>(std::countr_zero(open));
            open &= open - 1u;
            const unsigned missed =
                lanes_missed<true>(avx, groups.members[group], ray, just_beyond(q.t)) &
                groups.spheres[group];
            unsigned offer = groups.used[group] & ~missed;
            while (offer != 0) {
                const std::size_t j = static_cast<std::size_t>(std::countr_zero(offer));
                offer &= offer - 1u;
                offer_listed(q, groups.listed[group * sphere_batch + j]);
            }
        }
    }
}

}  // namespace

// Flattened: GCC weighs inlining offer_sphere here against all its calls,
// and one more of them made it stop (1% more instructions on few).
[[gnu::flatten]] void sphere_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto& q = *reinterpret_cast<ClosestQuery*>(args->context);
    if (offer_sphere(q, args->primID)) accept(args, q);
}

void shape_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto& q = *reinterpret_cast<ClosestQuery*>(args->context);
    if (offer_shape(q, args->primID)) accept(args, q);
}

bool closest_hit(const Geometry& geometry, const Vec3& origin, const Vec3& direction, double t_min,
                 Hit& hit, const ListedShapes* candidates, const Departure& from) {
    ClosestQuery q;
    q.geometry = &geometry;
    q.origin = origin;
    q.direction = direction;
    q.t_min = t_min;
    q.t = no_hit;
    q.source = no_source;
    q.kind = HitKind::plane;
    q.index = 0;
    q.part = CylinderPart::side;

    // Planes first: a near plane hit tightens the BVH walk.
    for (std::uint32_t i = 0; i < geometry.planes.size(); ++i) {
        const WorldPlane& p = geometry.planes[i];
        double t =
            intersect_plane(origin, direction, p.normal, p.distance, t_min, just_beyond(q.t));
        if (t != no_hit && better(t, p.source, q)) {
            q.t = t;
            q.source = p.source;
            q.index = i;
        }
    }
    for (const std::uint32_t listed : geometry.beyond_bvh) offer_listed(q, listed);

    // A long list is walked too when a sphere on it covers the block
    // (heavily overlapping spheres): that sphere's hit soon ends the walk,
    // long before Embree would have offered every sphere whose box the ray
    // crosses. Past max_covered_position shapes the BVH walk takes over from
    // the best hit so far. Any other long list has its head walked: its
    // nearest shapes often settle the ray, and where they do not, the BVH
    // walk starts from their best hit.
    bool settled = false;
    if (candidates) {
        const std::size_t limit = !geometry.bvh ? candidates->size()
                                  : candidates->size() <= max_closest_walk || candidates->covered
                                      ? max_covered_position
                                      : max_closest_walk;
        settled = closest_by_listed(q, *candidates, limit);
    }
    if (!settled && !candidates && groups_take(geometry.groups, origin)) {
        closest_by_groups(q);
    } else if (!settled && !geometry.bvh) {
        closest_by_testing_all(q);
    } else if (!settled) {
        rtcInitIntersectContext(&q.context);
        RTCRayHit rayhit;
        clear_hit(rayhit.hit);
        const FarRay far = fit_embree_ray(geometry.bvh, origin, direction, t_min, q.t, rayhit.ray);
        if (far.fit == FarRay::Fit::out_of_reach) {
            closest_by_testing_all(q);
        } else if (far.fit != FarRay::Fit::misses) {
            if (far.fit == FarRay::Fit::moved) q.far = &far;
            rtcIntersect1(geometry.bvh, &q.context, &rayhit);
            q.far = nullptr;
        }
    }
    // Triangles last, no farther than the nearest other surface.
    TriangleHit triangle;
    if (geometry.triangles &&
        closest_triangle(*geometry.triangles, origin, direction, t_min, just_beyond(q.t), triangle,
                         from) &&
        better(triangle.t, triangle.source, q)) {
        const TriangleSurface surface = triangle_surface(*geometry.triangles, triangle);
        hit.t = triangle.t;
        hit.source = triangle.source;
        hit.normal = surface.geometric;
        hit.triangle = triangle.id;
        hit.shading = surface.shading;
        hit.uv = surface.uv;
        hit.barycentric = {triangle.u, triangle.v};
        return true;
    }
    if (q.source == no_source) return false;
    hit.triangle = {};
    hit.shading = Vec3(0.0);
    hit.uv = glm::dvec2(0.0);

    hit.t = q.t;
    hit.source = q.source;
    if (q.kind == HitKind::plane) {
        hit.normal = geometry.planes[q.index].normal;
    } else if (q.kind == HitKind::sphere) {
        const WorldSphere& s = geometry.spheres[q.index];
        hit.normal = (origin + q.t * direction) - s.center;
    } else {
        const TransformedShape& s = geometry.shapes[q.index];
        Vec3 p = apply_point(s.to_object, origin) + q.t * apply_vector(s.to_object, direction);
        Vec3 n =
            s.kind == TransformedShape::Kind::sphere ? p - s.center : cylinder_normal(p, q.part);
        hit.normal = s.normal_matrix * n;
    }
    return true;
}

}  // namespace jt
