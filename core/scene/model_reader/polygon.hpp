#pragma once
// The triangles of one polygon face of a model file (an OBJ's `f` line of
// four or more corners, an OFF or PLY face). A fan from the first corner
// covers a convex polygon exactly, and is what a convex one gets; a concave
// one (an L-shaped floor, a letter, a ring joined to its hole by a seam, as
// 3D tools export n-gons) would be covered past its edges by a fan, so its
// ears are cut off one by one instead, in the plane it lies in.

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace jt {

// Polygons of more corners than this are fanned as they come: cutting ears
// costs time in the square of the corners, and a hostile file can hold one
// face of millions.
inline constexpr std::size_t kMaxEarClippedCorners = 4096;

// Cutting ears tests corners against ears; a whole model file may spend this
// many tests (under a second) before the rest of its polygons
// are fanned, so that a hostile file of many large concave faces cannot stall
// the read.
inline constexpr std::uint64_t kEarClippingBudget = 100'000'000;

// Triangles as positions in `corners` (0 .. size - 1), each wound as the
// polygon is. A polygon with no area, or the part of one that has no ear (it
// crosses itself), gets the fan. `budget` is what the model has left to spend.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const glm::dvec3> corners,
                                                              std::uint64_t& budget);

}  // namespace jt
