#pragma once
// The float copy of a double ray that Embree walks its BVHs with, and the
// float bounds that keep it conservative: Embree only culls, and its float
// range must hold every exact hit in the double range.

#include "geometry/float_step.hpp"
#include "jtracer/scene.hpp"

#include <embree3/rtcore.h>

#include <limits>

namespace jt {

inline constexpr float float_infinity = std::numeric_limits<float>::infinity();

inline float float_down(double x) {
    if (!(x > 0.0)) return 0.0f;
    if (x >= static_cast<double>(std::numeric_limits<float>::max()))
        return std::numeric_limits<float>::max();
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = next_float_down(f);
    return f;
}

// One float step above too, so that Embree's own rounding of box entry
// distances cannot cull a box that holds an equally near exact hit.
inline float float_up(double x) {
    if (!(x > 0.0)) return next_float_up(0.0f);
    if (!(x < static_cast<double>(std::numeric_limits<float>::max()))) return float_infinity;
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = next_float_up(f);
    return next_float_up(f);
}

// Embree writes a hit only where it finds one: the ids say "none" until then.
inline void clear_hit(RTCHit& hit) {
    hit.geomID = RTC_INVALID_GEOMETRY_ID;
    hit.primID = RTC_INVALID_GEOMETRY_ID;
    hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

inline void set_float_ray(RTCRay& ray, const Vec3& origin, const Vec3& direction, double t_min,
                          double t_max) {
    ray.org_x = static_cast<float>(origin.x);
    ray.org_y = static_cast<float>(origin.y);
    ray.org_z = static_cast<float>(origin.z);
    ray.dir_x = static_cast<float>(direction.x);
    ray.dir_y = static_cast<float>(direction.y);
    ray.dir_z = static_cast<float>(direction.z);
    ray.tnear = float_down(t_min);
    ray.tfar = float_up(t_max);
    ray.time = 0.0f;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
}

}  // namespace jt
