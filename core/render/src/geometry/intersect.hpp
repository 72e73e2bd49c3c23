#pragma once
// Exact double-precision ray intersection of the three shapes, in the space the
// shape is defined in. A ray is origin + t * direction; the direction need not be
// unit length (rays reach object space through an inverse transform), and t
// keeps its meaning across that change of space.
//
// Each function returns the smallest root in the open interval (t_min, t_max),
// or +infinity when there is none.

#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace jt {

inline constexpr double no_hit = std::numeric_limits<double>::infinity();

// The roots of a t^2 + 2 b t + c = 0 where a = |d|^2, in a form that keeps full
// precision when the ray starts far from a small target (Ray Tracing Gems,
// ch. 7): the discriminant comes from the perpendicular offset, not b^2 - a c.
// Returns false when there is no real root.
inline bool solve_ray_quadratic(double a, double b, double c, double perpendicular_sq,
                                double radius_sq, double& t0, double& t1) {
    double discriminant = a * (radius_sq - perpendicular_sq);
    if (!(discriminant >= 0.0) || !(a > 0.0)) return false;
    double q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0.0) {
        t0 = t1 = -b / a;
        return true;
    }
    t0 = c / q;
    t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

// The margin of `passes_wide_of_sphere`, as a multiple of the unit roundoff
// times |f|^2 |d|^2: its bound needs 54 (see there); 128 leaves room.
inline constexpr double wide_miss_margin_ulps = 128.0;
// Below this |d|^2 or |f|^2 the products of the early answers below may be
// subnormal, where relative error bounds do not hold: such rays take the
// exact test.
inline constexpr double smallest_early_answer_scale = 1e-150;

// True only when the exact test of intersect_sphere would find no root. With
// f = origin - center, a = |d|^2, b = f.d and c = |f|^2 - r^2, a c - b^2 is
// a (p - r^2), p being the line's squared distance from the centre; it is
// tested against a margin larger than the rounding error of either test. Three
// multiplications, where the exact test needs a division, a vector update and
// a dot product: most spheres offered a ray are missed by it.
//
// Why the margin suffices: computed, a c - b^2 is a (p - r^2) within
// 16 u |f|^2 a (u = 2^-53, p the true squared distance of the ray from the
// centre, p <= |f|^2), and the exact test's squared perpendicular is at least
// p - 38 u |f|^2. So a result above 128 u |f|^2 a means
// p > r^2 + 112 u |f|^2, and the exact test's perpendicular then exceeds r^2:
// no root. A NaN or an overflow compares false and leaves the ray to the
// exact test; so does c <= 0 (the origin in the sphere), where a c - b^2 is
// not positive.
inline bool passes_wide_of_sphere(double a, double b, double c, double ff) {
    const double margin = wide_miss_margin_ulps * 0x1p-53 * (ff * a);
    return a > smallest_early_answer_scale && ff > smallest_early_answer_scale &&
           a * c - b * b > margin;
}

// The margin of `enters_beyond`, as a multiple of the unit roundoff times
// |f|^2: its bound needs 78 (see there); 128 leaves room.
inline constexpr double entry_beyond_margin_ulps = 128.0;

// True only when every root the exact test of intersect_sphere computes is at
// or beyond t_max (given 0 <= t_max), so that it would answer no_hit. With a,
// b, c and ff as in `passes_wide_of_sphere` and g(t) = a t^2 + 2 b t + c =
// |f + t d|^2 - r^2: a ray starting outside (c > 0) whose t_max comes before
// its closest approach (a t_max + b < 0) and is still outside the sphere there
// (g(t_max) > 0) enters, if at all, after t_max. Two multiplications and two
// additions, where the exact test needs a square root and two divisions: most
// of the overlapping shells a primary ray is offered lie behind its nearest
// hit.
//
// Why the margin suffices (u = 2^-53; a, b, c the computed values, B = -b/a,
// D = (b^2 - a c) / a^2, the real roots B -+ sqrt(D), T = t_max):
// - The exact test's discriminant a (r^2 - perpendicular^2) is at most
//   b^2 - a c + 58 u a |f|^2: its perpendicular is within 38 u |f|^2 of the
//   true one (see passes_wide_of_sphere), a is within 3 u a, b within
//   3 u |f| |d| and c within 4 u |f|^2 of their true values, and the last
//   subtraction and multiplication add 2 u. So with E = 58 u |f|^2 / a, its
//   near root c / q is at least (c / a) / (B + sqrt(D + E)) (1 - 3 u), which
//   is at least (B - sqrt(D + E)) (1 - 3 u) because c / a = B^2 - D; its far
//   root q / a is at least B (1 - u).
// - Both are at least T when T' = T (1 + 4 u) <= B and g(T') >= a E, that is
//   when T' is before the smaller root of a t^2 + 2 b t + c = a E.
// - g(T') >= g(T) - 8 u T |b| >= g(T) - 8 u |f|^2, since g's slope between T
//   and B is at most 2 |b| in size and T |b| <= b^2 / a <= |f|^2; the
//   computed g(T) is within 12 u |f|^2 of the real one. A computed g(T) above
//   (58 + 8 + 12) u |f|^2 thus makes g(T') >= a E.
// - If T' > B, the computed a t_max + b < 0 puts T within 5 u B of B, so
//   g(B) >= g(T) - 25 u^2 |f|^2 > a E and the exact discriminant is
//   negative: no root at all.
// A NaN or an infinite t_max compares false and leaves the ray to the exact
// test.
inline bool enters_beyond(double a, double b, double c, double ff, double t_max) {
    const double approach = a * t_max + b;
    const double outside = (approach + b) * t_max + c;
    return c > 0.0 && approach < 0.0 && a > smallest_early_answer_scale &&
           ff > smallest_early_answer_scale && outside > entry_beyond_margin_ulps * 0x1p-53 * ff;
}

inline double first_in_range(double t0, double t1, double t_min, double t_max) {
    if (t0 > t_min && t0 < t_max) return t0;
    if (t1 > t_min && t1 < t_max) return t1;
    return no_hit;
}

// DecideEntryBeyond: whether to try `enters_beyond` before the exact roots.
// It pays where a ray is offered spheres behind its nearest hit so far. The
// spheres a shadow ray tests seldom lie beyond its light: there it would only
// add work (more instructions on every benchmark scene), so shadow rays leave
// it out.
template <bool DecideEntryBeyond = true>
inline double intersect_sphere(const Vec3& origin, const Vec3& direction, const Vec3& center,
                               double radius, double t_min, double t_max) {
    Vec3 f = origin - center;
    double b = glm::dot(f, direction);
    double ff = glm::dot(f, f);
    double c = ff - radius * radius;
    // Starting outside (c > 0) and not heading in (b >= 0): the roots' product
    // c/a is positive and their sum -2b/a is not, so none is positive, and the
    // computed ones below keep those signs (b == 0 gives a negative
    // discriminant). Most shadow and reflection rays leave their sphere this
    // way; deciding it before the division and square root changes no result.
    if (c > 0.0 && b >= 0.0 && t_min >= 0.0) return no_hit;
    double a = glm::dot(direction, direction);
    if (passes_wide_of_sphere(a, b, c, ff)) return no_hit;
    // A t_max below t_min >= 0 leaves no range: enters_beyond's premise
    // 0 <= t_max need not be tested.
    if (DecideEntryBeyond && t_min >= 0.0 && enters_beyond(a, b, c, ff, t_max)) return no_hit;
    Vec3 perpendicular = f - (b / a) * direction;
    double t0, t1;
    if (!solve_ray_quadratic(a, b, c, glm::dot(perpendicular, perpendicular), radius * radius, t0,
                             t1))
        return no_hit;
    return first_in_range(t0, t1, t_min, t_max);
}

// The plane { p : dot(p, unit_normal) = distance }.
inline double intersect_plane(const Vec3& origin, const Vec3& direction, const Vec3& unit_normal,
                              double distance, double t_min, double t_max) {
    double denominator = glm::dot(unit_normal, direction);
    if (denominator == 0.0) return no_hit;
    double t = (distance - glm::dot(unit_normal, origin)) / denominator;
    return (t > t_min && t < t_max) ? t : no_hit;
}

// Which surface of a cylinder a ray met; it decides the normal.
enum class CylinderPart : unsigned char { side, bottom, top };

// True only when intersect_cylinder would find no root, side or cap: the
// ray's projection on the xz plane passes wide of the disk x^2 + z^2 <= r^2.
// a, b, c and ff are the side's quadratic in that plane (a = dx^2 + dz^2,
// b = ox dx + oz dz, ff = ox^2 + oz^2, c = ff - r^2), and the test is
// passes_wide_of_sphere's in two dimensions: an infinite cylinder is the disk
// swept along y. Most cylinders a ray is offered after their bounding sphere
// are thin ones it misses: this spares their side's division and square root
// and both caps' divisions.
//
// Why it covers the caps too (u = 2^-53, o = (ox, oz), p the squared
// distance of the projected line from the axis): passing means
// p > r^2 + 112 u |o|^2, as for the sphere, and a computed c > 0 means
// r <= |o| (1 + 2 u). A cap's computed point (x, z) = o + t (dx, dz) + e for
// its computed t, whatever t is, with |e| <= u |t (dx, dz)| + u |(x, z)|
// (1 + u); its true part X = o + t (dx, dz) lies on the projected line, so
// |X|^2 >= p, and |t (dx, dz)| <= |X| + |o|. Accepting the point needs
// computed x^2 + z^2 <= r^2 (1 + 3 u), so |(x, z)| <= r (1 + 2 u), hence
// |X| <= r (1 + 5 u) + 2 u |o| and p <= |X|^2 <= r^2 + 15 u |o|^2: a
// contradiction. Products below the smallest normal double add under 2^-536
// to these lengths, far below the margin once a and ff exceed
// smallest_early_answer_scale; an infinite or NaN t or point is never accepted.
inline bool passes_wide_of_cylinder(double a, double b, double c, double ff) {
    return passes_wide_of_sphere(a, b, c, ff);
}

// Solid cylinder x^2 + z^2 <= r^2, 0 <= y <= height, closed by both caps.
inline double intersect_cylinder(const Vec3& origin, const Vec3& direction, double radius,
                                 double height, double t_min, double t_max, CylinderPart& part) {
    double best = no_hit;
    const double r2 = radius * radius;
    // The side, x^2 + z^2 = r^2, where 0 <= y <= height.
    double a = direction.x * direction.x + direction.z * direction.z;
    if (a > 0.0) {
        double b = origin.x * direction.x + origin.z * direction.z;
        double ff = origin.x * origin.x + origin.z * origin.z;
        double c = ff - r2;
        if (passes_wide_of_cylinder(a, b, c, ff)) return no_hit;
        double px = origin.x - (b / a) * direction.x;
        double pz = origin.z - (b / a) * direction.z;
        double t0, t1;
        if (solve_ray_quadratic(a, b, c, px * px + pz * pz, r2, t0, t1)) {
            for (double t : {t0, t1}) {
                if (!(t > t_min && t < best && t < t_max)) continue;
                double y = origin.y + t * direction.y;
                if (y >= 0.0 && y <= height) {
                    best = t;
                    part = CylinderPart::side;
                }
            }
        }
    }
    // The caps, y = 0 and y = height, where x^2 + z^2 <= r^2.
    if (direction.y != 0.0) {
        for (CylinderPart cap : {CylinderPart::bottom, CylinderPart::top}) {
            double y = cap == CylinderPart::bottom ? 0.0 : height;
            double t = (y - origin.y) / direction.y;
            if (!(t > t_min && t < best && t < t_max)) continue;
            double x = origin.x + t * direction.x;
            double z = origin.z + t * direction.z;
            if (x * x + z * z <= r2) {
                best = t;
                part = cap;
            }
        }
    }
    return best;
}

// The outward normal (not unit) of a cylinder at an object-space point on `part`.
inline Vec3 cylinder_normal(const Vec3& p, CylinderPart part) {
    switch (part) {
        case CylinderPart::bottom:
            return {0.0, -1.0, 0.0};
        case CylinderPart::top:
            return {0.0, 1.0, 0.0};
        case CylinderPart::side:
            break;
    }
    return {p.x, 0.0, p.z};
}

// Where the line origin + t * direction meets the plane of triangle (a, b, c),
// in double precision: t and the barycentric weights u (of b) and v (of c).
// No test that the point lies inside: the caller has one (Embree's watertight
// test) and wants its answer kept on shared edges. False when the line is
// parallel to the plane.
struct TrianglePoint {
    double t = no_hit;
    double u = 0.0, v = 0.0;
};
inline bool triangle_plane_point(const Vec3& origin, const Vec3& direction, const Vec3& a,
                                 const Vec3& b, const Vec3& c, TrianglePoint& out) {
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (!(det != 0.0) || !std::isfinite(det)) return false;
    const Vec3 s = origin - a;
    const Vec3 q = glm::cross(s, e1);
    out.u = glm::dot(s, p) / det;
    out.v = glm::dot(direction, q) / det;
    out.t = glm::dot(e2, q) / det;
    return std::isfinite(out.t);
}

}  // namespace jt
