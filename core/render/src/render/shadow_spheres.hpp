#pragma once
// A second BVH for hard shadow rays: the plain spheres as Embree's native
// float spheres (RTC_GEOMETRY_TYPE_SPHERE_POINT, tested several at a time in
// Embree's leaves), the other shapes as the user geometry of the main BVH.
// A float sphere only culls: each of its hits goes to an occlusion filter that
// decides the sphere exactly, in double precision, on the ray as it is. So
// the float spheres must meet the float ray wherever the exact sphere meets
// the double ray, and they are padded for that:
//
// - Every coordinate of the spheres lies within the scene's magnitude m
//   (prepare_scene's scene_magnitude), and the float path takes rays whose
//   origin lies within reach = 2m (others walk the main BVH). The float
//   centres, origins and directions are each within 2^-24 of their own size
//   of the double ones, so where the double ray crosses a sphere (within
//   about 2 * reach of its origin) the float ray passes within about
//   2^-24 * 4 * reach of it.
// - Embree's test (sphere_intersector.h) takes the distance from the centre
//   to the ray's line through rcp(dot(dir, dir)), an estimate refined once
//   (relative error under 2^-21 on every ISA), a dot product and a difference,
//   with |centre - origin| under 2 * reach: its error in that distance is
//   under 2^-19 * reach, and with the above under 2^-18 * reach.
// - Each float radius is r + pad, pad = 2^-10 * reach, rounded up: where the
//   exact sphere has a crossing point, the float ray's line passes nearer the
//   centre than the padded radius by pad less that error, so Embree's
//   `l2 <= r2` holds, and the padded sphere's entry lies at least that much
//   before the crossing and its exit at least that much after it.
// - Embree then counts a hit only when its entry or exit distance lies within
//   (tnear, tfar) = (0, tfar). Its square root magnifies the rounding of
//   r2 - l2, to at most 2^-18 * reach * sqrt(radius / pad), under
//   2^-13 * reach: 8 times less than pad. So an entry after the origin is
//   seen after it; an entry before it leaves the exit seen after it. The
//   float ray ends `tail` = 2 * (the largest padded radius + pad) past t_max,
//   so that an exit past the end of a ray that lies wholly inside a padded
//   sphere is still within its range.
//
// The filter tests the sphere whatever Embree's distances say; they only
// decide which spheres reach it. tests/render/shadow_spheres_test.cpp checks
// the answers against the exact ones on grazing rays, and that unpadded float
// spheres lose some.

#include "render/prepared_scene.hpp"

#include <embree3/rtcore.h>

#include <vector>

namespace jt {

// As above: the reach in multiples of the scene's magnitude, the pad of the reach.
inline constexpr double shadow_reach_factor = 2.0;
inline constexpr double shadow_pad_factor = 0x1p-10;

// The measure of crowding that the shadow BVH and the longer walks of the
// lights' cells (occlusion.cpp) pay on: the spheres' volumes summed over
// the volume of their bounding box, above min_overlap. It is 8 on
// nested_shells and under 0.2 on the other race scenes; above 1 the spheres
// must overlap. Where they hardly overlap, the main BVH's single tight boxes
// cull as well as the float spheres, whose leaves of several spheres cost
// more, and a long cell list costs more than its BVH walk (docs/benchmarks.md
// §2.7 has the figures).
inline constexpr double min_overlap = 1.0;
bool spheres_overlap_heavily(const std::vector<WorldSphere>& spheres);

// Builds geometry.shadow (its BVH and the distances above) from the
// geometry's spheres and shapes; nothing when it has no plain spheres.
// Another `pad_factor` is for the test that shows the pad is needed.
void build_shadow_spheres(Geometry& geometry, double magnitude, RTCBuildQuality quality,
                          double pad_factor = shadow_pad_factor);

// Sets `ray` to the float ray the shadow BVH walks for the double ray from
// `origin` along `direction` over [t_min, t_max]; false when the shadow BVH
// does not take the ray (no such BVH, an origin beyond the reach, a negative
// t_min, a direction far from unit length or anything not finite).
bool fit_shadow_ray(const ShadowSpheres& shadow, const Vec3& origin, const Vec3& direction,
                    double t_min, double t_max, RTCRay& ray);

}  // namespace jt
