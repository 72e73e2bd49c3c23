#pragma once
// Whitted shading of one ray (docs/language.md §8).

#include "render/pixel_hash.hpp"
#include "render/prepared_scene.hpp"

#include <cstdint>

namespace jt {

// The colour seen along origin + t * unit_direction, t > t_min, unclamped.
// `sample`: the pixel sample the ray is traced for, which turns the points of
// soft lights (docs/language.md §14.1). Adds the rays it traces (this one,
// shadow and reflection rays) to `rays`.
// `first_candidates`, when given, lists every shape the ray may meet first
// (closest_hit's `candidates`).
Colour trace_ray(const PreparedScene& scene, const Vec3& origin, const Vec3& unit_direction,
                 double t_min, const PixelSample& sample, std::uint64_t& rays,
                 const ListedShapes* first_candidates = nullptr);

// How far to lift a secondary ray's origin off the surface at `point`, reached
// from `origin` after `distance`: well above the rounding error of the hit
// point (about 1e-16 of these magnitudes), far below any feature of the scene.
double surface_offset(const Vec3& origin, const Vec3& point, double distance);

}  // namespace jt
