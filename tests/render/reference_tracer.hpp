#pragma once
// An independent, deliberately plain renderer of docs/language.md sections 5-8, for
// the differential test: one ray through each pixel centre, every ray tested
// against every primitive in that primitive's own object space, in double
// precision; no acceleration structure, no tables, no tiles, no code shared
// with the core (only the Scene values and glm's vector arithmetic).
//
// Secondary rays start exactly on the surface: the root of the ray's own
// primitive at the start point is removed algebraically (the other root of a
// quadratic through a known root), not by an offset.
//
// Besides its colour, each pixel says whether its bytes are numerically
// ambiguous: whether errors of the size any double-precision renderer makes
// could change them. A pixel is ambiguous when
// - its colour changes under a perturbation of the primary ray far above
//   rounding (1e-8 radians along each of the camera's right and up axes, both
//   ways: whatever edge passes within that of the ray, in any direction, lies
//   between two of the four rays), or when secondary rays start 1e-7 of the
//   scene's magnitude off the surface instead of on it (the offsets renderers
//   use lie between);
// - a channel lies within 1e-6 of a rounding boundary of the 0..255 scale;
// - two surfaces lie within 1e-8 (relative) of each other along one of its
//   rays, or a secondary ray meets another surface within 1e-6 (relative) of
//   its start: coincident or touching surfaces, where the nearest hit or the
//   shadow is a matter of rounding.

#include "jtracer/image.hpp"
#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace jt::reference {

// p -> linear * p + translation
struct Map {
    glm::dmat3 linear{1.0};
    Vec3 translation{0.0};
};

// p -> second(first(p))
inline Map then(const Map& first, const Map& second) {
    return {second.linear * first.linear, second.linear * first.translation + second.translation};
}

inline glm::dmat3 rotation(TransformKind axis, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    glm::dmat3 m(1.0);  // m[column][row]
    int i = 0, j = 1;   // the plane turned: +i toward +j
    if (axis == TransformKind::xrotate) i = 1, j = 2;
    if (axis == TransformKind::yrotate) i = 2, j = 0;
    m[i][i] = c;
    m[i][j] = s;
    m[j][i] = -s;
    m[j][j] = c;
    return m;
}

inline Map op_map(const TransformOp& op) {
    Map m;
    if (op.kind == TransformKind::translate)
        m.translation = op.vector;
    else if (op.kind == TransformKind::scale)
        m.linear = glm::dmat3(glm::dvec3(op.vector.x, 0, 0), glm::dvec3(0, op.vector.y, 0),
                              glm::dvec3(0, 0, op.vector.z));
    else
        m.linear = rotation(op.kind, op.degrees);
    return m;
}

inline Map op_inverse(const TransformOp& op) {
    Map m;
    if (op.kind == TransformKind::translate)
        m.translation = -op.vector;
    else if (op.kind == TransformKind::scale)
        m.linear = glm::dmat3(glm::dvec3(1 / op.vector.x, 0, 0), glm::dvec3(0, 1 / op.vector.y, 0),
                              glm::dvec3(0, 0, 1 / op.vector.z));
    else
        m.linear = rotation(op.kind, -op.degrees);
    return m;
}

inline Map to_world(const std::vector<TransformOp>& ops) {
    Map m;
    for (const TransformOp& op : ops) m = then(m, op_map(op));
    return m;
}

inline Map to_object(const std::vector<TransformOp>& ops) {
    Map m;
    for (const TransformOp& op : ops) m = then(op_inverse(op), m);
    return m;
}

// docs/language.md §5.5: a scale with a zero component leaves the primitive out.
inline bool flattened(const std::vector<TransformOp>& ops) {
    for (const TransformOp& op : ops)
        if (op.kind == TransformKind::scale &&
            (op.vector.x == 0 || op.vector.y == 0 || op.vector.z == 0))
            return true;
    return false;
}

inline double max_abs(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb8&) const = default;
};

struct ReferenceImage {
    Image8 image;
    std::vector<bool> ambiguous;  // per pixel, row 0 at the bottom
    // Per pixel and channel, the least and greatest value any of the pixel's
    // variant rays gave: an ambiguous pixel's bytes are expected within.
    std::vector<std::array<std::uint8_t, 6>> range;
};

class Tracer {
  public:
    explicit Tracer(const Scene& scene) : scene_(scene) {
        for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
            const Primitive& p = scene.primitives[i];
            if (flattened(p.transforms)) continue;
            Placed q;
            q.index = i;
            q.shape = &p.shape;
            q.material = &p.material;
            const Map inverse = to_object(p.transforms);
            q.world_to_object = inverse;
            q.normal_matrix = glm::transpose(inverse.linear);
            if (const auto* plane = std::get_if<Plane>(&p.shape))
                q.unit_normal = plane->normal / std::sqrt(glm::dot(plane->normal, plane->normal));
            placed_.push_back(q);
        }
    }

    ReferenceImage render(int camera_index) const {
        const Camera& camera = scene_.cameras[camera_index];
        const int w = scene_.settings.width, h = scene_.settings.height;
        const Vec3 f = glm::normalize(camera.look_at - camera.position);
        const Vec3 r = glm::normalize(glm::cross(f, camera.up));
        const Vec3 u = glm::cross(r, f);
        const double t = std::tan(camera.fov / 2 * std::numbers::pi / 180);
        ReferenceImage out;
        out.image = Image8(w, h);
        out.ambiguous.assign(static_cast<std::size_t>(w) * h, false);
        out.range.resize(static_cast<std::size_t>(w) * h);
        constexpr double turn = 1e-8;
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                const double sx = (2 * (i + 0.5) / w - 1) * t * camera.aspect;
                const double sy = (2 * (j + 0.5) / h - 1) * t;
                const Vec3 d = glm::normalize(f + sx * r + sy * u);
                Flags flags;
                const Rgb8 centre = quantize(trace(camera.position, d, 0, {}, 0.0, false, flags));
                bool ambiguous = flags.ambiguous || near_rounding_boundary(flags.colour);
                std::array<std::uint8_t, 6> range = {centre.r, centre.g, centre.b,
                                                     centre.r, centre.g, centre.b};
                auto variant = [&](const Vec3& direction, bool lifted) {
                    Flags ignored;
                    Rgb8 c =
                        quantize(trace(camera.position, direction, 0, {}, 0.0, lifted, ignored));
                    if (!(c == centre)) ambiguous = true;
                    const std::uint8_t v[3] = {c.r, c.g, c.b};
                    for (int k = 0; k < 3; ++k) {
                        range[k] = std::min(range[k], v[k]);
                        range[3 + k] = std::max(range[3 + k], v[k]);
                    }
                };
                variant(d, true);
                for (const Vec3& axis : {r, u})
                    for (double sign : {-1.0, 1.0})
                        variant(glm::normalize(d + sign * turn * axis), false);
                std::uint8_t* p = out.image.pixel(i, j);
                p[0] = centre.r;
                p[1] = centre.g;
                p[2] = centre.b;
                out.ambiguous[static_cast<std::size_t>(j) * w + i] = ambiguous;
                out.range[static_cast<std::size_t>(j) * w + i] = range;
            }
        }
        return out;
    }

  private:
    struct Placed {
        std::size_t index = 0;
        const Shape* shape = nullptr;
        const Material* material = nullptr;
        Map world_to_object;
        glm::dmat3 normal_matrix{1.0};
        Vec3 unit_normal{0.0};  // planes
    };

    // Where a ray starts: on surface `part` of placed primitive `placed`, or
    // nowhere (placed < 0) for a primary or lifted ray.
    struct Origin {
        int placed = -1;
        int part = 0;  // sphere 0; cylinder side 0, bottom 1, top 2; plane 0
    };

    struct Hit {
        double t = INFINITY;
        int placed = -1;
        int part = 0;
        Vec3 object_normal{0.0};
    };

    struct Flags {
        bool ambiguous = false;
        Colour colour{0.0};  // the unclamped colour of the primary ray
    };

    static Rgb8 quantize(const Colour& c) {
        auto q = [](double v) {
            return static_cast<std::uint8_t>(std::floor(std::clamp(v, 0.0, 1.0) * 255 + 0.5));
        };
        return {q(c.x), q(c.y), q(c.z)};
    }

    static bool near_rounding_boundary(const Colour& c) {
        for (int k = 0; k < 3; ++k) {
            const double v = std::clamp(c[k], 0.0, 1.0) * 255 + 0.5;
            const double fraction = v - std::floor(v);
            if (v > 0.5 && v < 255.5 && (fraction < 1e-6 || fraction > 1 - 1e-6)) return true;
        }
        return false;
    }

    // Every root t > 0 of the ray with primitive q, except the ray's own start.
    template <class Visit>
    void roots(int which, const Vec3& world_origin, const Vec3& world_direction, const Origin& from,
               Visit visit) const {
        const Placed& q = placed_[which];
        const Vec3 o = q.world_to_object.linear * world_origin + q.world_to_object.translation;
        const Vec3 d = q.world_to_object.linear * world_direction;
        const bool own = from.placed == which;
        auto offer = [&](double t, int part, const Vec3& normal) {
            if (t > 0 && std::isfinite(t)) visit(t, part, normal);
        };
        if (const auto* sphere = std::get_if<Sphere>(q.shape)) {
            const Vec3 f = o - sphere->center;
            const double a = glm::dot(d, d), b = glm::dot(f, d);
            if (own) {  // roots 0 and -2b/a
                const double t = -2 * b / a;
                offer(t, 0, f + t * d);
                return;
            }
            const Vec3 perpendicular = f - (b / a) * d;
            const double h2 =
                sphere->radius * sphere->radius - glm::dot(perpendicular, perpendicular);
            if (h2 < 0) return;
            const double half = std::sqrt(h2 / a);
            for (double t : {-b / a - half, -b / a + half}) offer(t, 0, f + t * d);
        } else if (const auto* cylinder = std::get_if<Cylinder>(q.shape)) {
            const double r = cylinder->radius, height = cylinder->height;
            const double a = d.x * d.x + d.z * d.z, b = o.x * d.x + o.z * d.z;
            auto side = [&](double t) {
                const double y = o.y + t * d.y;
                if (y >= 0 && y <= height) offer(t, 0, {o.x + t * d.x, 0, o.z + t * d.z});
            };
            if (a > 0) {
                if (own && from.part == 0) {
                    side(-2 * b / a);
                } else {
                    const double px = o.x - (b / a) * d.x, pz = o.z - (b / a) * d.z;
                    const double h2 = r * r - (px * px + pz * pz);
                    if (h2 >= 0) {
                        const double half = std::sqrt(h2 / a);
                        side(-b / a - half);
                        side(-b / a + half);
                    }
                }
            }
            for (int part : {1, 2}) {
                if ((own && from.part == part) || d.y == 0) continue;
                const double y = part == 1 ? 0.0 : height;
                const double t = (y - o.y) / d.y;
                const double x = o.x + t * d.x, z = o.z + t * d.z;
                if (x * x + z * z <= r * r) offer(t, part, {0, part == 1 ? -1.0 : 1.0, 0});
            }
        } else if (const auto* plane = std::get_if<Plane>(q.shape)) {
            if (own) return;
            const double denominator = glm::dot(q.unit_normal, d);
            if (denominator == 0) return;
            offer((plane->distance - glm::dot(q.unit_normal, o)) / denominator, 0, q.unit_normal);
        }
    }

    // The nearest hit; equal distances go to the lower primitive index.
    Hit nearest(const Vec3& o, const Vec3& d, const Origin& from, double magnitude,
                Flags& flags) const {
        Hit best;
        double second = INFINITY;
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            roots(k, o, d, from, [&](double t, int part, const Vec3& normal) {
                if (from.placed >= 0 && t < 1e-6 * magnitude) flags.ambiguous = true;
                if (t < best.t) {
                    second = best.t;
                    best = {t, k, part, normal};
                } else {
                    second = std::min(second, t);
                }
            });
        }
        if (second - best.t <= 1e-8 * std::max(best.t, magnitude)) flags.ambiguous = true;
        return best;
    }

    bool blocked(const Vec3& o, const Vec3& d, double distance, const Origin& from,
                 double magnitude, Flags& flags) const {
        bool any = false;
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            roots(k, o, d, from, [&](double t, int, const Vec3&) {
                if (from.placed >= 0 && t < 1e-6 * magnitude) flags.ambiguous = true;
                if (std::abs(t - distance) <= 1e-8 * magnitude) flags.ambiguous = true;
                if (t < distance) any = true;
            });
        }
        return any;
    }

    // docs/language.md §8.5. `lifted`: secondary rays start 1e-7 of the magnitude off
    // the surface and meet every surface, their own included.
    Colour trace(const Vec3& o, const Vec3& d, int depth, const Origin& from, double magnitude,
                 bool lifted, Flags& flags) const {
        const Hit hit = nearest(o, d, from, magnitude, flags);
        if (hit.placed < 0) {
            if (depth == 0) flags.colour = scene_.settings.background;
            return scene_.settings.background;
        }
        const Placed& q = placed_[hit.placed];
        const Material& m = *q.material;
        const Vec3 p = o + hit.t * d;
        Vec3 n = glm::normalize(q.normal_matrix * hit.object_normal);
        if (glm::dot(n, d) > 0) n = -n;
        const Vec3 v = -d;
        const double scale = std::max({max_abs(o), max_abs(p), hit.t});
        const Origin here = lifted ? Origin{} : Origin{hit.placed, hit.part};
        const Vec3 start = lifted ? p + 1e-7 * scale * n : p;

        Colour c = scene_.settings.ambient_light * m.ambient * m.pigment;
        for (const PointLight& light : scene_.lights) {
            const Vec3 l = glm::normalize(light.position - p);
            const double n_dot_l = glm::dot(n, l);
            if (n_dot_l <= 0) continue;
            const Vec3 to_light = light.position - start;
            const double distance = glm::length(to_light);
            if (blocked(start, to_light / distance, distance, here, scale, flags)) continue;
            c += light.intensity * m.diffuse * m.pigment * std::pow(n_dot_l, 1 / m.diffuse_k);
            const Vec3 reflected = 2 * n_dot_l * n - l;
            const double r_dot_v = glm::dot(reflected, v);
            if (r_dot_v > 0) c += light.intensity * m.specular * std::pow(r_dot_v, m.specular_k);
        }
        if (depth < scene_.settings.recurse_depth && m.reflection > 0) {
            const Vec3 mirrored = glm::normalize(d - 2 * glm::dot(d, n) * n);
            c += m.reflection * trace(start, mirrored, depth + 1, here, scale, lifted, flags);
        }
        if (depth == 0) flags.colour = c;
        return c;
    }

    const Scene& scene_;
    std::vector<Placed> placed_;
};

// The camera docs/language.md §7.1 says renders: the one named by active_camera, else the first.
inline int active_camera(const Scene& scene) {
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (!scene.settings.active_camera.empty() &&
            scene.cameras[i].name == scene.settings.active_camera)
            return static_cast<int>(i);
    return 0;
}

inline ReferenceImage render(const Scene& scene) {
    return Tracer(scene).render(active_camera(scene));
}

}  // namespace jt::reference
