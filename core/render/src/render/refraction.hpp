#pragma once
// Whitted's transmitted ray (docs/language.md §13.2).

#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace jt {

// The unit direction of the ray transmitted at a surface of index `ior`, for
// the unit ray direction `d` and the unit normal `n` facing the ray; `entering`
// when the ray arrives from outside. Past the critical angle (total internal
// reflection), the mirror direction. The outside is always vacuum: no nesting.
inline Vec3 transmitted_direction(const Vec3& d, const Vec3& n, bool entering, double ior) {
    const double eta = entering ? 1.0 / ior : ior;
    const double cos_i = -glm::dot(d, n);
    const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    const Vec3 t = k < 0.0 ? d + 2.0 * cos_i * n : eta * d + (eta * cos_i - std::sqrt(k)) * n;
    return glm::normalize(t);
}

}  // namespace jt
