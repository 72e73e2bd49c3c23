#pragma once
// Small scenes built in code, for tests whose expected pixels are worked out by
// hand from docs/language.md.

#include "jtracer/image.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>

#include <random>

namespace jt::test {

inline Camera camera_at(const Vec3& position, const Vec3& look_at, const Vec3& up = {0, 1, 0},
                        double fov = 45.0, double aspect = 1.0) {
    Camera c;
    c.position = position;
    c.look_at = look_at;
    c.up = up;
    c.fov = fov;
    c.aspect = aspect;
    return c;
}

inline Scene scene_with_camera(const Camera& camera, int width = 1, int height = 1) {
    Scene s;
    s.settings.width = width;
    s.settings.height = height;
    s.cameras.push_back(camera);
    return s;
}

inline Primitive sphere(const Vec3& center, double radius, const Material& m = {}) {
    return Primitive{Sphere{center, radius}, m, {}};
}

inline Primitive plane(const Vec3& normal, double distance, const Material& m = {}) {
    return Primitive{Plane{normal, distance}, m, {}};
}

inline Primitive cylinder(double radius, double height, const Material& m = {}) {
    return Primitive{Cylinder{radius, height}, m, {}};
}

inline TransformOp translate(const Vec3& v) {
    return {TransformKind::translate, v, 0.0};
}
inline TransformOp scale(const Vec3& v) {
    return {TransformKind::scale, v, 0.0};
}
inline TransformOp rotate(TransformKind axis, double degrees) {
    return {axis, Vec3(0.0), degrees};
}

inline Material matte(const Colour& pigment, const Colour& diffuse = Colour(1.0)) {
    Material m;
    m.pigment = pigment;
    m.finish.edit().diffuse = diffuse;
    return m;
}

// Material that shows pigment * ambient_light exactly, whatever the lights.
inline Material glowing(const Colour& pigment) {
    Material m;
    m.pigment = pigment;
    m.finish.edit().ambient = Colour(1.0);
    return m;
}

inline Image8 render(const Scene& scene, int samples = 1, int threads = 0) {
    RenderOptions o = render_options_for(scene);
    o.samples = samples;
    o.threads = threads;
    return render_image(prepare_scene(scene).value(), o);
}

struct Rgb {
    int r, g, b;
    bool operator==(const Rgb&) const = default;
};

inline Rgb at(const Image8& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}

inline Rgb expected(const Colour& c) {
    return {quantize_channel(c.x), quantize_channel(c.y), quantize_channel(c.z)};
}

inline std::ostream& operator<<(std::ostream& os, const Rgb& c) {
    return os << "(" << c.r << ", " << c.g << ", " << c.b << ")";
}

// A random unit vector at right angles to `v`.
template <class Random>
Vec3 across(const Vec3& v, Random& rng) {
    std::normal_distribution<double> n;
    Vec3 u;
    do {
        const Vec3 w{n(rng), n(rng), n(rng)};
        u = w - (glm::dot(w, v) / glm::dot(v, v)) * v;
    } while (!(glm::dot(u, u) > 1e-6));
    return glm::normalize(u);
}

// `count` shapes scattered in [-extent, extent]^3, sizes up to `max_size`:
// every third a plain sphere, the others an ellipsoid (a transformed sphere)
// or a transformed cylinder. A crowd for checking ray queries against each other.
inline Scene random_crowd(std::mt19937& rng, int count, double extent, double max_size) {
    std::uniform_real_distribution<double> u(-extent, extent), r(0.1, max_size), angle(0.0, 360.0);
    Scene scene;
    for (int i = 0; i < count; ++i) {
        Primitive p =
            i % 3 == 2 ? cylinder(r(rng), 2 * r(rng)) : sphere({u(rng), u(rng), u(rng)}, r(rng));
        if (i % 3 != 0)
            p.transforms = {
                scale({r(rng), r(rng), r(rng)}), rotate(TransformKind::xrotate, angle(rng)),
                rotate(TransformKind::yrotate, angle(rng)), translate({u(rng), u(rng), u(rng)})};
        scene.primitives.push_back(p);
    }
    return scene;
}

}  // namespace jt::test
