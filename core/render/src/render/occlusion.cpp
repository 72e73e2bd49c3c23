// The shadow-ray queries of render/ray_queries.hpp: whether anything lies
// across a ray, one ray or a packet at a time, by a light's list, a soft
// light's candidates, every shape or a BVH walk; and the BVH's callbacks for
// them.

#include "geometry/intersect.hpp"
#include "jtracer/check.hpp"
#include "render/far_ray.hpp"
#include "render/float_ray.hpp"
#include "render/ray_queries.hpp"
#include "render/shadow_spheres.hpp"
#include "render/shape_tests.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

namespace jt {

namespace {

// Where the spheres overlap heavily (Geometry::crowded), testing a light's
// cell list beats the BVH walk, even the shadow BVH's, up to about this many
// (docs/benchmarks.md §2.7).
constexpr std::size_t max_crowded_light_candidates = 256;
constexpr std::size_t short_candidate_list = 2;

// One ray, or a packet whose lanes name their ray by their id: Embree may
// hand a packet's lanes to the callbacks one by one, in copies. It starts
// with the context that Embree hands the callbacks, so that they find it.
struct OcclusionQuery {
    RTCIntersectContext context;
    const Geometry* geometry;
    const ShadowRay* rays;
    OccluderHint blocker;  // what blocked a ray, once something did
};

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

// A shadow ray whose walk of its light's list would test more than
// max_light_walk shapes, or that has no list: the list still, where the
// spheres are crowded and it is not too long, else a BVH walk.
bool occluded_beyond_cell(const Geometry& geometry, const ListedShapes* candidates,
                          const ShadowRay& one, OccluderHint& blocker) {
    if (geometry.crowded && candidates && candidates->size() <= max_crowded_light_candidates)
        return occluded_by_listed(geometry, *candidates, one.origin, one.direction, one.t_min,
                                  one.t_max, blocker);
    return occluded_by_shadow_bvh(geometry, one, blocker);
}

}  // namespace

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

void shape_occluded(const RTCOccludedFunctionNArguments* args) {
    const unsigned index = args->primID;
    occlude_lanes(args, {OccluderHint::Set::shape, index},
                  [index](const Geometry* g, const ShadowRay& r) {
                      CylinderPart part;
                      return shape_distance(g->shapes[index], r.origin, r.direction, r.t_min,
                                            r.t_max, part) != no_hit;
                  });
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
        (!geometry.bvh || light_walk_within(*candidates, direction, t_max, max_light_walk))) {
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
