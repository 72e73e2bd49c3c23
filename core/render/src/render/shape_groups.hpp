#pragma once
// The bounded shapes of a small scene in groups of four, for the closest-hit
// queries that have no list of a table (mirror rays, mostly): in a scene of a
// few dozen shapes, Embree's walk of its BVH, with a callback for each shape
// whose box the ray crosses, costs some 300 instructions a ray, and most
// mirror rays meet nothing. Here a ray is tested against four groups' spheres
// at a time in vector lanes (render/sphere_batch.hpp), then against the four
// members of each group it may meet, and only the members not decided there
// get the exact test.
//
// Why a group's sphere never drops a hit. Lane k of a group is a sphere
// itself, or a transformed shape's bounding sphere (which holds the shape with
// a margin of 1e-6 of the scene's size, prepare_geometry.cpp). The group's
// sphere holds every lane's with `pad` to spare: its radius is the largest
// |centre_g - centre_k| + r_k, rounded up, plus pad = group_pad * m, m the
// largest coordinate any lane reaches. The groups take rays whose origin lies
// within `reach` = group_reach * m, so |f| = |origin - centre| < 9 m, and the
// early answers of intersect_sphere for the group's sphere (starting outside
// and heading away, passes_wide_of_sphere) err in |f|^2 by under 64 u |f|^2 <
// 6e-13 m^2 (u = 2^-53). An answer of either means the true ray stays
// farther from the group's centre than its radius R less 6e-13 m^2 / R <=
// 6e-9 m (R >= pad), so from each lane's centre farther than r_k + pad -
// 6e-9 m: its squared distance exceeds r_k^2 + 9.9e-9 m^2. The exact sphere
// test finds a root only within 38 u |f|^2 < 3.5e-13 m^2 of r_k^2
// (intersect.hpp), and a shape's exact test only inside its bounding sphere:
// neither can meet such a ray.
//
// A sphere lane of a group the ray may meet is then decided by
// intersect_sphere's own early answers (the entry beyond the best hit
// included), on the same operands as the scalar test (sphere_batch.hpp); a
// shape lane is offered as a list walk offers it, its bounding sphere first.

#include "render/prepared_scene.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace jt {

// A scene of more bounded shapes leaves its rays to the BVH: the groups are
// tested one after another, however far the ray passes from them.
inline constexpr std::size_t max_grouped_shapes = 64;
// The groups' padding and the origins they take, in multiples of the largest
// coordinate any shape reaches (see above).
inline constexpr double group_pad = 1e-4;
inline constexpr double group_reach = 4.0;

// Empty for more than max_grouped_shapes bounded shapes, for none, or where a
// sphere or bound is not finite.
ShapeGroups group_shapes(const std::vector<WorldSphere>& spheres,
                         const std::vector<TransformedShape>& shapes);

}  // namespace jt
