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
//
// With the extensions of docs/language.md §13 (random_scene_1_1), triangles and
// meshes join them, with the files they name: triangles sometimes glass
// (transmission, ior) and mirrored, sometimes image-mapped with a BMP stored
// top-down or bottom-up; meshes (an octahedron or a tetrahedron from an OBJ),
// flat or smooth with vertex normals that may lean far from the faces, each
// placed so that one pixel's centre ray meets one of its vertices or the middle
// of one of its edges exactly.
//
// With the features of docs/language.md §14 (random_scene_1_2, each feature on
// its own or together): lights with a radius and 1-6 shadow samples (some with
// shadow_samples but radius 0); cameras with a lens, with or without a focus
// distance, rendered with 1-4 samples on smaller images; a sky map (a BMP of a
// few texels); meshes without normals, smooth with a smooth_angle (often 0,
// 60 or 180), some with every face's corners written apart as STL does, some
// flat with a smooth_angle that does nothing; meshes with materials: "file",
// an OBJ whose runs of faces take 1-3 materials' Kd or the mesh's own.

#include "reference_tracer.hpp"

#include "jtracer/scene.hpp"

#include <glm/matrix.hpp>

#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <random>
#include <string>

namespace jt::test {

// The features of docs/language.md §14 a generated scene may use.
struct Features {
    bool soft_shadows = false;       // lights with a radius (§14.1)
    bool lens = false;               // cameras with an aperture (§14.2)
    bool sky = false;                // a background map (§14.3)
    bool generated_normals = false;  // meshes without normals, smooth_angle (§14.4)
    bool file_materials = false;     // meshes with materials: "file", an OBJ's Kd (§14.5)
};

struct RandomScene {
    Scene scene;
    std::string text;
    int flattened = 0;                              // primitives with a zero scale component
    reference::Files files;                         // what the reference knows of them
    std::map<std::string, std::string> file_bytes;  // the files, by name, for the core
};

class SceneGenerator {
  public:
    SceneGenerator(std::uint64_t seed, bool extensions, Features features = {})
        : rng_(seed), extensions_(extensions), features_(features) {}

    RandomScene generate() {
        RandomScene out;
        Scene& s = out.scene;
        size_ = log_uniform(1e-3, 1e3);
        s.settings.width = integer(16, 48);
        s.settings.height = integer(12, 36);
        if (features_.lens || features_.soft_shadows) {
            // Several samples a pixel on a smaller image, to keep a seed quick.
            s.settings.samples = chance(0.3) ? 1 : integer(2, 4);
            s.settings.width = std::max(8, s.settings.width * 2 / (1 + s.settings.samples));
            s.settings.height = std::max(6, s.settings.height * 2 / (1 + s.settings.samples));
        }
        if (features_.sky && chance(0.7)) s.settings.background_map = picture();
        s.settings.recurse_depth = chance(0.4) ? 0 : integer(1, 4);
        if (chance(0.5)) s.settings.background = colour();
        if (chance(0.6)) s.settings.ambient_light = colour();
        const int cameras = chance(0.3) ? 2 : 1;
        for (int i = 0; i < cameras; ++i) s.cameras.push_back(camera(i, s.settings));
        if (chance(0.5)) s.settings.active_camera = s.cameras[integer(0, cameras - 1)].name;
        const int lights = chance(0.1) ? 0 : integer(1, 3);
        for (int i = 0; i < lights; ++i) {
            s.lights.push_back({size_ * point(5.0), bright_colour()});
            if (!features_.soft_shadows) continue;
            if (chance(0.4)) s.lights.back().radius = size_ * log_uniform(0.05, 1.0);
            if (s.lights.back().radius > 0 || chance(0.2))
                s.lights.back().shadow_samples = integer(1, 6);
        }
        const int primitives = chance(0.25) ? integer(9, 30) : integer(2, 8);
        int planes = 0;
        for (int i = 0; i < primitives; ++i) {
            // Drawn again when the ops shrink it so much that its own size
            // or place passes the language's limit of 1e9.
            Primitive p;
            do {
                if (extensions_ && chance(0.5)) {
                    p = chance(0.5) ? triangle() : mesh(out, s);
                    continue;
                }
                const double kind = uniform(0, 1);
                // Built with its shape: assigning one over a default Sphere makes
                // GCC 12 warn falsely about the Mesh alternative's string.
                const bool plane = kind < 0.15 && planes < 2;
                p = Primitive{plane        ? Shape(Plane{})
                              : kind < 0.5 ? Shape(Cylinder{})
                                           : Shape(Sphere{}),
                              {},
                              {}};
                p.material = material();
                p.transforms = transforms();
                place(p);
            } while (!within_limits(p));
            if (shape_is<Plane>(p.shape)) ++planes;
            if (reference::flattened(p.transforms)) ++out.flattened;
            s.primitives.push_back(p);
        }
        out.text = text(s);
        for (auto& [name, pic] : pending_pictures_) {
            out.file_bytes[name] = bmp_bytes(pic, name.find("top-down") != std::string::npos);
            out.files.pictures[name] = std::move(pic);
        }
        return out;
    }

    // A 24-bit BMP of the picture, written here (not by the core's writer):
    // rows padded to 4 bytes, bottom-up, or top-down with a negative height.
    static std::string bmp_bytes(const reference::Picture& pic, bool top_down) {
        const std::size_t stride = (3 * static_cast<std::size_t>(pic.width) + 3) & ~std::size_t{3};
        std::string b(54 + stride * pic.height, '\0');
        auto put = [&](std::size_t at, std::uint32_t v, int bytes) {
            for (int k = 0; k < bytes; ++k) b[at + k] = static_cast<char>(v >> (8 * k));
        };
        b[0] = 'B';
        b[1] = 'M';
        put(2, static_cast<std::uint32_t>(b.size()), 4);
        put(10, 54, 4);
        put(14, 40, 4);
        put(18, static_cast<std::uint32_t>(pic.width), 4);
        put(22, static_cast<std::uint32_t>(top_down ? -pic.height : pic.height), 4);
        put(26, 1, 2);
        put(28, 24, 2);
        for (int j = 0; j < pic.height; ++j) {
            const std::size_t row = 54 + stride * (top_down ? pic.height - 1 - j : j);
            for (int i = 0; i < pic.width; ++i)
                for (int c = 0; c < 3; ++c)  // BGR
                    b[row + 3 * i + c] = static_cast<char>(
                        pic.rgb[3 * (static_cast<std::size_t>(j) * pic.width + i) + 2 - c]);
        }
        return b;
    }

  private:
    // A triangle near a target, through its transform; some glass, some image-mapped.
    Primitive triangle() {
        Triangle t;
        Primitive p{t, material(), transforms()};
        if (chance(0.4)) {
            p.material.finish.edit().transmission = uniform(0.3, 1.0);
            p.material.finish.edit().ior = log_uniform(0.6, 2.2);
            if (chance(0.7)) p.transforms.push_back({TransformKind::scale, mirror_scale(), 0.0});
        }
        if (chance(0.3)) p.material.finish.edit().image_map = picture();
        const Vec3 target = size_ * point(1.2);
        const reference::Map object = reference::to_object(unflattened(p.transforms));
        auto corner = [&] {
            const Vec3 world = target + size_ * log_uniform(0.3, 1.5) * direction();
            return object.linear * world + object.translation;
        };
        auto& tri = shape_as<Triangle>(p.shape);
        do {
            tri.a = corner();
            tri.b = corner();
            tri.c = corner();
        } while (glm::length(glm::cross(tri.b - tri.a, tri.c - tri.a)) <
                 0.05 * glm::length(tri.b - tri.a) * glm::length(tri.c - tri.a));
        tri.uv_a = {uniform(-1, 2), uniform(-1, 2), 0};
        tri.uv_b = {uniform(-1, 2), uniform(-1, 2), 0};
        tri.uv_c = {uniform(-1, 2), uniform(-1, 2), 0};
        return p;
    }

    // The parts of a model with materials: "file": 1-3 materials with a Kd
    // of whole 256ths (exact in any reader's floats), runs of faces in them,
    // some faces in none; the .mtl text.
    std::string parts(reference::Model& m) {
        const int count = integer(1, 3);
        std::string mtl;
        for (int c = 0; c < count; ++c) {
            const Colour kd(integer(0, 256) / 256.0, integer(0, 256) / 256.0,
                            integer(0, 256) / 256.0);
            m.part_colours.push_back(kd);
            mtl += "newmtl m" + std::to_string(c) + "\nKd " + num(kd.x) + " " + num(kd.y) + " " +
                   num(kd.z) + "\n";
        }
        int part = chance(0.3) ? -1 : integer(0, count - 1);
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
            if (f > 0 && chance(0.4)) part = integer(-1, count - 1);
            m.face_part.push_back(part);
        }
        return mtl;
    }

    // Whether every number of the primitive is within the language's 1e9.
    static bool within_limits(const Primitive& p) {
        constexpr double limit = 1e9;
        auto fits = [&](const Vec3& v) { return reference::max_abs(v) <= limit; };
        bool ok = true;
        if (const auto* sphere = shape_if<Sphere>(&p.shape))
            ok = fits(sphere->center) && sphere->radius <= limit;
        else if (const auto* cylinder = shape_if<Cylinder>(&p.shape))
            ok = cylinder->radius <= limit && cylinder->height <= limit;
        else if (const auto* plane = shape_if<Plane>(&p.shape))
            ok = fits(plane->normal) && std::abs(plane->distance) <= limit;
        else if (const auto* t = shape_if<Triangle>(&p.shape))
            ok = fits(t->a) && fits(t->b) && fits(t->c);
        for (const TransformOp& op : p.transforms)
            ok = ok && fits(op.vector) && std::abs(op.degrees) <= limit;
        return ok;
    }

    // A scale with an odd number of negative components: a mirror.
    Vec3 mirror_scale() {
        Vec3 v(1.0);
        v[integer(0, 2)] = -1.0;
        if (chance(0.3)) v = -v;
        return v * log_uniform(0.5, 2.0);
    }

    // A picture of 2-6 x 2-5 random texels, written as a BMP stored bottom-up
    // or top-down; its name.
    std::string picture() {
        reference::Picture pic;
        pic.width = integer(2, 6);
        pic.height = integer(2, 5);
        for (int k = 0; k < 3 * pic.width * pic.height; ++k)
            pic.rgb.push_back(static_cast<std::uint8_t>(integer(0, 255)));
        const bool top_down = chance(0.5);
        const std::string name =
            "map" + std::to_string(pictures_++) + (top_down ? "-top-down.bmp" : "-bottom-up.bmp");
        pending_pictures_.emplace_back(name, pic);
        return name;
    }

    // An octahedron or a tetrahedron with corners on a grid of 1/4 (exact in
    // any reader's floats), flat or smooth, placed so that the centre ray of a
    // random pixel meets a vertex or the middle of an edge.
    Primitive mesh(RandomScene& out, const Scene& s) {
        reference::Model m;
        const bool octahedron = chance(0.5);
        if (octahedron) {
            m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                       {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
        } else {
            m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
            m.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
        }
        for (Vec3& v : m.positions)
            for (int k = 0; k < 3; ++k) v[k] += 0.25 * integer(-1, 1);
        const bool smooth = chance(0.6);
        std::optional<double> smooth_angle;
        bool split = false;
        if (features_.generated_normals && chance(smooth ? 0.6 : 0.2)) {
            const double angles[] = {0.0, 60.0, 180.0, uniform(0, 180)};
            smooth_angle = angles[integer(0, 3)];
            split = chance(0.3);
        }
        if (split) {  // every face's corners written apart, as STL does
            reference::Model apart;
            for (const auto& face : m.faces) {
                const int first = static_cast<int>(apart.positions.size());
                for (int k : face) apart.positions.push_back(m.positions[k]);
                apart.faces.push_back({first, first + 1, first + 2});
            }
            m = std::move(apart);
        }
        if (smooth && !smooth_angle) {
            const bool leaning = chance(0.5);  // far from the faces, any way
            for (const Vec3& v : m.positions)
                m.normals.push_back(leaning ? Vec3(0.25 * integer(-4, 4), 0.25 * integer(-4, 4),
                                                   0.25 * integer(1, 4))
                                            : v);
        }
        const std::string stem = "model" + std::to_string(models_++);
        const std::string name = stem + ".obj";
        std::string obj;
        const bool file_materials = features_.file_materials && chance(0.7);
        if (file_materials) obj += "mtllib " + stem + ".mtl\n";
        if (file_materials) out.file_bytes[stem + ".mtl"] = parts(m);
        for (const Vec3& v : m.positions)
            obj += "v " + num(v.x) + " " + num(v.y) + " " + num(v.z) + "\n";
        for (const Vec3& n : m.normals)
            obj += "vn " + num(n.x) + " " + num(n.y) + " " + num(n.z) + "\n";
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
            // A run's first face names its part: faces before any usemtl,
            // or after an unknown name, take the mesh's own material.
            const int part = m.face_part.empty() ? -1 : m.face_part[f];
            if (!m.face_part.empty() && (f == 0 ? part >= 0 : part != m.face_part[f - 1]))
                obj += part >= 0 ? "usemtl m" + std::to_string(part) + "\n" : "usemtl unknown\n";
            obj += "f";
            for (int k : m.faces[f])
                obj += " " + std::to_string(k + 1) +
                       (m.normals.empty() ? "" : "//" + std::to_string(k + 1));
            obj += "\n";
        }
        out.file_bytes[name] = obj;
        Primitive p{Mesh{name, std::string(smooth ? kSmoothShading : kFlatShading), smooth_angle,
                         std::string(file_materials ? kFileMaterials : kSceneMaterials)},
                    material(), transforms()};
        // The model's own size first, then its ops; then a last translation puts
        // the chosen point on the chosen pixel's ray.
        const double gain = std::cbrt(
            std::abs(glm::determinant(reference::to_world(unflattened(p.transforms)).linear)));
        p.transforms.insert(
            p.transforms.begin(),
            {TransformKind::scale, Vec3(size_ * log_uniform(0.3, 1.0) / gain), 0.0});
        const auto& face = m.faces[integer(0, static_cast<int>(m.faces.size()) - 1)];
        const int k = integer(0, 2);
        const Vec3 aim = chance(0.5)
                             ? m.positions[face[k]]
                             : 0.5 * (m.positions[face[k]] + m.positions[face[(k + 1) % 3]]);
        const Camera& camera = s.cameras[reference::active_camera(s)];
        const int w = s.settings.width, h = s.settings.height;
        const Vec3 d =
            reference::pixel_direction(camera, w, h, integer(0, w - 1), integer(0, h - 1));
        const Vec3 world = camera.position + glm::length(camera.position) * uniform(0.4, 0.9) * d;
        const reference::Map placed = reference::to_world(unflattened(p.transforms));
        p.transforms.push_back(
            {TransformKind::translate, world - (placed.linear * aim + placed.translation), 0.0});
        out.files.models[name] = std::move(m);
        return p;
    }

    static std::vector<TransformOp> unflattened(std::vector<TransformOp> ops) {
        for (TransformOp& op : ops)
            if (op.kind == TransformKind::scale)
                for (int k = 0; k < 3; ++k)
                    if (op.vector[k] == 0.0) op.vector[k] = 1.0;
        return ops;
    }

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
        if (features_.lens && chance(0.7)) {
            const double distance = glm::length(c.look_at - c.position);
            c.aperture = distance * log_uniform(0.002, 0.05);
            if (chance(0.5)) c.focus_distance = distance * uniform(0.3, 1.5);
        }
        return c;
    }

    Material material() {
        Material m;
        m.pigment = bright_colour();
        if (chance(0.5)) m.finish.edit().ambient = colour();
        if (chance(0.85)) m.finish.edit().diffuse = bright_colour();
        if (chance(0.5)) m.finish.edit().specular = colour();
        if (chance(0.5)) m.finish.edit().diffuse_k = log_uniform(0.3, 4.0);
        m.finish.edit().specular_k = log_uniform(1.0, 300.0);
        if (chance(0.4)) m.finish.edit().reflection = chance(0.2) ? 1.0 : uniform(0, 1);
        if (extensions_ && chance(0.15)) {
            m.finish.edit().transmission = uniform(0.3, 1.0);
            m.finish.edit().ior = log_uniform(0.6, 2.2);
        }
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
        if (auto* sphere = shape_if<Sphere>(&p.shape)) {
            sphere->radius = size;
            sphere->center = object.linear * target + object.translation;
        } else if (auto* cylinder = shape_if<Cylinder>(&p.shape)) {
            cylinder->radius = size;
            cylinder->height = size * uniform(0.5, 3.0);
            aim_a_translation(p.transforms, unflattened, target);
        } else if (auto* plane = shape_if<Plane>(&p.shape)) {
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
        if (s.settings.samples != 1) t += " samples: " + std::to_string(s.settings.samples) + ";";
        if (!s.settings.background_map.empty())
            t += " background_map: \"" + s.settings.background_map + "\";";
        t += " }\ncameras {\n";
        for (const Camera& c : s.cameras)
            t += "  perspective_camera { name: \"" + c.name + "\"; position: " + vec(c.position) +
                 "; look_at: " + vec(c.look_at) + "; up: " + vec(c.up) + "; fov: " + num(c.fov) +
                 "; aspect: " + num(c.aspect) + ";" +
                 (c.aperture > 0 ? " aperture: " + num(c.aperture) + ";" : "") +
                 (c.focus_distance ? " focus_distance: " + num(*c.focus_distance) + ";" : "") +
                 " }\n";
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
        std::string t = "  point_light { position: " + vec(l.position) +
                        "; intensity: " + vec(l.intensity) + ";";
        if (l.radius > 0) t += " radius: " + num(l.radius) + ";";
        if (l.shadow_samples != PointLight{}.shadow_samples)
            t += " shadow_samples: " + std::to_string(l.shadow_samples) + ";";
        return t + " }\n";
    }

    std::string primitive_text(const Primitive& p) {
        std::string t;
        auto property = [&](const char* name, const std::string& value, bool is_default) {
            if (!is_default || chance(0.5)) t += std::string(name) + ": " + value + "; ";
        };
        if (const auto* sphere = shape_if<Sphere>(&p.shape)) {
            t = "  sphere { ";
            property("center", vec(sphere->center), sphere->center == Vec3(0.0));
            property("radius", num(sphere->radius), sphere->radius == 1.0);
        } else if (const auto* cylinder = shape_if<Cylinder>(&p.shape)) {
            t = "  cylinder { ";
            property("radius", num(cylinder->radius), false);
            property("height", num(cylinder->height), false);
        } else if (const auto* plane = shape_if<Plane>(&p.shape)) {
            t = "  plane { ";
            property("normal", vec(plane->normal), false);
            property("distance", num(plane->distance), false);
        } else if (const auto* tri = shape_if<Triangle>(&p.shape)) {
            t = "  triangle { a: " + vec(tri->a) + "; b: " + vec(tri->b) + "; c: " + vec(tri->c) +
                "; uv_a: " + vec(tri->uv_a) + "; uv_b: " + vec(tri->uv_b) +
                "; uv_c: " + vec(tri->uv_c) + "; ";
        } else if (const auto* mesh = shape_if<Mesh>(&p.shape)) {
            t = "  mesh { file: \"" + mesh->file + "\"; shading: \"" + mesh->shading + "\"; ";
            if (mesh->smooth_angle) t += "smooth_angle: " + num(*mesh->smooth_angle) + "; ";
            if (mesh->materials != kSceneMaterials) t += "materials: \"" + mesh->materials + "\"; ";
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
        material_property("ambient", vec(m.finish->ambient),
                          m.finish->ambient == d.finish->ambient);
        material_property("diffuse", vec(m.finish->diffuse),
                          m.finish->diffuse == d.finish->diffuse);
        material_property("specular", vec(m.finish->specular),
                          m.finish->specular == d.finish->specular);
        material_property("diffuse_k", num(m.finish->diffuse_k),
                          m.finish->diffuse_k == d.finish->diffuse_k);
        material_property("specular_k", num(m.finish->specular_k),
                          m.finish->specular_k == d.finish->specular_k);
        material_property("reflection", num(m.finish->reflection),
                          m.finish->reflection == d.finish->reflection);
        if (m.finish->transmission != d.finish->transmission)
            t += "transmission: " + num(m.finish->transmission) + "; ior: " + num(m.finish->ior) +
                 "; ";
        if (!m.finish->image_map.empty()) t += "image_map: \"" + m.finish->image_map + "\"; ";
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
    bool extensions_ = false;
    Features features_;
    double size_ = 1.0;
    int models_ = 0, pictures_ = 0;
    std::vector<std::pair<std::string, reference::Picture>> pending_pictures_;
};

inline RandomScene random_scene(std::uint64_t seed) {
    return SceneGenerator(seed, false).generate();
}

// With triangles, meshes, glass and image maps (docs/language.md §13).
inline RandomScene random_scene_1_1(std::uint64_t seed) {
    return SceneGenerator(seed, true).generate();
}

// Language 1.1's scenes with the features of docs/language.md §14 asked for.
inline RandomScene random_scene_1_2(std::uint64_t seed, Features features) {
    return SceneGenerator(seed, true, features).generate();
}

}  // namespace jt::test
