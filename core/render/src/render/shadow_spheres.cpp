#include "render/shadow_spheres.hpp"

#include "render/embree_device.hpp"
#include "render/float_ray.hpp"
#include "render/ray_queries.hpp"
#include "render/user_geometry.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace jt {

namespace {

// Magnitudes the float path is meant for: far from float's underflow and
// overflow, where the relative bounds of shadow_spheres.hpp hold.
constexpr double min_magnitude = 1e-12;
constexpr double max_magnitude = 1e15;

float padded_radius(double radius, double pad) {
    return float_up(radius + pad);
}

}  // namespace

bool spheres_overlap_heavily(const std::vector<WorldSphere>& spheres) {
    Vec3 lower(std::numeric_limits<double>::infinity()), upper(-lower);
    double volume = 0.0;
    for (const WorldSphere& s : spheres) {
        lower = glm::min(lower, s.center - Vec3(s.radius));
        upper = glm::max(upper, s.center + Vec3(s.radius));
        volume += 4.0 / 3.0 * 3.141592653589793 * s.radius * s.radius * s.radius;
    }
    const Vec3 size = upper - lower;
    return volume > min_overlap * size.x * size.y * size.z;
}

void build_shadow_spheres(Geometry& g, double magnitude, RTCBuildQuality quality,
                          double pad_factor) {
    if (g.spheres.empty() || !(magnitude >= min_magnitude && magnitude <= max_magnitude)) return;
    ShadowSpheres& shadow = g.shadow;
    shadow.reach = shadow_reach_factor * magnitude;
    const double pad = pad_factor * shadow.reach;

    shadow.bvh = rtcNewScene(embree_device());
    rtcSetSceneBuildQuality(shadow.bvh, quality);
    rtcSetSceneFlags(shadow.bvh, RTC_SCENE_FLAG_ROBUST);

    RTCGeometry spheres = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
    rtcSetGeometryBuildQuality(spheres, quality);
    auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(spheres, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                               g.spheres.size()));
    double largest = 0.0;
    for (std::size_t i = 0; i < g.spheres.size(); ++i) {
        const WorldSphere& s = g.spheres[i];
        const float radius = padded_radius(s.radius, pad);
        points[4 * i + 0] = static_cast<float>(s.center.x);
        points[4 * i + 1] = static_cast<float>(s.center.y);
        points[4 * i + 2] = static_cast<float>(s.center.z);
        points[4 * i + 3] = radius;
        largest = std::max(largest, static_cast<double>(radius));
    }
    rtcSetGeometryUserData(spheres, &g);
    rtcSetGeometryOccludedFilterFunction(spheres, sphere_occluded_filter);
    rtcCommitGeometry(spheres);
    rtcAttachGeometry(shadow.bvh, spheres);
    rtcReleaseGeometry(spheres);
    shadow.tail = 2.0 * (largest + pad);

    if (!g.shapes.empty())
        attach_user_geometry(shadow.bvh, &g, g.shapes.size(), quality, shape_bounds,
                             shape_intersect, shape_occluded);
    rtcCommitScene(shadow.bvh);
}

bool fit_shadow_ray(const ShadowSpheres& shadow, const Vec3& origin, const Vec3& direction,
                    double t_min, double t_max, RTCRay& ray) {
    if (!shadow.bvh || !(t_min >= 0.0) || !(t_max < std::numeric_limits<double>::max()))
        return false;
    if (!(std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z)}) <= shadow.reach))
        return false;
    const double length_sq = glm::dot(direction, direction);
    // Near unit length, so that the bounds in distances hold in t.
    if (!(length_sq >= 0.25 && length_sq <= 4.0)) return false;
    set_float_ray(ray, origin, direction, 0.0, t_max + shadow.tail / std::sqrt(length_sq));
    return true;
}

}  // namespace jt
