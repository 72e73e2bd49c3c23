#pragma once
// The tests of one transformed shape that the closest-hit and the shadow
// queries share (closest_hit.cpp, occlusion.cpp): a cheap rejection by its
// bounding sphere, then the exact test in its object space.

#include "geometry/intersect.hpp"
#include "render/prepared_scene.hpp"

#include <glm/geometric.hpp>

namespace jt {

// The distance along the ray to transformed shape `s` within (t_min, t_max),
// or no_hit; on a cylinder, `part` says which surface was met.
inline double shape_distance(const TransformedShape& s, const Vec3& origin, const Vec3& direction,
                             double t_min, double t_max, CylinderPart& part) {
    Vec3 o = apply_point(s.to_object, origin);
    Vec3 d = apply_vector(s.to_object, direction);
    if (s.kind == TransformedShape::Kind::sphere)
        return intersect_sphere(o, d, s.center, s.radius, t_min, t_max);
    return intersect_cylinder(o, d, s.radius, s.height, t_min, t_max, part);
}

// Whether the line through the ray misses the shape's bounding sphere (the
// direction need not be unit length).
inline bool misses_bounds(const TransformedShape& s, const Vec3& origin, const Vec3& direction) {
    Vec3 f = origin - s.bounding_center;
    Vec3 perpendicular = f - (glm::dot(f, direction) / glm::dot(direction, direction)) * direction;
    return glm::dot(perpendicular, perpendicular) > s.bounding_radius_sq;
}

}  // namespace jt
