#pragma once
// Closest-hit and any-hit queries against a Geometry, exact in double precision.
// Embree only culls: it walks the BVH with a float copy of the ray, and our
// callbacks decide every hit with the double ray, keeping the result in the
// query (Embree's float tfar is only ever a conservative upper bound).
// closest_hit.cpp holds the closest-hit query, occlusion.cpp the shadow ones.

#include "render/prepared_scene.hpp"
#include "render/triangle_queries.hpp"

#include <embree3/rtcore.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace jt {

// closest_hit sets every field when it finds a hit: a Hit is made for every
// ray, and zeroing it first showed in profiles.
struct Hit {
    double t;
    Vec3 normal;  // outward geometric normal, world space, not unit length
    std::uint32_t source;
    // A triangle's: which one, its smooth shading normal (world space, not unit
    // length; zero for none) and its texture coordinates (zero for none).
    TriangleId triangle;
    Vec3 shading;
    glm::dvec2 uv;
    glm::dvec2 barycentric;  // a triangle's weights of its second and third corner
};

// Nearest surface along origin + t * direction with t in (t_min, infinity).
// Equal distances resolve to the lower primitive index, so that the answer
// never depends on BVH traversal order.
// With `candidates`, every shape the ray may meet first (a list of a view
// or direction table), tests those instead of walking the BVH when they are
// few. `from`: the triangle a secondary ray leaves, met as closest_triangle says.
bool closest_hit(const Geometry& geometry, const Vec3& origin, const Vec3& direction, double t_min,
                 Hit& hit, const ListedShapes* candidates = nullptr, const Departure& from = {});

// The surface that blocked a previous shadow ray: shadow rays toward one light
// from neighbouring points are mostly blocked by the same surface, and testing
// it first skips the BVH walk. Only a guess: a stale or wrong one costs one
// test and never changes an answer.
struct OccluderHint {
    enum class Set : std::uint8_t { none, plane, sphere, shape };
    Set set = Set::none;
    std::uint32_t index = 0;
};

// Whether any surface lies at some t in (t_min, t_max). With a hint, tries the
// hinted surface first and leaves the hint on the surface that blocked the ray.
// With `light`, the table of the light the ray runs to (t_max its distance),
// tests the shapes of the ray's cell instead of walking the BVH when they are
// few: the answer is the same.
bool occluded(const Geometry& geometry, const Vec3& origin, const Vec3& direction, double t_min,
              double t_max, OccluderHint* hint = nullptr, const DirectionTable* light = nullptr,
              const Departure& from = {});

// A shadow ray whose walk of its light's list would test more shapes than
// this is left to the BVH. A light's list is sorted nearest the light first,
// and the walk ends at the ray's origin, so a long list often serves rays
// that walk only its head; even past a few dozen shapes, a walk that ends on
// the first blocker beats Embree's walk with a callback per box it enters
// (docs/benchmarks.md §2.5: 128 against 16 took 2-3% off lattice and
// sphereflake, 1% off tree and spheres_5761).
inline constexpr std::size_t max_light_walk = 128;

// A shadow ray: any surface at some t in (t_min, t_max) blocks it.
struct ShadowRay {
    Vec3 origin, direction;
    double t_min, t_max;
};

// occluded() of each of up to shadow_packet rays, blocked[i] for rays[i],
// the same answers; their BVH walks go as one packet. For the rays of a soft
// light from one hit, which leave one point for one small disk.
inline constexpr std::size_t shadow_packet = 16;
void occluded_together(const Geometry& geometry, std::span<const ShadowRay> rays, bool* blocked,
                       OccluderHint* hint = nullptr, const Departure& from = {});

// The shapes that may lie across a shadow ray of a soft light from one hit
// (docs/language.md §14.1). The rays leave points within `lift` of `point` for
// points of the light's disk of `radius` about `centre`, so every point of
// every ray lies within radius + lift of the segment from `point` to `centre`:
// a shape whose bounding sphere stays farther from that segment meets none.
// Found once for the hit's M rays, they are listed nearest `point` first, as a
// list around the rays' origins (ListedShapes) that closest_hit and
// occluded_among walk instead of every shape or the BVH.
inline constexpr std::size_t max_disk_candidates = 64;
struct DiskCandidates {
    std::array<std::uint32_t, max_disk_candidates> shapes;
    std::array<ListedDistance, max_disk_candidates> nearest;
    std::size_t count = 0;
    ListedShapes listed() const { return {{shapes.data(), count}, {nearest.data(), count}}; }
};

// False, leaving `out` unusable, for a geometry of more than max_disk_candidates
// bounded shapes: testing each of those against the disk costs more than the
// BVH walks it would spare.
bool shapes_toward_disk(const Geometry& geometry, const Vec3& point, double lift,
                        const Vec3& centre, double radius, DiskCandidates& out);

// occluded() with the spheres and shapes limited to `candidates`, a list
// around the ray's origin holding every shape that may lie across the ray
// (planes and triangles are all tested): the same answer.
bool occluded_among(const Geometry& geometry, const ListedShapes& candidates, const Vec3& origin,
                    const Vec3& direction, double t_min, double t_max, OccluderHint* hint,
                    const Departure& from);

// Embree callbacks for the two user geometries (their boxes:
// render/user_geometry.hpp); prepare_scene registers them.
void sphere_intersect(const RTCIntersectFunctionNArguments* args);
void sphere_occluded(const RTCOccludedFunctionNArguments* args);
void shape_intersect(const RTCIntersectFunctionNArguments* args);
void shape_occluded(const RTCOccludedFunctionNArguments* args);

// The occlusion filter of the shadow BVH's float spheres (render/shadow_spheres.hpp):
// keeps a float hit only where the sphere blocks the double ray.
void sphere_occluded_filter(const RTCFilterFunctionNArguments* args);

}  // namespace jt
