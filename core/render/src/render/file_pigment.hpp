#pragma once
// The pigment of a mesh read with `materials: "file"` (docs/language.md
// §14.5): texel x vertex colour x base colour of the triangle's part, the
// absent ones left out.

#include "render/triangle_geometry.hpp"

#include <glm/vec2.hpp>

#include <optional>

namespace jt {

// The pigment at a hit on triangle `id` with barycentric weights
// (u, v) = `barycentric` and texture coordinates `uv`, or nullopt when the
// block's material applies unchanged: a loose triangle, a mesh without
// "file", or a triangle whose part has no material and no vertex colours.
std::optional<Colour> file_pigment(const TriangleGeometry& g, TriangleId id, glm::dvec2 barycentric,
                                   glm::dvec2 uv);

}  // namespace jt
