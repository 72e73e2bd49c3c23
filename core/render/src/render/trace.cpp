#include "render/trace.hpp"

#include "jtracer/limits.hpp"
#include "render/ray_queries.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace jt {

namespace {

constexpr int max_depth =
    kMaxRecurseDepth;  // recurse_depth is clamped here (docs/language.md §4.1)

double max_abs(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The local (non-reflected) light at a hit: ambient, then each light's diffuse
// and specular terms when nothing shadows it.
Colour shade_hit(const PreparedScene& scene, const Material& m, const Vec3& point,
                 const Vec3& lifted, const Vec3& normal, const Vec3& view, std::uint64_t& rays) {
    Colour c = scene.settings.ambient_light * m.ambient * m.pigment;
    const Geometry& geometry = *scene.geometry;
    const std::vector<DirectionTable>* light_tables =
        scene.light_tables && !scene.light_tables->empty() ? scene.light_tables.get() : nullptr;
    // One hint a light, per thread: consecutive shadow rays of a thread come
    // from neighbouring pixels of one tile. Hints never change a result, so
    // neither thread count nor tile order can show in the image.
    thread_local std::vector<OccluderHint> hints;
    if (hints.size() < scene.lights.size()) hints.resize(scene.lights.size());
    for (std::size_t light_index = 0; light_index < scene.lights.size(); ++light_index) {
        const PointLight& light = scene.lights[light_index];
        Vec3 to_light = light.position - point;
        double distance = glm::length(to_light);
        if (!(distance > 0.0)) continue;
        Vec3 l = to_light / distance;
        double n_dot_l = glm::dot(normal, l);
        if (!(n_dot_l > 0.0)) continue;
        // A black light adds nothing whether shadowed or not: skip its shadow ray.
        if (light.intensity == Colour(0.0)) continue;
        Vec3 shadow_direction = light.position - lifted;
        double shadow_distance = glm::length(shadow_direction);
        if (!(shadow_distance > 0.0)) continue;
        ++rays;
        if (occluded(geometry, lifted, shadow_direction / shadow_distance, 0.0, shadow_distance,
                     &hints[light_index], light_tables ? &(*light_tables)[light_index] : nullptr))
            continue;
        // pow(x, 1) is x exactly, and adding a zero term changes nothing: both
        // shortcuts leave every bit as the plain formula would.
        double diffuse_factor = m.diffuse_k == 1.0 ? n_dot_l : std::pow(n_dot_l, 1.0 / m.diffuse_k);
        c += light.intensity * m.diffuse * m.pigment * diffuse_factor;
        if (m.specular == Colour(0.0)) continue;
        Vec3 r = 2.0 * n_dot_l * normal - l;
        double r_dot_v = glm::dot(r, view);
        if (r_dot_v > 0.0) c += light.intensity * m.specular * std::pow(r_dot_v, m.specular_k);
    }
    return c;
}

}  // namespace

double surface_offset(const Vec3& origin, const Vec3& point, double distance) {
    double scale = std::max({max_abs(origin), max_abs(point), std::abs(distance)});
    return std::max(1e-9 * scale, 1e-300);
}

Colour trace_ray(const PreparedScene& scene, const Vec3& origin, const Vec3& unit_direction,
                 double t_min, std::uint64_t& rays, const DirectionTable* around_origin) {
    const Geometry& geometry = *scene.geometry;
    const int depth_limit = std::clamp(scene.settings.recurse_depth, 0, max_depth);
    // c_k = local_k + reflection_k * c_(k+1): kept per bounce and folded back in
    // the end, so the sum rounds exactly as the recursive definition does.
    std::array<Colour, max_depth + 1> local;
    std::array<double, max_depth + 1> reflection;

    Vec3 o = origin;
    Vec3 d = unit_direction;
    double t_lower = t_min;
    int last = 0;
    for (int depth = 0;; ++depth) {
        last = depth;
        reflection[depth] = 0.0;
        Hit hit;
        ++rays;
        const DirectionTable* table = depth == 0 ? around_origin : nullptr;
        if (!finite(o) || !finite(d) || !closest_hit(geometry, o, d, t_lower, hit, table)) {
            local[depth] = scene.settings.background;
            break;
        }
        Vec3 point = o + hit.t * d;
        Vec3 normal = glm::normalize(hit.normal);
        if (glm::dot(normal, d) > 0.0) normal = -normal;  // two-sided: face the ray
        if (!finite(normal)) {
            local[depth] = Colour(0.0);
            break;
        }
        Vec3 lifted = point + surface_offset(o, point, hit.t) * normal;
        const Material& m = scene.materials[scene.material_of[hit.source]];
        local[depth] = shade_hit(scene, m, point, lifted, normal, -d, rays);
        if (depth >= depth_limit || !(m.reflection > 0.0)) break;
        reflection[depth] = m.reflection;
        d = glm::normalize(d - 2.0 * glm::dot(d, normal) * normal);
        o = lifted;
        t_lower = 0.0;
    }
    Colour c = local[last];
    for (int k = last - 1; k >= 0; --k) c = local[k] + reflection[k] * c;
    return c;
}

}  // namespace jt
