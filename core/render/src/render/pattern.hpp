#pragma once
// Patterns: the pigment a material shows at a point (docs/language.md §13.3).

#include "jtracer/scene.hpp"

namespace jt {

// Whether the material's pigment depends on where it is hit.
bool has_pattern(const Material& m);

// The pigment at `object_point`, a point in the primitive's object space
// (before its transform): the checker's colour on odd cubes, else `pigment`.
Colour pattern_pigment(const Material& m, const Vec3& object_point);

}  // namespace jt
