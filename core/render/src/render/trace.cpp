#include "render/trace.hpp"

#include "jtracer/limits.hpp"
#include "render/file_pigment.hpp"
#include "render/light_disk.hpp"
#include "render/pattern.hpp"
#include "render/pixel_hash.hpp"
#include "render/ray_queries.hpp"
#include "render/refraction.hpp"
#include "render/sky_map.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

namespace jt {

namespace {

constexpr int max_depth =
    kMaxRecurseDepth;  // recurse_depth is clamped here (docs/language.md §4.1)

double max_abs(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// The fraction of a light that reaches along origin + t * direction for t in
// (0, t_max): the product of the transmission of every surface crossed, 0 at
// the first opaque one (docs/language.md §13.2). Each query starts from the
// same origin past the previous hit, so no surface is counted twice.
// `candidates`: a list around the origin of every shape that may lie across
// the ray before t_max (a nearer hit is all the loop uses), or null.
double transmittance(const PreparedScene& scene, const Vec3& origin, const Vec3& direction,
                     double t_max, const Departure& from,
                     const ListedShapes* candidates = nullptr) {
    double through = 1.0;
    double t_lower = 0.0;
    Hit hit;
    while (through > 0.0 &&
           closest_hit(*scene.geometry, origin, direction, t_lower, hit, candidates, from) &&
           hit.t < t_max) {
        through *= primitive_material(scene, hit.source).finish->transmission;
        t_lower = hit.t;
    }
    return through;
}

// What a ray meets first. Only `kind` is set up front: first_surface sets
// every other field that its kind reads, and zeroing the whole struct twice a
// bounce showed in profiles.
struct SurfaceHit {
    enum class Kind : std::uint8_t { miss, no_normal, surface };
    Kind kind = Kind::miss;
    Vec3 point;
    Vec3 normal;     // unit, facing the ray: the shading normal N
    Vec3 geometric;  // unit, facing the ray: Ng (the same as N but on triangles)
    bool entering;   // the ray arrives from the outside (docs/language.md §13.2)
    Vec3 lifted;     // point moved off the surface toward the ray's side
    double offset;
    std::uint32_t source;
    TriangleId triangle;     // on a triangle: which
    glm::dvec2 uv;           // on a triangle: its texture coordinates
    glm::dvec2 barycentric;  // on a triangle: the weights of its second and third corner
};

// `leaving`: the triangle a secondary ray starts on, which it never meets
// again (docs/language.md §13.5: no surface reflects itself). Lifted along Ng,
// a ray reflected or refracted about a smooth normal that points far from the
// face may still head back through it.
SurfaceHit first_surface(const Geometry& geometry, const Vec3& o, const Vec3& d, double t_lower,
                         const ListedShapes* candidates, const Departure& leaving) {
    SurfaceHit s;
    Hit hit;
    if (!all_finite(o) || !all_finite(d) ||
        !closest_hit(geometry, o, d, t_lower, hit, candidates, leaving))
        return s;
    s.point = o + hit.t * d;
    s.geometric = glm::normalize(hit.normal);
    const double along = glm::dot(s.geometric, d);
    s.entering = along < 0.0;
    if (along > 0.0) s.geometric = -s.geometric;  // two-sided: face the ray
    if (!all_finite(s.geometric)) {
        s.kind = SurfaceHit::Kind::no_normal;
        return s;
    }
    s.normal = s.geometric;
    if (hit.shading != Vec3(0.0)) {
        // A smooth normal turns to the side the geometric one faces (§13.5).
        const Vec3 n = glm::normalize(hit.shading);
        if (all_finite(n)) s.normal = glm::dot(n, s.geometric) < 0.0 ? -n : n;
    }
    s.kind = SurfaceHit::Kind::surface;
    s.offset = surface_offset(o, s.point, hit.t);
    s.lifted = s.point + s.offset * s.geometric;
    s.source = hit.source;
    s.triangle = hit.triangle;
    s.uv = hit.uv;
    s.barycentric = hit.barycentric;
    return s;
}

// What a soft light lets through to a hit: the mean visibility of its disk's
// points (docs/language.md §14.1), summed in index order. Its rays all leave
// one point but toward points off the light's centre, so the light's
// direction table (built for rays through the centre) does not apply; the
// shapes near the cone from the hit to the disk, found once for all its rays,
// do. The occluder hint only orders the tests and never changes an answer.
double disk_visibility(const PreparedScene& scene, const PointLight& light, const SurfaceHit& s,
                       const Vec3& l, const PixelSample& sample, OccluderHint& hint) {
    const LightDisk disk = light_disk(light.position, light.radius, l);
    const int count = light.shadow_samples;
    const double turn = pixel_angle(sample.i, sample.j, sample.k);
    const Vec3 above = s.lifted;
    const Vec3 below = s.point - s.offset * s.geometric;
    const Departure from{s.triangle, s.point};
    DiskCandidates near;
    const bool culled =
        shapes_toward_disk(*scene.geometry, s.point, s.offset, light.position, light.radius, near);
    const ListedShapes listed = near.listed();
    // In packets of rays: v of each, then the sum in index order. Rays left to
    // the BVH wait in `rays` (their v is 1 until the packet says otherwise).
    double sum = 0.0;
    std::array<double, shadow_packet> v;
    std::array<ShadowRay, shadow_packet> rays;
    std::array<int, shadow_packet> ray_of;
    for (int first = 0; first < count; first += static_cast<int>(shadow_packet)) {
        const int n = std::min(count - first, static_cast<int>(shadow_packet));
        std::size_t waiting = 0;
        for (int k = 0; k < n; ++k) {
            const Vec3 q = disk_point(disk, first + k, count, turn);
            const Vec3 l_m = glm::normalize(q - s.point);
            v[k] = 0.0;
            if (!(glm::dot(s.normal, l_m) > 0.0)) continue;
            // Toward a point behind the face (a smooth normal on a mesh), the
            // ray starts under it and only its own triangle cannot block it.
            const Vec3 origin = glm::dot(s.geometric, l_m) < 0.0 ? below : above;
            const Vec3 path = q - origin;
            const double length = glm::length(path);
            if (!(length > 0.0)) continue;
            const Vec3 direction = path / length;
            if (scene.has_transmission) {
                v[k] = transmittance(scene, origin, direction, length, from,
                                     culled ? &listed : nullptr);
            } else if (culled) {
                v[k] = occluded_among(*scene.geometry, listed, origin, direction, 0.0, length,
                                      &hint, from)
                           ? 0.0
                           : 1.0;
            } else {
                v[k] = 1.0;
                rays[waiting] = {origin, direction, 0.0, length};
                ray_of[waiting++] = k;
            }
        }
        if (waiting > 0) {
            std::array<bool, shadow_packet> blocked;
            occluded_together(*scene.geometry, std::span(rays.data(), waiting), blocked.data(),
                              &hint, from);
            for (std::size_t w = 0; w < waiting; ++w)
                if (blocked[w]) v[ray_of[w]] = 0.0;
        }
        for (int k = 0; k < n; ++k) sum += v[k];
    }
    return sum / count;
}

// The local (non-reflected) light at a hit: ambient, then each light's diffuse
// and specular terms when nothing shadows it. A triangle's shadow rays never
// meet the triangle they leave (`own`): a smooth normal may face a light its
// flat face turns away from (docs/language.md §13.5). The pigment is the
// material's, or the one its pattern or model file gives at the hit.
Colour shade_hit(const PreparedScene& scene, const Finish& m, const Colour& pigment,
                 const SurfaceHit& s, const Vec3& view, const PixelSample& sample,
                 std::uint64_t& rays) {
    const Vec3& point = s.point;
    const Vec3& lifted = s.lifted;
    const Vec3& normal = s.normal;
    const Departure from{s.triangle, point};
    Colour c = scene.settings.ambient_light * m.ambient * pigment;
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
        Colour intensity = light.intensity;
        // Inside its sphere, a soft light is a point light (§14.1).
        if (light.radius > 0.0 && distance > light.radius && sample.soft_shadows) {
            rays += static_cast<std::uint64_t>(light.shadow_samples);
            const double visible = disk_visibility(scene, light, s, l, sample, hints[light_index]);
            if (!(visible > 0.0)) continue;
            intensity *= visible;
        } else {
            Vec3 shadow_direction = light.position - lifted;
            double shadow_distance = glm::length(shadow_direction);
            if (!(shadow_distance > 0.0)) continue;
            ++rays;
            if (scene.has_transmission) {
                const double through = transmittance(
                    scene, lifted, shadow_direction / shadow_distance, shadow_distance, from);
                if (!(through > 0.0)) continue;
                intensity *= through;
            } else if (occluded(geometry, lifted, shadow_direction / shadow_distance, 0.0,
                                shadow_distance, &hints[light_index],
                                light_tables ? &(*light_tables)[light_index] : nullptr, from)) {
                continue;
            }
        }
        // pow(x, 1) is x exactly, and adding a zero term changes nothing: both
        // shortcuts leave every bit as the plain formula would.
        double diffuse_factor = m.diffuse_k == 1.0 ? n_dot_l : std::pow(n_dot_l, 1.0 / m.diffuse_k);
        c += intensity * m.diffuse * pigment * diffuse_factor;
        if (m.specular == Colour(0.0)) continue;
        Vec3 r = 2.0 * n_dot_l * normal - l;
        double r_dot_v = glm::dot(r, view);
        if (r_dot_v > 0.0) c += intensity * m.specular * std::pow(r_dot_v, m.specular_k);
    }
    return c;
}

Colour shade_surface(const PreparedScene& scene, const SurfaceHit& s, const Vec3& d,
                     const PixelSample& sample, std::uint64_t& rays) {
    const Material& m = primitive_material(scene, s.source);
    // A mesh's part with colours from its file replaces the block's pigment
    // and pattern (docs/language.md §14.5).
    if (s.triangle.instance != TriangleId::no_instance && scene.geometry->triangles->file_materials)
        if (const std::optional<Colour> pigment =
                file_pigment(*scene.geometry->triangles, s.triangle, s.barycentric, s.uv))
            return shade_hit(scene, *m.finish, *pigment, s, -d, sample, rays);
    if (!has_pattern(m)) return shade_hit(scene, *m.finish, m.pigment, s, -d, sample, rays);
    // A scene with a pattern always gathers its materials, so they have entries.
    const PatternSpace& space = scene.pattern_space[s.source];
    const Colour patterned =
        pattern_pigment(m, scene.textures[material_entry(scene, s.source)].get(), space.shape,
                        apply_point(space.to_object, s.point), Uv{s.uv.x, s.uv.y});
    return shade_hit(scene, *m.finish, patterned, s, -d, sample, rays);
}

Vec3 mirror(const Vec3& d, const Vec3& n) {
    return glm::normalize(d - 2.0 * glm::dot(d, n) * n);
}

// A branch whose weight in the pixel (the product of the reflection and
// transmission factors on its way) is below this is not traced: it could move
// a pixel by a level only where the light there is a thousand times white.
// Without it, a surface that both reflects and transmits doubles the rays at
// every bounce, 2^recurse_depth in all.
constexpr double min_branch_weight = 1e-6;

// The recursive Whitted tracer for scenes with transmissive surfaces, where a
// hit can spawn both a reflected and a transmitted ray.
Colour trace_branching(const PreparedScene& scene, const Vec3& o, const Vec3& d, double t_lower,
                       int depth, int depth_limit, double weight, const PixelSample& sample,
                       std::uint64_t& rays, const ListedShapes* candidates,
                       const Departure& leaving) {
    ++rays;
    const SurfaceHit s = first_surface(*scene.geometry, o, d, t_lower, candidates, leaving);
    if (s.kind == SurfaceHit::Kind::miss) return miss_colour(scene, d);
    if (s.kind == SurfaceHit::Kind::no_normal) return Colour(0.0);
    Colour c = shade_surface(scene, s, d, sample, rays);
    if (depth >= depth_limit) return c;
    const Finish& m = *primitive_material(scene, s.source).finish;
    if (m.reflection > 0.0 && weight * m.reflection >= min_branch_weight)
        c += m.reflection * trace_branching(scene, s.lifted, mirror(d, s.normal), 0.0, depth + 1,
                                            depth_limit, weight * m.reflection, sample, rays,
                                            nullptr, {s.triangle, s.point});
    if (m.transmission > 0.0 && weight * m.transmission >= min_branch_weight) {
        const Vec3 t = transmitted_direction(d, s.normal, s.entering, m.ior);
        // Total internal reflection stays on the ray's side; a refracted ray crosses.
        const Vec3 from =
            glm::dot(t, s.geometric) > 0.0 ? s.lifted : s.point - s.offset * s.geometric;
        c += m.transmission * trace_branching(scene, from, t, 0.0, depth + 1, depth_limit,
                                              weight * m.transmission, sample, rays, nullptr,
                                              {s.triangle, s.point});
    }
    return c;
}

}  // namespace

double surface_offset(const Vec3& origin, const Vec3& point, double distance) {
    double scale = std::max({max_abs(origin), max_abs(point), std::abs(distance)});
    return std::max(1e-9 * scale, 1e-300);
}

Colour trace_ray(const PreparedScene& scene, const Vec3& origin, const Vec3& unit_direction,
                 double t_min, const PixelSample& sample, std::uint64_t& rays,
                 const ListedShapes* first_candidates) {
    const Geometry& geometry = *scene.geometry;
    const int depth_limit = std::clamp(scene.settings.recurse_depth, 0, max_depth);
    if (scene.has_transmission)
        return trace_branching(scene, origin, unit_direction, t_min, 0, depth_limit, 1.0, sample,
                               rays, first_candidates, {});
    // c_k = local_k + reflection_k * c_(k+1): kept per bounce and folded back in
    // the end, so the sum rounds exactly as the recursive definition does.
    // Plain doubles, left uninitialised: glm's vectors zero themselves, and
    // zeroing room for every possible bounce (8 KiB) cost more than most rays.
    struct Bounce {
        double local[3];
        double reflection;
    };
    std::array<Bounce, max_depth + 1> bounces;
    auto keep = [&](int depth, const Colour& c) {
        bounces[depth].local[0] = c.x;
        bounces[depth].local[1] = c.y;
        bounces[depth].local[2] = c.z;
    };

    Vec3 o = origin;
    Vec3 d = unit_direction;
    double t_lower = t_min;
    Departure leaving;
    int last = 0;
    for (int depth = 0;; ++depth) {
        last = depth;
        bounces[depth].reflection = 0.0;
        ++rays;
        const SurfaceHit s = first_surface(geometry, o, d, t_lower,
                                           depth == 0 ? first_candidates : nullptr, leaving);
        if (s.kind != SurfaceHit::Kind::surface) {
            keep(depth, s.kind == SurfaceHit::Kind::miss ? miss_colour(scene, d) : Colour(0.0));
            break;
        }
        keep(depth, shade_surface(scene, s, d, sample, rays));
        const Finish& m = *primitive_material(scene, s.source).finish;
        if (depth >= depth_limit || !(m.reflection > 0.0)) break;
        bounces[depth].reflection = m.reflection;
        d = mirror(d, s.normal);
        o = s.lifted;
        t_lower = 0.0;
        leaving = {s.triangle, s.point};
    }
    auto local = [&](int k) {
        return Colour(bounces[k].local[0], bounces[k].local[1], bounces[k].local[2]);
    };
    Colour c = local(last);
    for (int k = last - 1; k >= 0; --k) c = local(k) + bounces[k].reflection * c;
    return c;
}

}  // namespace jt
