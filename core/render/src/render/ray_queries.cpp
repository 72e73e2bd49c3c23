#include "render/ray_queries.hpp"

#include "geometry/intersect.hpp"
#include "jtracer/check.hpp"
#include "render/far_ray.hpp"
#include "render/float_ray.hpp"
#include "render/shadow_spheres.hpp"
#include "render/shape_groups.hpp"
#include "render/sphere_batch.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

namespace jt {

namespace {

constexpr std::uint32_t no_source = std::numeric_limits<std::uint32_t>::max();

// A shadow ray whose walk of its light's cell would test more shapes than
// this, or a closest-hit query that has tested as many of its list, is left
// to the BVH: testing each costs more than Embree's walk past most of them.
constexpr std::size_t max_cell_candidates = 16;
// Where the spheres overlap heavily (Geometry::crowded), testing a light's
// cell list beats the BVH walk, even the shadow BVH's, up to about this many
// (docs/benchmarks.md §2.7).
constexpr std::size_t max_crowded_light_candidates = 256;
constexpr std::size_t short_candidate_list = 2;
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

// Embree hands our callbacks the context pointer we passed in; the query
// structs start with it so that they can be found again from it.
enum class HitKind : std::uint8_t { plane, sphere, shape };

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

// One ray, or a packet whose lanes name their ray by their id: Embree may
// hand a packet's lanes to the callbacks one by one, in copies.
struct OcclusionQuery {
    RTCIntersectContext context;
    const Geometry* geometry;
    const ShadowRay* rays;
    OccluderHint blocker;  // what blocked a ray, once something did
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

double shape_distance(const TransformedShape& s, const Vec3& origin, const Vec3& direction,
                      double t_min, double t_max, CylinderPart& part) {
    Vec3 o = apply_point(s.to_object, origin);
    Vec3 d = apply_vector(s.to_object, direction);
    if (s.kind == TransformedShape::Kind::sphere)
        return intersect_sphere(o, d, s.center, s.radius, t_min, t_max);
    return intersect_cylinder(o, d, s.radius, s.height, t_min, t_max, part);
}

void accept(const RTCIntersectFunctionNArguments* args, const ClosestQuery& q) {
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    RTCRayN_tfar(ray, args->N, 0) = q.far ? far_t_up(*q.far, q.t) : float_up(q.t);
    RTCHitN_geomID(hit, args->N, 0) = args->geomID;
    RTCHitN_primID(hit, args->N, 0) = args->primID;
    RTCHitN_instID(hit, args->N, 0, 0) = RTC_INVALID_GEOMETRY_ID;
}

// Tests each live lane of the callback's rays against one surface.
template <class Blocks>
void occlude_lanes(const RTCOccludedFunctionNArguments* args, OccluderHint hit, Blocks blocks) {
    auto& q = *reinterpret_cast<OcclusionQuery*>(args->context);
    for (unsigned lane = 0; lane < args->N; ++lane) {
        if (!args->valid[lane]) continue;
        const ShadowRay& r = q.rays[RTCRayN_id(args->ray, args->N, lane)];
        if (blocks(q.geometry, r)) {
            q.blocker = hit;
            RTCRayN_tfar(args->ray, args->N, lane) = -float_infinity;
        }
    }
}

// Lane `lane` of a packet, as set_float_ray sets a single ray; its id names it.
template <class Packet>
void set_float_lane(Packet& packet, unsigned lane, const ShadowRay& r) {
    packet.org_x[lane] = static_cast<float>(r.origin.x);
    packet.org_y[lane] = static_cast<float>(r.origin.y);
    packet.org_z[lane] = static_cast<float>(r.origin.z);
    packet.dir_x[lane] = static_cast<float>(r.direction.x);
    packet.dir_y[lane] = static_cast<float>(r.direction.y);
    packet.dir_z[lane] = static_cast<float>(r.direction.z);
    packet.tnear[lane] = float_down(r.t_min);
    packet.tfar[lane] = float_up(r.t_max);
    packet.time[lane] = 0.0f;
    packet.mask[lane] = 0xFFFFFFFFu;
    packet.id[lane] = lane;
    packet.flags[lane] = 0;
}

// Whether the line through the ray misses the shape's bounding sphere (the
// direction need not be unit length).
bool misses_bounds(const TransformedShape& s, const Vec3& origin, const Vec3& direction) {
    Vec3 f = origin - s.bounding_center;
    Vec3 perpendicular = f - (glm::dot(f, direction) / glm::dot(direction, direction)) * direction;
    return glm::dot(perpendicular, perpendicular) > s.bounding_radius_sq;
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

// Whether world sphere `s` blocks a shadow ray: the one sphere test of every
// shadow query, without the entry-beyond answer (intersect_sphere says why).
[[gnu::always_inline]] inline bool sphere_blocks(const WorldSphere& s, const Vec3& origin,
                                                 const Vec3& direction, double t_min,
                                                 double t_max) {
    return intersect_sphere<false>(origin, direction, s.center, s.radius, t_min, t_max) != no_hit;
}

// Whether `listed` (a sphere index, or a shape index with shape_flag, as in
// the direction tables) blocks the ray; a shape's bounding sphere is tried
// before its exact test. Forced inline: the list walks call it for every
// shape they test, and GCC kept it a call.
[[gnu::always_inline]] inline bool listed_blocks(const Geometry& g, std::uint32_t listed,
                                                 const Vec3& origin, const Vec3& direction,
                                                 double t_min, double t_max) {
    const std::uint32_t i = listed & ~shape_flag;
    if (!(listed & shape_flag)) return sphere_blocks(g.spheres[i], origin, direction, t_min, t_max);
    const TransformedShape& s = g.shapes[i];
    CylinderPart part;
    return !misses_bounds(s, origin, direction) &&
           shape_distance(s, origin, direction, t_min, t_max, part) != no_hit;
}

OccluderHint hint_for(std::uint32_t listed) {
    return {listed & shape_flag ? OccluderHint::Set::shape : OccluderHint::Set::sphere,
            listed & ~shape_flag};
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

bool occluded_by_testing_all(const Geometry& g, const Vec3& origin, const Vec3& direction,
                             double t_min, double t_max, OccluderHint& blocker) {
    const auto spheres = static_cast<std::uint32_t>(g.spheres.size());
    const auto shapes = static_cast<std::uint32_t>(g.shapes.size());
    for (std::uint32_t k = 0; k < spheres + shapes; ++k) {
        const std::uint32_t listed = k < spheres ? k : (k - spheres) | shape_flag;
        if (listed_blocks(g, listed, origin, direction, t_min, t_max)) {
            blocker = hint_for(listed);
            return true;
        }
    }
    return false;
}

// How near the light a shape must come to be walked for a shadow ray: a
// blocker lies nearer the light than the ray's origin (a list's `nearest`
// are distances from the light).
[[gnu::always_inline]] inline double light_walk_reach(const Vec3& direction, double t_max) {
    return t_max * glm::length(direction) * (1.0 + 1e-9);
}

// Whether the walk of a light's list for a shadow ray tests at most `limit`
// shapes: the list is that short, or its shape at `limit` already lies
// beyond the ray's origin, where the walk stops. A long list often serves
// rays from shapes near its light's end: the shapes behind them are listed
// too, but never walked.
[[gnu::always_inline]] inline bool light_walk_within(const ListedShapes& listed,
                                                     const Vec3& direction, double t_max,
                                                     std::size_t limit) {
    return listed.size() <= limit || listed.nearest[limit] >= light_walk_reach(direction, t_max);
}

// The walk of a direction table's list around the light the ray runs to: a
// blocker lies between the origin and the light, so nearer the light than
// the origin is, and the walk stops at the first shape that is not. Forced
// inline, as is unbounded_blocks: GCC kept both as calls, and every hard
// shadow ray makes each of them (2% of the instructions on few).
[[gnu::always_inline]] inline bool occluded_by_listed(const Geometry& g, const ListedShapes& listed,
                                                      const Vec3& origin, const Vec3& direction,
                                                      double t_min, double t_max,
                                                      OccluderHint& blocker) {
    // Most cells list nothing: no square root for those.
    if (listed.size() == 0) return false;
    const double reach = light_walk_reach(direction, t_max);
    for (std::size_t k = 0; k < listed.size() && listed.nearest[k] < reach; ++k) {
        if (listed_blocks(g, listed.shapes[k], origin, direction, t_min, t_max)) {
            blocker = hint_for(listed.shapes[k]);
            return true;
        }
    }
    return false;
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

// Whether the hinted surface blocks the ray; false for no hint or a stale one.
bool hinted_blocks(const Geometry& g, const OccluderHint& hint, const Vec3& origin,
                   const Vec3& direction, double t_min, double t_max) {
    switch (hint.set) {
        case OccluderHint::Set::none:
            return false;
        case OccluderHint::Set::plane:
            if (hint.index >= g.planes.size()) return false;
            return intersect_plane(origin, direction, g.planes[hint.index].normal,
                                   g.planes[hint.index].distance, t_min, t_max) != no_hit;
        case OccluderHint::Set::sphere:
            return hint.index < g.spheres.size() &&
                   listed_blocks(g, hint.index, origin, direction, t_min, t_max);
        case OccluderHint::Set::shape:
            return hint.index < g.shapes.size() &&
                   listed_blocks(g, hint.index | shape_flag, origin, direction, t_min, t_max);
    }
    return false;
}

// Planes are few and unbounded, so they are tested before any list or BVH;
// so are the shapes the BVH leaves out (Geometry::beyond_bvh), which no list
// or walk may be relied on to hold.
[[gnu::always_inline]] inline bool unbounded_blocks(const Geometry& geometry, const Vec3& origin,
                                                    const Vec3& direction, double t_min,
                                                    double t_max, OccluderHint& blocker) {
    for (std::uint32_t i = 0; i < geometry.planes.size(); ++i) {
        const WorldPlane& p = geometry.planes[i];
        if (intersect_plane(origin, direction, p.normal, p.distance, t_min, t_max) != no_hit) {
            blocker = {OccluderHint::Set::plane, i};
            return true;
        }
    }
    for (const std::uint32_t listed : geometry.beyond_bvh)
        if (listed_blocks(geometry, listed, origin, direction, t_min, t_max)) {
            blocker = hint_for(listed);
            return true;
        }
    return false;
}

// One ray against the BVH of spheres and shapes; a ray out of Embree's reach
// is moved into it (render/far_ray.hpp) or tested against every shape.
bool occluded_by_bvh(const Geometry& geometry, const ShadowRay& one, OccluderHint& blocker) {
    OcclusionQuery q;
    rtcInitIntersectContext(&q.context);
    q.geometry = &geometry;
    q.rays = &one;
    RTCRay ray;
    const FarRay far =
        fit_embree_ray(geometry.bvh, one.origin, one.direction, one.t_min, one.t_max, ray);
    if (far.fit == FarRay::Fit::misses) return false;
    if (far.fit == FarRay::Fit::out_of_reach)
        return occluded_by_testing_all(geometry, one.origin, one.direction, one.t_min, one.t_max,
                                       blocker);
    rtcOccluded1(geometry.bvh, &q.context, &ray);
    if (!(ray.tfar < 0.0f)) return false;
    blocker = q.blocker;
    return true;
}

// occluded_by_bvh through the shadow BVH of float spheres where it takes the ray.
bool occluded_by_shadow_bvh(const Geometry& geometry, const ShadowRay& one, OccluderHint& blocker) {
    RTCRay ray;
    if (!fit_shadow_ray(geometry.shadow, one.origin, one.direction, one.t_min, one.t_max, ray))
        return occluded_by_bvh(geometry, one, blocker);
    OcclusionQuery q;
    rtcInitIntersectContext(&q.context);
    q.geometry = &geometry;
    q.rays = &one;
    rtcOccluded1(geometry.shadow.bvh, &q.context, &ray);
    if (!(ray.tfar < 0.0f)) return false;
    blocker = q.blocker;
    return true;
}

// A shadow ray whose light's cell lists more shapes than max_cell_candidates,
// or that has no cell: the list still, where the spheres are crowded and it is
// not too long, else a BVH walk.
bool occluded_beyond_cell(const Geometry& geometry, const ListedShapes* candidates,
                          const ShadowRay& one, OccluderHint& blocker) {
    if (geometry.crowded && candidates && candidates->size() <= max_crowded_light_candidates)
        return occluded_by_listed(geometry, *candidates, one.origin, one.direction, one.t_min,
                                  one.t_max, blocker);
    return occluded_by_shadow_bvh(geometry, one, blocker);
}

}  // namespace

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
    *args->bounds_o = padded_sphere_bounds(*g, args->primID);
}

// Flattened: GCC weighs inlining offer_sphere here against all its calls,
// and one more of them made it stop (1% more instructions on few).
[[gnu::flatten]] void sphere_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto& q = *reinterpret_cast<ClosestQuery*>(args->context);
    if (offer_sphere(q, args->primID)) accept(args, q);
}

void sphere_occluded(const RTCOccludedFunctionNArguments* args) {
    const unsigned index = args->primID;
    occlude_lanes(
        args, {OccluderHint::Set::sphere, index}, [index](const Geometry* g, const ShadowRay& r) {
            return sphere_blocks(g->spheres[index], r.origin, r.direction, r.t_min, r.t_max);
        });
}

void sphere_occluded_filter(const RTCFilterFunctionNArguments* args) {
    auto& q = *reinterpret_cast<OcclusionQuery*>(args->context);
    for (unsigned lane = 0; lane < args->N; ++lane) {
        if (!args->valid[lane]) continue;
        const std::uint32_t index = RTCHitN_primID(args->hit, args->N, lane);
        const ShadowRay& r = q.rays[RTCRayN_id(args->ray, args->N, lane)];
        if (sphere_blocks(q.geometry->spheres[index], r.origin, r.direction, r.t_min, r.t_max))
            q.blocker = {OccluderHint::Set::sphere, index};
        else
            args->valid[lane] = 0;
    }
}

void shape_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
    *args->bounds_o = g->shapes[args->primID].bounds;
}

void shape_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto& q = *reinterpret_cast<ClosestQuery*>(args->context);
    if (offer_shape(q, args->primID)) accept(args, q);
}

void shape_occluded(const RTCOccludedFunctionNArguments* args) {
    const unsigned index = args->primID;
    occlude_lanes(args, {OccluderHint::Set::shape, index},
                  [index](const Geometry* g, const ShadowRay& r) {
                      CylinderPart part;
                      return shape_distance(g->shapes[index], r.origin, r.direction, r.t_min,
                                            r.t_max, part) != no_hit;
                  });
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
                                  : candidates->size() <= max_cell_candidates || candidates->covered
                                      ? max_covered_position
                                      : max_cell_candidates;
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

bool shapes_toward_disk(const Geometry& geometry, const Vec3& point, double lift,
                        const Vec3& centre, double radius, DiskCandidates& out) {
    out.count = 0;
    const std::size_t bounded = geometry.spheres.size() + geometry.shapes.size();
    if (bounded > max_disk_candidates) return false;
    const Vec3 axis = centre - point;
    const double axis_sq = glm::dot(axis, axis);
    auto max_abs = [](const Vec3& v) {
        return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    };
    // Far beyond the rounding of the distances below and of the rays' own
    // origins, directions and disk points.
    const double spread =
        radius * (1.0 + 1e-6) + 2.0 * lift + 1e-7 * (max_abs(point) + max_abs(centre) + radius);
    // Sorted by the doubles: shapes whose bounds round to one float keep the
    // order of their bounds.
    std::array<double, max_disk_candidates> exact;
    auto offer = [&](std::uint32_t listed, const Vec3& c, double r) {
        const PaddedBound b = padded_bound(c, r, point);
        const Vec3 f = c - point;
        const double s = axis_sq > 0.0 ? std::clamp(glm::dot(f, axis) / axis_sq, 0.0, 1.0) : 0.0;
        const Vec3 off = f - s * axis;
        const double reach = b.radius + spread;
        if (glm::dot(off, off) > reach * reach) return;
        // Kept nearest first (insertion: a handful of shapes).
        std::size_t k = out.count++;
        const double nearest = std::max(0.0, b.nearest - 2.0 * lift);
        for (; k > 0 && exact[k - 1] > nearest; --k) {
            exact[k] = exact[k - 1];
            out.shapes[k] = out.shapes[k - 1];
        }
        exact[k] = nearest;
        out.shapes[k] = listed;
    };
    for (std::uint32_t i = 0; i < geometry.spheres.size(); ++i)
        offer(i, geometry.spheres[i].center, geometry.spheres[i].radius);
    for (std::uint32_t i = 0; i < geometry.shapes.size(); ++i)
        offer(i | shape_flag, geometry.shapes[i].bounding_center,
              std::sqrt(geometry.shapes[i].bounding_radius_sq));
    for (std::size_t k = 0; k < out.count; ++k) out.nearest[k] = listed_distance(exact[k]);
    return true;
}

bool occluded_among(const Geometry& geometry, const ListedShapes& candidates, const Vec3& origin,
                    const Vec3& direction, double t_min, double t_max, OccluderHint* hint,
                    const Departure& from) {
    if (hint && hinted_blocks(geometry, *hint, origin, direction, t_min, t_max)) return true;
    OccluderHint blocker;
    bool blocked = unbounded_blocks(geometry, origin, direction, t_min, t_max, blocker);
    // A blocker lies nearer the origin than the ray's end.
    const double reach = t_max * glm::length(direction) * (1.0 + 1e-9);
    for (std::size_t k = 0; k < candidates.size() && !blocked && candidates.nearest[k] < reach;
         ++k) {
        if (listed_blocks(geometry, candidates.shapes[k], origin, direction, t_min, t_max)) {
            blocker = hint_for(candidates.shapes[k]);
            blocked = true;
        }
    }
    if (!blocked && geometry.triangles)
        blocked = triangle_blocks(*geometry.triangles, origin, direction, t_min, t_max, from);
    if (blocked && hint) *hint = blocker;
    return blocked;
}

bool occluded(const Geometry& geometry, const Vec3& origin, const Vec3& direction, double t_min,
              double t_max, OccluderHint* hint, const DirectionTable* light,
              const Departure& from) {
    std::optional<ListedShapes> candidates;
    if (light) candidates = shapes_toward(*light, -direction);
    // Testing a short list costs about what testing the hint does: the hint
    // pays only before a long list or a BVH walk.
    const bool short_list = candidates && candidates->size() <= short_candidate_list;
    if (hint && !short_list && hinted_blocks(geometry, *hint, origin, direction, t_min, t_max))
        return true;
    OccluderHint blocker;
    bool blocked = unbounded_blocks(geometry, origin, direction, t_min, t_max, blocker);
    if (!blocked && candidates &&
        (!geometry.bvh || light_walk_within(*candidates, direction, t_max, max_cell_candidates))) {
        blocked =
            occluded_by_listed(geometry, *candidates, origin, direction, t_min, t_max, blocker);
    } else if (!blocked && !geometry.bvh) {
        blocked = occluded_by_testing_all(geometry, origin, direction, t_min, t_max, blocker);
    } else if (!blocked) {
        blocked = occluded_beyond_cell(geometry, candidates ? &*candidates : nullptr,
                                       {origin, direction, t_min, t_max}, blocker);
    }
    if (!blocked && geometry.triangles)
        blocked = triangle_blocks(*geometry.triangles, origin, direction, t_min, t_max, from);
    if (blocked && hint) *hint = blocker;
    return blocked;
}

}  // namespace jt

namespace jt {

void occluded_together(const Geometry& geometry, std::span<const ShadowRay> rays, bool* blocked,
                       OccluderHint* hint, const Departure& from) {
    JT_DCHECK(rays.size() <= shadow_packet, "one packet of rays at most");
    OccluderHint blocker;
    bool any = false;
    bool all = true;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const ShadowRay& r = rays[i];
        blocked[i] =
            hint && hinted_blocks(geometry, *hint, r.origin, r.direction, r.t_min, r.t_max);
        if (!blocked[i] &&
            unbounded_blocks(geometry, r.origin, r.direction, r.t_min, r.t_max, blocker))
            any = blocked[i] = true;
        all = all && blocked[i];
    }
    if (!all && !geometry.bvh) {
        for (std::size_t i = 0; i < rays.size(); ++i)
            if (!blocked[i] && occluded_by_testing_all(geometry, rays[i].origin, rays[i].direction,
                                                       rays[i].t_min, rays[i].t_max, blocker))
                any = blocked[i] = true;
    } else if (!all) {
        // A ray out of Embree's reach is answered on its own, and its lane in
        // the packet holds a ray Embree takes.
        std::array<bool, shadow_packet> far{};
        for (std::size_t i = 0; i < rays.size(); ++i) {
            far[i] = !embree_takes(rays[i].origin, rays[i].direction);
            if (far[i] && !blocked[i] && occluded_by_bvh(geometry, rays[i], blocker))
                any = blocked[i] = true;
        }
        OcclusionQuery q;
        rtcInitIntersectContext(&q.context);
        q.context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        q.geometry = &geometry;
        q.rays = rays.data();
        RTCRay16 packet;
        // Embree loads the mask and the packet as whole vectors: aligned as they are.
        alignas(64) std::array<int, shadow_packet> valid{};
        // Idle lanes hold a copy of the first ray, so that no lane is garbage.
        const ShadowRay idle{Vec3(0.0), Vec3(0.0, 0.0, 1.0), 0.0, 0.0};
        for (unsigned lane = 0; lane < shadow_packet; ++lane) {
            const std::size_t i = std::min<std::size_t>(lane, rays.size() - 1);
            set_float_lane(packet, lane, far[i] ? idle : rays[i]);
        }
        for (unsigned lane = 0; lane < rays.size(); ++lane)
            valid[lane] = blocked[lane] || far[lane] ? 0 : -1;
        if (std::find(valid.begin(), valid.end(), -1) != valid.end())
            rtcOccluded16(valid.data(), geometry.bvh, &q.context, &packet);
        for (unsigned lane = 0; lane < rays.size(); ++lane)
            if (valid[lane] && packet.tfar[lane] < 0.0f) {
                any = blocked[lane] = true;
                blocker = q.blocker;
            }
    }
    if (geometry.triangles)
        for (std::size_t i = 0; i < rays.size(); ++i)
            if (!blocked[i])
                blocked[i] = triangle_blocks(*geometry.triangles, rays[i].origin, rays[i].direction,
                                             rays[i].t_min, rays[i].t_max, from);
    if (any && hint) *hint = blocker;
}

}  // namespace jt
