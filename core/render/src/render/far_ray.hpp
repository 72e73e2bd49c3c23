#pragma once
// Rays Embree cannot take as they are. Debian's Embree 3 aborts the process
// (assertion `ray.valid()`) when a component of a ray's origin or direction
// passes FLT_LARGE (1.844e18). Every number of a scene is within 1e9, but
// composed transforms are not: a sphere scaled by 1e9 twice sends reflected
// rays from near 1e18 and beyond. Such a ray goes to Embree moved along
// itself to where it enters the (padded) bounds of what the BVH holds, its
// direction scaled by a power of two; Embree only finds candidates, and every
// hit is still decided in double precision on the ray as it is. When even the
// moved ray is out of Embree's reach (the BVH itself reaches past it), the
// caller tests every surface in double precision instead.

#include "jtracer/scene.hpp"
#include "render/float_ray.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace jt {

// x * 2^e, exactly as std::ldexp gives it, without a call into libm (hot in
// the walks of meshes): a product with a power of two that is a normal double
// is exact, or rounds once as ldexp's result does.
inline double times_two_to(double x, int e) {
    if (e == 0) return x;
    if (e >= -1022 && e <= 1023)
        return x * std::bit_cast<double>(static_cast<std::uint64_t>(1023 + e) << 52);
    return std::ldexp(x, e);
}

// Below FLT_LARGE by more than float rounding of any coordinate.
inline constexpr double embree_reach = 1e18;

inline bool within_reach(const Vec3& v) {
    return std::abs(v.x) <= embree_reach && std::abs(v.y) <= embree_reach &&
           std::abs(v.z) <= embree_reach;
}

// Whether Embree's BVH holds a primitive with this box: its build leaves out,
// without a word, every box that reaches past FLT_LARGE (false for NaN too).
inline bool within_reach(const RTCBounds& box) {
    return within_reach(Vec3(box.lower_x, box.lower_y, box.lower_z)) &&
           within_reach(Vec3(box.upper_x, box.upper_y, box.upper_z));
}

// Whether Embree takes the ray as it is (false for NaN too).
inline bool embree_takes(const Vec3& origin, const Vec3& direction) {
    return within_reach(origin) && within_reach(direction);
}

// Embree's ray starts at origin + shift * direction and runs along
// direction * 2^-exponent: a distance t along the ray is (t - shift) * 2^exponent
// along Embree's.
struct FarRay {
    // as_is: Embree takes the ray unmoved; moved: shift and exponent say how;
    // misses: nothing Embree holds can be met; out_of_reach: test every surface.
    enum class Fit { as_is, moved, misses, out_of_reach };
    Fit fit = Fit::moved;
    Vec3 origin{0.0}, direction{0.0};
    double shift = 0.0;
    int exponent = 0;
};

// Embree's distance for the ray's `t`, rounded up a step past the rounding
// of t itself, for a tfar that culls nothing as near as t.
inline float far_t_up(const FarRay& far, double t) {
    if (!(std::abs(t) < std::numeric_limits<double>::max())) return float_infinity;
    const double slack =
        4.0 * (std::nextafter(std::abs(t), std::numeric_limits<double>::infinity()) - std::abs(t));
    return float_up(times_two_to(t - far.shift + slack, far.exponent));
}

// The ray from `origin` along `direction` between t_min and t_max, fitted to
// Embree against `bounds` (the BVH's). Directions need not be unit length.
inline FarRay fit_far_ray(const Vec3& origin, const Vec3& direction, double t_min, double t_max,
                          const RTCBounds& bounds) {
    FarRay far;
    const Vec3 lo(bounds.lower_x, bounds.lower_y, bounds.lower_z);
    const Vec3 hi(bounds.upper_x, bounds.upper_y, bounds.upper_z);
    // Padded well past the rounding of the box and of the moved origin.
    const double size = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x),
                                  std::abs(hi.y), std::abs(hi.z)});
    const double pad = 1e-5 * size + 1e-3;
    double enter = std::max(t_min, 0.0), leave = t_max;
    for (int a = 0; a < 3; ++a) {
        const double l = lo[a] - pad, h = hi[a] + pad;
        if (!(l <= h) || std::isnan(origin[a]) || std::isnan(direction[a])) {
            far.fit = FarRay::Fit::misses;
            return far;
        }
        if (direction[a] == 0.0) {
            if (!(origin[a] >= l && origin[a] <= h)) {
                far.fit = FarRay::Fit::misses;
                return far;
            }
            continue;
        }
        double t0 = (l - origin[a]) / direction[a], t1 = (h - origin[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    if (!(enter <= leave)) {
        far.fit = FarRay::Fit::misses;
        return far;
    }
    // One rounding of the exact origin + enter * direction (std::fma is
    // correctly rounded on every machine): the moved start lies on the ray
    // itself, where a product and a sum would each round at the size of the
    // far origin.
    far.shift = enter;
    far.origin =
        Vec3(std::fma(enter, direction.x, origin.x), std::fma(enter, direction.y, origin.y),
             std::fma(enter, direction.z, origin.z));
    const double longest =
        std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
    far.exponent = longest > embree_reach ? std::ilogb(longest) + 1 : 0;
    far.direction =
        Vec3(times_two_to(direction.x, -far.exponent), times_two_to(direction.y, -far.exponent),
             times_two_to(direction.z, -far.exponent));
    if (!within_reach(far.origin)) far.fit = FarRay::Fit::out_of_reach;
    return far;
}

inline void set_far_ray(RTCRay& ray, const FarRay& far, double t_min, double t_max) {
    set_float_ray(ray, far.origin, far.direction, 0.0, 0.0);
    ray.tnear = float_down(times_two_to(t_min - far.shift, far.exponent));
    ray.tfar = far_t_up(far, t_max);
}

// Sets `ray` to what Embree walks against `scene` for the ray from `origin`
// along `direction` between t_min and t_max: the ray itself when Embree takes
// it, else the moved one. The result says which, or that `ray` is not set.
inline FarRay fit_embree_ray(RTCScene scene, const Vec3& origin, const Vec3& direction,
                             double t_min, double t_max, RTCRay& ray) {
    if (embree_takes(origin, direction)) {
        set_float_ray(ray, origin, direction, t_min, t_max);
        FarRay as_is;
        as_is.fit = FarRay::Fit::as_is;
        return as_is;
    }
    RTCBounds bounds;
    rtcGetSceneBounds(scene, &bounds);
    const FarRay far = fit_far_ray(origin, direction, t_min, t_max, bounds);
    if (far.fit == FarRay::Fit::moved) set_far_ray(ray, far, t_min, t_max);
    return far;
}

}  // namespace jt
