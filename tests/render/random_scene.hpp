#pragma once
// Random valid scenes for the differential test, as a Scene and as the .jts
// text that means it (numbers written with 17 significant digits, so the text
// parses back to the same doubles).
//
// A scene has a size W from 1e-3 to 1e3 (log-uniform): cameras, lights and
// primitives are placed in units of W, so that something is in view at any
// size. Every primitive kind; 0-5 transform ops in one or two blocks, in any
// order, with rotations (some by multiples of 90 degrees), translations and
// scales whose components run from 1e-3 to 1e3 (mostly near-uniform, some
// stretched, some mirrored); now and then a scale with a zero component. A
// primitive's own size and position (or one of its translations) are chosen
// after its ops, so that it lands in view at a size near W whatever the ops.
// Materials use every property; one or two cameras, 0-3 lights, reflections up
// to depth 4; one scene in four has 9-30 primitives, more than a BVH-less
// render tests one by one.

#include "reference_tracer.hpp"

#include "jtracer/scene.hpp"

#include <glm/matrix.hpp>

#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

namespace jt::test {

struct RandomScene {
    Scene scene;
    std::string text;
    int flattened = 0;  // primitives with a zero scale component
};

class SceneGenerator {
  public:
    explicit SceneGenerator(std::uint64_t seed) : rng_(seed) {}

    RandomScene generate() {
        RandomScene out;
        Scene& s = out.scene;
        size_ = log_uniform(1e-3, 1e3);
        s.settings.width = integer(16, 48);
        s.settings.height = integer(12, 36);
        s.settings.recurse_depth = chance(0.4) ? 0 : integer(1, 4);
        if (chance(0.5)) s.settings.background = colour();
        if (chance(0.6)) s.settings.ambient_light = colour();
        const int cameras = chance(0.3) ? 2 : 1;
        for (int i = 0; i < cameras; ++i) s.cameras.push_back(camera(i, s.settings));
        if (chance(0.5)) s.settings.active_camera = s.cameras[integer(0, cameras - 1)].name;
        const int lights = chance(0.1) ? 0 : integer(1, 3);
        for (int i = 0; i < lights; ++i) s.lights.push_back({size_ * point(5.0), bright_colour()});
        const int primitives = chance(0.25) ? integer(9, 30) : integer(2, 8);
        int planes = 0;
        for (int i = 0; i < primitives; ++i) {
            const double kind = uniform(0, 1);
            // Built with its shape: assigning one over a default Sphere makes
            // GCC 12 warn falsely about the Mesh alternative's string.
            const bool plane = kind < 0.15 && planes < 2;
            if (plane) ++planes;
            Primitive p{plane ? Shape(Plane{}) : kind < 0.5 ? Shape(Cylinder{}) : Shape(Sphere{}),
                        {}, {}};
            p.material = material();
            p.transforms = transforms();
            if (reference::flattened(p.transforms)) ++out.flattened;
            place(p);
            s.primitives.push_back(p);
        }
        out.text = text(s);
        return out;
    }

  private:
    double uniform(double a, double b) {
        return std::uniform_real_distribution<double>(a, b)(rng_);
    }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
    bool chance(double p) { return uniform(0, 1) < p; }
    double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
    Colour colour() { return {uniform(0, 1), uniform(0, 1), uniform(0, 1)}; }
    Colour bright_colour() { return {uniform(0.3, 1), uniform(0.3, 1), uniform(0.3, 1)}; }
    Vec3 point(double extent) {
        return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
    }
    Vec3 direction() {
        for (;;) {
            Vec3 v = point(1.0);
            double length = glm::length(v);
            if (length > 0.1 && length <= 1.0) return v / length;
        }
    }

    Camera camera(int i, const RenderSettings& settings) {
        Camera c;
        c.name = "camera" + std::to_string(i);
        c.position = size_ * uniform(2.0, 5.0) * direction();
        c.look_at = size_ * point(0.3);
        const Vec3 view = glm::normalize(c.look_at - c.position);
        do {
            c.up = direction() * uniform(0.5, 2.0);
        } while (glm::length(glm::cross(view, glm::normalize(c.up))) < 0.2);
        c.fov = uniform(25, 90);
        c.aspect =
            chance(0.7) ? static_cast<double>(settings.width) / settings.height : uniform(0.5, 2.0);
        return c;
    }

    Material material() {
        Material m;
        m.pigment = bright_colour();
        if (chance(0.5)) m.ambient = colour();
        if (chance(0.85)) m.diffuse = bright_colour();
        if (chance(0.5)) m.specular = colour();
        if (chance(0.5)) m.diffuse_k = log_uniform(0.3, 4.0);
        m.specular_k = log_uniform(1.0, 300.0);
        if (chance(0.4)) m.reflection = chance(0.2) ? 1.0 : uniform(0, 1);
        return m;
    }

    // A scale's components: near-uniform, now and then stretched along each
    // axis anywhere in 1e-3..1e3, sometimes mirrored.
    Vec3 scale_vector(bool& stretched) {
        const double base = log_uniform(1e-3, 1e3);
        Vec3 v;
        const bool stretch = !stretched && chance(0.1);
        stretched = stretched || stretch;
        for (int k = 0; k < 3; ++k) {
            v[k] = stretch ? log_uniform(1e-3, 1e3)
                           : std::clamp(base * log_uniform(0.3, 3.0), 1e-3, 1e3);
            if (chance(0.1)) v[k] = -v[k];
        }
        if (chance(0.4)) v = Vec3(v.x);
        return v;
    }

    std::vector<TransformOp> transforms() {
        std::vector<TransformOp> ops;
        if (chance(0.25)) return ops;
        const int count = integer(1, 5);
        bool stretched = false;
        for (int i = 0; i < count; ++i) {
            const double kind = uniform(0, 1);
            TransformOp op;
            if (kind < 0.3) {
                op.kind = TransformKind::translate;
                op.vector = size_ * point(1.0);
            } else if (kind < 0.6) {
                op.kind = TransformKind::scale;
                op.vector = scale_vector(stretched);
            } else {
                const TransformKind axes[] = {TransformKind::xrotate, TransformKind::yrotate,
                                              TransformKind::zrotate};
                op.kind = axes[integer(0, 2)];
                op.degrees = chance(0.25) ? 90.0 * integer(-4, 4) : uniform(-360, 360);
            }
            ops.push_back(op);
        }
        if (chance(0.12)) {  // flattened: one or more components zero, anywhere in the list
            TransformOp zero{TransformKind::scale, scale_vector(stretched), 0.0};
            zero.vector[integer(0, 2)] = chance(0.5) ? 0.0 : -0.0;
            if (chance(0.2)) zero.vector[integer(0, 2)] = 0.0;
            ops.insert(ops.begin() + integer(0, static_cast<int>(ops.size())), zero);
        }
        return ops;
    }

    // Sizes and positions chosen through the ops: the primitive appears at a
    // random point within about 1.2 W of the origin, its size 0.2-1.2 W.
    // A flattened primitive is placed as if its zeros were ones, so that it
    // would be in view if it were not left out.
    void place(Primitive& p) {
        std::vector<TransformOp> unflattened = p.transforms;
        for (TransformOp& op : unflattened)
            if (op.kind == TransformKind::scale)
                for (int k = 0; k < 3; ++k)
                    if (op.vector[k] == 0.0) op.vector[k] = 1.0;
        const Vec3 target = size_ * point(1.2);
        const reference::Map world = reference::to_world(unflattened);
        const reference::Map object = reference::to_object(unflattened);
        const double gain = std::cbrt(std::abs(glm::determinant(world.linear)));
        const double size = size_ * log_uniform(0.2, 1.2) / gain;
        if (auto* sphere = std::get_if<Sphere>(&p.shape)) {
            sphere->radius = size;
            sphere->center = object.linear * target + object.translation;
        } else if (auto* cylinder = std::get_if<Cylinder>(&p.shape)) {
            cylinder->radius = size;
            cylinder->height = size * uniform(0.5, 3.0);
            aim_a_translation(p.transforms, unflattened, target);
        } else if (auto* plane = std::get_if<Plane>(&p.shape)) {
            plane->normal = direction() * uniform(0.5, 2.0);
            const Vec3 through = chance(0.5) ? target : size_ * point(3.0);
            const Vec3 on = object.linear * through + object.translation;
            plane->distance = glm::dot(plane->normal / glm::length(plane->normal), on);
        }
    }

    // Sets (or inserts) one translate op so that the object origin lands on
    // `target` through `unflattened` (ops with any zero scale component made 1).
    void aim_a_translation(std::vector<TransformOp>& ops, std::vector<TransformOp> unflattened,
                           const Vec3& target) {
        std::vector<int> translations;
        for (int k = 0; k < static_cast<int>(ops.size()); ++k)
            if (ops[k].kind == TransformKind::translate) translations.push_back(k);
        int k;
        if (translations.empty() || chance(0.2)) {
            k = integer(0, static_cast<int>(ops.size()));
            const TransformOp zero{TransformKind::translate, Vec3(0.0), 0.0};
            ops.insert(ops.begin() + k, zero);
            unflattened.insert(unflattened.begin() + k, zero);
        } else {
            k = translations[integer(0, static_cast<int>(translations.size()) - 1)];
        }
        const std::vector<TransformOp> before(unflattened.begin(), unflattened.begin() + k);
        const std::vector<TransformOp> after(unflattened.begin() + k + 1, unflattened.end());
        const reference::Map undo_after = reference::to_object(after);
        ops[k].vector = undo_after.linear * target + undo_after.translation -
                        reference::to_world(before).translation;
    }

    // .jts text, with the scene's parts spread over blocks as a person might:
    // a primitive's material or transform list sometimes split in two blocks,
    // properties at their default sometimes left out, lights among the primitives.
    std::string text(const Scene& s) {
        std::string t = "render_settings { width: " + std::to_string(s.settings.width) +
                        "; height: " + std::to_string(s.settings.height) +
                        "; recurse_depth: " + std::to_string(s.settings.recurse_depth) +
                        "; background: " + vec(s.settings.background) +
                        "; ambient_light: " + vec(s.settings.ambient_light) + ";";
        if (!s.settings.active_camera.empty())
            t += " active_camera: \"" + s.settings.active_camera + "\";";
        t += " }\ncameras {\n";
        for (const Camera& c : s.cameras)
            t += "  perspective_camera { name: \"" + c.name + "\"; position: " + vec(c.position) +
                 "; look_at: " + vec(c.look_at) + "; up: " + vec(c.up) + "; fov: " + num(c.fov) +
                 "; aspect: " + num(c.aspect) + "; }\n";
        t += "}\nscene {\n";
        std::size_t light = 0;
        for (const Primitive& p : s.primitives) {
            while (light < s.lights.size() && chance(0.3)) t += light_text(s.lights[light++]);
            t += primitive_text(p);
        }
        while (light < s.lights.size()) t += light_text(s.lights[light++]);
        return t + "}\n";
    }

    static std::string num(double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", v);
        return buffer;
    }
    static std::string vec(const Vec3& v) {
        return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">";
    }

    std::string light_text(const PointLight& l) {
        return "  point_light { position: " + vec(l.position) + "; intensity: " + vec(l.intensity) +
               "; }\n";
    }

    std::string primitive_text(const Primitive& p) {
        std::string t;
        auto property = [&](const char* name, const std::string& value, bool is_default) {
            if (!is_default || chance(0.5)) t += std::string(name) + ": " + value + "; ";
        };
        if (const auto* sphere = std::get_if<Sphere>(&p.shape)) {
            t = "  sphere { ";
            property("center", vec(sphere->center), sphere->center == Vec3(0.0));
            property("radius", num(sphere->radius), sphere->radius == 1.0);
        } else if (const auto* cylinder = std::get_if<Cylinder>(&p.shape)) {
            t = "  cylinder { ";
            property("radius", num(cylinder->radius), false);
            property("height", num(cylinder->height), false);
        } else if (const auto* plane = std::get_if<Plane>(&p.shape)) {
            t = "  plane { ";
            property("normal", vec(plane->normal), false);
            property("distance", num(plane->distance), false);
        }
        const Material& m = p.material;
        const Material d;
        const bool split = chance(0.3);
        t += "material { ";
        int written = 0;
        auto material_property = [&](const char* name, const std::string& value, bool is_default) {
            if (split && written == 3) t += "} material { ";
            ++written;
            property(name, value, is_default);
        };
        material_property("pigment", vec(m.pigment), m.pigment == d.pigment);
        material_property("ambient", vec(m.ambient), m.ambient == d.ambient);
        material_property("diffuse", vec(m.diffuse), m.diffuse == d.diffuse);
        material_property("specular", vec(m.specular), m.specular == d.specular);
        material_property("diffuse_k", num(m.diffuse_k), m.diffuse_k == d.diffuse_k);
        material_property("specular_k", num(m.specular_k), m.specular_k == d.specular_k);
        material_property("reflection", num(m.reflection), m.reflection == d.reflection);
        t += "} ";
        if (!p.transforms.empty()) {
            const std::size_t split_at =
                chance(0.3) ? integer(1, static_cast<int>(p.transforms.size())) : 0;
            t += "transform { ";
            for (std::size_t k = 0; k < p.transforms.size(); ++k) {
                if (k == split_at && k > 0) t += "} transform { ";
                const TransformOp& op = p.transforms[k];
                switch (op.kind) {
                    case TransformKind::translate:
                        t += "translate: " + vec(op.vector);
                        break;
                    case TransformKind::scale:
                        t += "scale: " + vec(op.vector);
                        break;
                    case TransformKind::xrotate:
                        t += "xrotate: " + num(op.degrees);
                        break;
                    case TransformKind::yrotate:
                        t += "yrotate: " + num(op.degrees);
                        break;
                    case TransformKind::zrotate:
                        t += "zrotate: " + num(op.degrees);
                        break;
                }
                t += "; ";
            }
            t += "} ";
        }
        return t + "}\n";
    }

    std::mt19937_64 rng_;
    double size_ = 1.0;
};

inline RandomScene random_scene(std::uint64_t seed) {
    return SceneGenerator(seed).generate();
}

}  // namespace jt::test
