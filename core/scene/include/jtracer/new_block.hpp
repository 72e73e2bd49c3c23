#pragma once
// The blocks an editor adds to a scene: primitives and lights with sensible
// values, placed where the active camera sees them, and new cameras. Sizes
// follow the camera's view, so a new sphere looks the same in a scene a few
// units across and in one of hundreds; numbers are rounded to three
// significant digits of that scale, so the text stays short.

#include "jtracer/model_file.hpp"
#include "jtracer/scene.hpp"

#include <array>
#include <string_view>

namespace jt {

// The shapes new_primitive makes; a mesh needs its file (new_mesh).
enum class ShapeKind { sphere, plane, cylinder, triangle };
inline constexpr std::array<ShapeKind, 4> kShapeKinds{ShapeKind::sphere, ShapeKind::plane,
                                                      ShapeKind::cylinder, ShapeKind::triangle};

// "sphere", "plane", "cylinder", "triangle": the keyword of the kind (schema.hpp).
std::string_view keyword_of(ShapeKind kind);

// A light grey, softly lit, slightly shiny material (the default one is black).
Material new_material();

// A primitive of that kind with new_material(), in front of the active camera
// halfway to its look_at point: a sphere and a standing cylinder a fifth of
// the view's height there across, a plane facing the camera's `up` as written
// (level even when the camera looks down) at the height of the view's floor
// and under the scene's objects (floor_height in new_block.cpp), and a
// triangle as wide as that sphere standing upright and facing the camera
// (counter-clockwise seen from it).
Primitive new_primitive(ShapeKind kind, const Scene& scene);

// A mesh of `file` (a name as the scene's `file` holds it) where new_primitive
// puts a sphere, `model` (what the file holds) scaled uniformly so that its
// largest extent is that sphere's diameter and its bounding box centred there.
Primitive new_mesh(const Scene& scene, const std::string& file, const Model& model);

// A white light of intensity 0.7 above the active camera.
PointLight new_light(const Scene& scene);

// A copy of the active camera (or a default one) with a name no camera has.
Camera new_camera(const Scene& scene);

// A scene to start from, valid as it is: a 640x360 image, a camera "main" whose
// aspect matches it looking at a point a unit above the origin, a white light
// above and beside the camera, and nothing else, so that new_primitive puts
// the first objects where the camera sees them.
Scene new_scene();

}  // namespace jt
