#pragma once
// Affine maps of points and normals, built from a primitive's transform ops.

#include "jtracer/scene.hpp"

#include <glm/mat3x3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <variant>
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

// A primitive's transform list as the renderer traces it.
struct ObjectTransform {
    Affine to_world;                // object space -> world space
    Affine to_object;               // world space -> object space, for rays
    glm::dmat3 normal_matrix{1.0};  // the inverse transpose of to_world.linear, for normals
    // det(to_world.linear) < 0: the map turns space inside out (an odd number
    // of negative scale components), so a winding seen in world space is
    // reversed. Counted from the ops, exact however large or small the map.
    bool mirrors = false;
};

// Why a transform list leaves its primitive out of the render.
struct LeftOut {
    enum class Reason : std::uint8_t {
        zero_scale,    // a `scale` with a zero component flattens the primitive to nothing
        out_of_range,  // composing the ops leaves the range of doubles (about 1e308)
    };
    Reason reason = Reason::zero_scale;
    std::size_t op = 0;  // index into the list of the op that decides it
};

// Whether this op is a `scale` with a zero component.
bool flattens(const TransformOp& op);

// The one rule for transform lists (docs/language.md §5.5), used by the renderer, the
// validator's warning and every tool that must agree with them:
// - a list containing a `scale` with a zero component leaves the primitive out,
//   whatever comes before or after it (the first such op is the one reported);
// - otherwise a list whose map or inverse has an entry that is not a finite
//   double leaves it out too (the op at which that first happens is reported);
// - otherwise the maps. The inverse is composed from each op's own inverse
//   (1/s, -t, the transposed rotation), never from a determinant, so that its
//   accuracy does not depend on how flat or stretched the map is.
std::variant<ObjectTransform, LeftOut> object_transform(const std::vector<TransformOp>& ops);

// v / |v|, also when squaring the components of v would underflow or overflow;
// nothing when v is zero or not finite. A plane's normal and the image of a
// normal under a transform are made unit length here.
std::optional<Vec3> unit_length(const Vec3& v);

// When the linear part is a rotation times a uniform scale, that scale: a sphere
// stays a sphere under such a map. Nothing otherwise.
std::optional<double> similarity_scale(const glm::dmat3& linear);

}  // namespace jt
