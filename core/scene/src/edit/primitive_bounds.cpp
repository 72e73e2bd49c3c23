#include "jtracer/primitive_bounds.hpp"

#include "jtracer/affine.hpp"

#include <variant>
#include <vector>

namespace jt {

namespace {

// The points whose box holds the shape, in object space.
std::vector<Vec3> extent_points(const Shape& shape) {
    if (const auto* s = shape_if<Sphere>(&shape)) {
        const Vec3 r(s->radius);
        return {s->center - r, s->center + r};
    }
    if (const auto* c = shape_if<Cylinder>(&shape))
        return {Vec3(-c->radius, 0.0, -c->radius), Vec3(c->radius, c->height, c->radius)};
    if (const auto* t = shape_if<Triangle>(&shape)) return {t->a, t->b, t->c};
    return {};
}

}  // namespace

std::optional<Bounds> primitive_bounds(const Primitive& primitive) {
    const std::vector<Vec3> points = extent_points(primitive.shape);
    if (points.empty()) return std::nullopt;
    Vec3 lower = points[0], upper = points[0];
    for (const Vec3& p : points) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    const Affine to_world = compose_transforms(primitive.transforms);
    Bounds box{Vec3(0.0), Vec3(0.0)};
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                     (corner & 4) ? upper.z : lower.z);
        const Vec3 w = apply_point(to_world, p);
        box.lower = corner == 0 ? w : glm::min(box.lower, w);
        box.upper = corner == 0 ? w : glm::max(box.upper, w);
    }
    if (!all_finite(box.lower) || !all_finite(box.upper)) return std::nullopt;
    return box;
}

}  // namespace jt
