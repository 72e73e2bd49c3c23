#include "render/pattern.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

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

double wrap(double x) {
    const double w = x - std::floor(x);
    return w < 1.0 ? w : 0.0;  // x just below an integer can round up to 1
}

// Index i modulo n, for any i.
int wrap_index(long long i, int n) {
    const long long m = i % n;
    return static_cast<int>(m < 0 ? m + n : m);
}

}  // namespace

bool has_pattern(const Material& m) {
    return m.finish->checker.has_value() || !m.finish->image_map.empty();
}

Uv sphere_uv(const Sphere& sphere, const Vec3& p) {
    const Vec3 d = glm::normalize(p - sphere.center);
    return {0.5 + std::atan2(d.x, d.z) / (2.0 * std::numbers::pi),
            0.5 + std::asin(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi};
}

Uv cylinder_uv(const Cylinder& cylinder, const Vec3& p) {
    // A cap hit lies inside the rim; a side hit on it, up to rounding.
    const double r2 = cylinder.radius * cylinder.radius;
    const bool cap = p.x * p.x + p.z * p.z < r2 * (1.0 - 1e-9);
    if (cap) return {0.5 + p.x / (2.0 * cylinder.radius), 0.5 + p.z / (2.0 * cylinder.radius)};
    return {0.5 + std::atan2(p.x, p.z) / (2.0 * std::numbers::pi), p.y / cylinder.height};
}

Uv plane_uv(const Plane& plane, double map_size, const Vec3& p) {
    const Vec3 n = glm::normalize(plane.normal);
    Vec3 e1 = glm::cross(n, Vec3(0, 0, 1));
    if (e1 == Vec3(0.0)) e1 = glm::cross(n, Vec3(1, 0, 0));
    e1 = glm::normalize(e1);
    const Vec3 e2 = glm::cross(n, e1);
    return {glm::dot(p, e1) / map_size, glm::dot(p, e2) / map_size};
}

Uv shape_uv(const Shape& shape, double map_size, const Vec3& p, Uv surface) {
    if (const auto* s = shape_if<Sphere>(&shape)) return sphere_uv(*s, p);
    if (const auto* c = shape_if<Cylinder>(&shape)) return cylinder_uv(*c, p);
    if (const auto* l = shape_if<Plane>(&shape)) return plane_uv(*l, map_size, p);
    return surface;
}

namespace {

// Columns i and i1 blended with weight ax, rows j and j1 with weight ay.
Colour blend(const Texture& t, int i, int i1, double ax, int j, int j1, double ay) {
    const Colour bottom = (1.0 - ax) * texel(t, i, j) + ax * texel(t, i1, j);
    const Colour top = (1.0 - ax) * texel(t, i, j1) + ax * texel(t, i1, j1);
    return (1.0 - ay) * bottom + ay * top;
}

}  // namespace

Colour sample_bilinear(const Texture& t, Uv uv) {
    // Texel i's centre is at (i + 0.5) / width.
    const double x = wrap(uv.u) * t.width - 0.5, y = wrap(uv.v) * t.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double ax = x - fx, ay = y - fy;
    const auto i0 = static_cast<long long>(fx), j0 = static_cast<long long>(fy);
    const int i = wrap_index(i0, t.width), i1 = wrap_index(i0 + 1, t.width);
    const int j = wrap_index(j0, t.height), j1 = wrap_index(j0 + 1, t.height);
    return blend(t, i, i1, ax, j, j1, ay);
}

Colour sample_bilinear_rows_clamped(const Texture& t, Uv uv) {
    const double x = wrap(uv.u) * t.width - 0.5;
    const double fx = std::floor(x);
    const double ax = x - fx;
    const auto i0 = static_cast<long long>(fx);
    const int i = wrap_index(i0, t.width), i1 = wrap_index(i0 + 1, t.width);
    // Below the bottom row's centre and above the top row's, the row itself:
    // the poles of a sky do not meet.
    const double y = std::clamp(uv.v * t.height - 0.5, 0.0, static_cast<double>(t.height - 1));
    const double fy = std::floor(y);
    const int j = static_cast<int>(fy), j1 = std::min(j + 1, t.height - 1);
    return blend(t, i, i1, ax, j, j1, y - fy);
}

Colour pattern_pigment(const Material& m, const Texture* image, const Shape& shape,
                       const Vec3& object_point, Uv surface) {
    if (image)
        return sample_bilinear(*image, shape_uv(shape, m.finish->map_size, object_point, surface));
    if (m.finish->checker && odd_cube(object_point, m.finish->checker_size))
        return *m.finish->checker;
    return m.pigment;
}

}  // namespace jt
