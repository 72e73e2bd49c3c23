#pragma once
// A box around a primitive in world space, from its shape's extent and its
// transforms: where an editor puts a floor under the objects and what it
// frames when it shows the selection. Loose (the box of the transformed box),
// never too small.

#include "jtracer/scene.hpp"

#include <optional>

namespace jt {

struct Bounds {
    Vec3 lower{0.0}, upper{0.0};
    Vec3 centre() const { return (lower + upper) * 0.5; }
};

// Nothing for a plane (unbounded), a mesh (its extent is in its file) and a
// primitive whose transforms or numbers leave the range of doubles.
std::optional<Bounds> primitive_bounds(const Primitive& primitive);

}  // namespace jt
