#pragma once
// Shadow-ray candidates by direction, one table a point light (the "light
// buffer" of Haines and Greenberg, 1986).
//
// A shape can block a shadow ray toward a light only if, seen from the light,
// it lies in the ray's direction. So the directions around each light are cut
// into the cells of a cube map, and each cell lists the shapes whose (padded)
// bounding sphere overlaps its cone. A shadow ray then tests the few shapes of
// its cell, exactly as the BVH callbacks would, instead of walking the BVH: on
// the benchmark scenes shadow rays were 40-65% of the render time, mostly in
// Embree's per-ray set-up and traversal. The lists are conservative, so the
// answers are the same bits as without them; a cell with many candidates
// says so and the BVH answers instead.

#include "jtracer/scene.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace jt {

struct Geometry;

// A candidate is an index into Geometry::spheres, or into Geometry::shapes
// with `shape_flag` set.
inline constexpr std::uint32_t shape_flag = 0x80000000u;

struct LightBuffer {
    int resolution = 0;                     // cells along a cube face's edge; 0: no table
    std::vector<std::uint32_t> cell_start;  // 6 * resolution^2 + 1 offsets into `candidates`
    std::vector<std::uint32_t> candidates;
};

// The table for a light at `position`, or an empty one (resolution 0) when the
// geometry has too many shapes for a table to pay for its building.
LightBuffer build_light_buffer(const Geometry& geometry, const Vec3& position);

// The shapes that may block a ray leaving the light in `direction` (any
// length): every shape that may block it is among them. Nothing when the
// buffer has no table or the direction is zero or not finite.
std::optional<std::span<const std::uint32_t>> candidates_toward(const LightBuffer& buffer,
                                                                const Vec3& direction);

// One table a light, parallel to PreparedScene::lights; empty when no table
// pays (see build_light_buffer).
std::vector<LightBuffer> build_light_buffers(const Geometry& geometry,
                                             const std::vector<PointLight>& lights);

}  // namespace jt
