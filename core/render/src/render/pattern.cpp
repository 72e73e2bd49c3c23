#include "render/pattern.hpp"

#include <cmath>

namespace jt {

namespace {

// Lifts points that lie on a cube face (a plane at y = 0 under a checker of
// size 1) off the face, so that the face shows one colour, not rounding noise.
constexpr double checker_face_lift = 1e-6;

bool odd_cube(const Vec3& p, double size) {
    const double k = std::floor(p.x / size + checker_face_lift) +
                     std::floor(p.y / size + checker_face_lift) +
                     std::floor(p.z / size + checker_face_lift);
    return std::abs(std::fmod(k, 2.0)) == 1.0;
}

}  // namespace

bool has_pattern(const Material& m) {
    return m.checker.has_value();
}

Colour pattern_pigment(const Material& m, const Vec3& object_point) {
    if (m.checker && odd_cube(object_point, m.checker_size)) return *m.checker;
    return m.pigment;
}

}  // namespace jt
