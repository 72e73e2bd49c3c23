#pragma once
// Affine maps of points and normals, built from a primitive's transform ops.

#include "jtracer/scene.hpp"

#include <glm/mat3x3.hpp>

#include <optional>
#include <vector>

namespace jt {

// p -> linear * p + translation.
struct Affine {
    glm::dmat3 linear{1.0};
    Vec3 translation{0.0};
};

inline Vec3 apply_point(const Affine& a, const Vec3& p) {
    return a.linear * p + a.translation;
}
inline Vec3 apply_vector(const Affine& a, const Vec3& v) {
    return a.linear * v;
}

// The map of one operation: a positive rotation turns +x toward +y (zrotate),
// +y toward +z (xrotate), +z toward +x (yrotate): the right-hand rule.
Affine affine_of(const TransformOp& op);

// first op applied first: M = last * ... * first.
Affine compose_transforms(const std::vector<TransformOp>& ops);

// a then b: the map p -> b(a(p)).
Affine then(const Affine& a, const Affine& b);

// Everything needed to intersect through a transform: the inverse for rays,
// the inverse transpose for normals.
struct AffineInverse {
    Affine inverse;
    glm::dmat3 normal_matrix{1.0};
};

// Nothing when the map is degenerate: a zero determinant (a zero scale flattens
// the primitive to nothing) or any non-finite entry.
std::optional<AffineInverse> invert(const Affine& a);

// When the linear part is a rotation times a uniform scale, that scale: a sphere
// stays a sphere under such a map. Nothing otherwise.
std::optional<double> similarity_scale(const glm::dmat3& linear);

}  // namespace jt
