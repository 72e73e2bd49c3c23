#pragma once
// Normals for the corners a model file gives none (docs/language.md §14.4):
// with `smooth_angle`, each such corner of a triangle T takes the area-weighted
// normal of the triangles that meet at its position and face within the angle
// of T. The model's own normals (model_file.hpp) stay where it has them.
//
//   if (corners_without_normals(model) > 0)
//       Expected<CornerNormals> n = smooth_corner_normals(model, 60.0);

#include "jtracer/error.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/scene.hpp"

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace jt {

// How many corners of the model's triangles have no normal in the file (a
// corner counts once for each triangle that names it).
std::size_t corners_without_normals(const Model& model);

// One normal for each corner of each triangle of the model, in its object
// space (parallel to Model::triangles): the file's where it gives one, as
// stored, else the generated unit normal.
using CornerNormals = std::vector<std::array<Vec3, 3>>;

// The corner normals with `smooth_angle` `degrees` (0..180). The triangles
// around one position are compared pairwise, so a model whose triangles of
// many different normals meet at one point could take quadratic time; one
// that needs more comparisons than smooth_normal_comparisons(model) allows is
// an error saying where, not a hang.
Expected<CornerNormals> smooth_corner_normals(const Model& model, double degrees);
std::size_t smooth_normal_comparisons(const Model& model);

// The same, from memory when this model (shared_model's copy) and angle were
// asked for lately: the validator makes them, to report a model past the
// bound where the angle is written, and the render that follows takes them.
Expected<std::shared_ptr<const CornerNormals>> shared_corner_normals(
    const std::shared_ptr<const Model>& model, double degrees);

}  // namespace jt
