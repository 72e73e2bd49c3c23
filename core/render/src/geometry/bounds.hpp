#pragma once
// Axis-aligned bounds for the BVH, padded so that Embree's single-precision
// traversal never culls a box that the exact double-precision ray would enter.

#include "jtracer/affine.hpp"
#include "jtracer/scene.hpp"

#include <embree3/rtcore.h>

namespace jt {

struct Box {
    Vec3 lower{0.0};
    Vec3 upper{0.0};
};

Box sphere_box(const Vec3& center, double radius);
// A sphere (center, radius) seen through `to_world`: an ellipsoid.
Box transformed_sphere_box(const Vec3& center, double radius, const Affine& to_world);
Box transformed_cylinder_box(double radius, double height, const Affine& to_world);

// Grows `box` by a margin relative to its own size and position, plus `slack`
// (world units), and rounds it outward to floats.
RTCBounds padded_float_bounds(const Box& box, double slack);

}  // namespace jt
