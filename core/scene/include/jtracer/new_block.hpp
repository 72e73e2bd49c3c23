#pragma once
// The blocks an editor adds to a scene: primitives and lights with sensible
// values, placed where the active camera sees them, and new cameras. Sizes
// follow the camera's view, so a new sphere looks the same in a scene a few
// units across and in one of hundreds; numbers are rounded to three
// significant digits of that scale, so the text stays short.

#include "jtracer/scene.hpp"

#include <array>
#include <string_view>

namespace jt {

enum class ShapeKind { sphere, plane, cylinder };
inline constexpr std::array<ShapeKind, 3> kShapeKinds{ShapeKind::sphere, ShapeKind::plane,
                                                      ShapeKind::cylinder};

// "sphere", "plane", "cylinder": the keyword of the kind (schema.hpp).
std::string_view keyword_of(ShapeKind kind);

// A light grey, softly lit, slightly shiny material (the default one is black).
Material new_material();

// A primitive of that kind with new_material(), in front of the active camera
// halfway to its look_at point: a sphere and a standing cylinder a fifth of
// the view's height there across, a plane below that point facing the
// camera's up.
Primitive new_primitive(ShapeKind kind, const Scene& scene);

// A white light of intensity 0.7 above the active camera.
PointLight new_light(const Scene& scene);

// A copy of the active camera (or a default one) with a name no camera has.
Camera new_camera(const Scene& scene);

}  // namespace jt
