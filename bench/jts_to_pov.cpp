// jts-to-pov: writes a POV-Ray 3.7 scene that renders what a .jts scene means,
// so that the benchmark can race the two renderers on the same picture.
//
// It reads the file with the core's own parser, so it sees exactly what
// JTracer sees. POV-Ray is left-handed, so every point, vector and transform is
// mirrored in z (S = diag(1, 1, -1); a map M becomes S M S), which shows the
// same image. Shading maps term by term (docs/language.md §8.1):
//   ambient_light * ambient * pigment -> global ambient_light, finish ambient (a colour)
//   diffuse * pigment * (N.L)^(1/diffuse_k) -> finish diffuse, brilliance 1/diffuse_k
//   specular * (R.V)^specular_k -> phong, phong_size (POV-Ray's phong is a number:
//                                  a coloured specular becomes its mean)
//   reflection -> reflection, recurse_depth + 1 -> max_trace_level
//   transmission, ior -> rgbt (transmit), interior { ior }
//   checker -> checker; image_map on triangles and meshes -> uv_mapping image_map;
//   on spheres, cylinders and planes -> map_type 1, 2 (caps: discs with 0), 0,
//   through a pigment matrix that turns POV-Ray's u, v into §13.4's
//   triangle, mesh -> mesh2 (the model's vertex normals when smooth, its UVs)
// with no gamma anywhere (assumed_gamma 1; render with File_Gamma=1.0).
// Language 1.2 (docs/language.md §14):
//   a light's radius r, shadow_samples M -> area_light, circular and orient: a
//       disk of diameter 2r facing the lit point, n x n points (n^2 >= M)
//   aperture a, focus_distance -> aperture 4a (POV-Ray 3.7 moves the eye by
//       up to a quarter of its aperture: measured, docs/benchmarks.md §1.4),
//       focal_point on the view axis, blur_samples n, n (JTracer's samples)
//   background_map -> sky_sphere with a spherical image map (map_type 1)

#include "converter_cli.hpp"
#include "jtracer/affine.hpp"
#include "jtracer/model_cache.hpp"
#include "jtracer/smooth_normals.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/validate.hpp"
#include "render/camera_rays.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

using jt::Vec3;
using PovWriter = jt::bench::TextWriter;
constexpr auto mirror = jt::bench::mirror_z;

double mean(const jt::Colour& c) {
    return (c.x + c.y + c.z) / 3.0;
}

// POV-Ray's name of a picture's format, from its extension.
std::string_view image_format(const std::string& file) {
    const std::string ext = std::filesystem::path(file).extension().string();
    if (ext == ".jpg" || ext == ".jpeg" || ext == ".JPG" || ext == ".JPEG") return "jpeg";
    if (ext == ".bmp" || ext == ".BMP") return "bmp";  // "sys" is no format on Unix
    return "png";
}

// How an image map lies on a shape in POV-Ray's terms: the mesh2's
// uv_vectors, or a map_type with the map from the picture's space (where
// POV-Ray's u, v are read) to the object's, as the rows of a `matrix`.
struct ImageMapping {
    bool uv = false;
    int map_type = 0;  // 0 planar, 1 spherical, 2 cylindrical
    std::array<Vec3, 4> rows{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.0)};
};

void write_rows(PovWriter& out, const std::array<Vec3, 4>& rows) {
    out.printf(" matrix <");
    for (std::size_t i = 0; i < rows.size(); ++i)
        out.printf("%.9g, %.9g, %.9g%s", rows[i].x, rows[i].y, rows[i].z, i < 3 ? ", " : ">");
}

// POV-Ray's spherical and cylindrical u is the angle from +x towards +z
// (its z, which is -z here); §13.4's is 0.5 + atan2(x, z) / 2 pi. The
// picture's space turned a quarter about y (x to +z, z to -x) makes them one.
// `height`: the cylinder's, over which v runs from 0 to 1 (spheres: 1).
ImageMapping around_y(int map_type, const Vec3& centre, double height) {
    return {false, map_type, {Vec3(0, 0, 1), Vec3(0, height, 0), Vec3(-1, 0, 0), mirror(centre)}};
}

// §13.4's cylinder caps, u = 0.5 + x / 2r and v = 0.5 + z / 2r with JTracer's
// z (POV-Ray's -z), on POV-Ray's planar map (u, v = the picture space's x, y).
ImageMapping cap_mapping(double r) {
    return {false, 0, {Vec3(2 * r, 0, 0), Vec3(0, 0, -2 * r), Vec3(0, 1, 0), Vec3(-r, 0, r)}};
}

// §13.4's plane: u = p.e1 / map_size, v = p.e2 / map_size.
ImageMapping plane_mapping(const Vec3& n, double map_size) {
    Vec3 e1 = glm::cross(n, Vec3(0, 0, 1));
    if (e1 == Vec3(0.0)) e1 = glm::cross(n, Vec3(1, 0, 0));
    e1 = glm::normalize(e1);
    const Vec3 e2 = glm::cross(n, e1);
    return {
        false, 0, {mirror(e1) * map_size, mirror(e2) * map_size, mirror(n) * map_size, Vec3(0.0)}};
}

// With no mapping the object shows its pigment where JTracer would show the image.
void write_material(PovWriter& out, const jt::Material& m, const jt::Scene& scene,
                    const std::optional<ImageMapping>& mapping) {
    // POV-Ray's diffuse is a number. A grey diffuse maps straight; a coloured
    // one is folded into the pigment, with the ambient scaled back so that
    // ambient * pigment is unchanged wherever the diffuse channel is not zero.
    jt::Colour pigment = m.pigment, ambient = m.finish->ambient;
    double diffuse = std::max({m.finish->diffuse.x, m.finish->diffuse.y, m.finish->diffuse.z});
    if (diffuse > 0.0 && !(m.finish->diffuse.x == m.finish->diffuse.y &&
                           m.finish->diffuse.y == m.finish->diffuse.z)) {
        for (int i = 0; i < 3; ++i) {
            double share = m.finish->diffuse[i] / diffuse;
            pigment[i] *= share;
            ambient[i] = share > 0.0 ? ambient[i] / share : 0.0;
        }
    }
    // JTracer's transmission adds t times the transmitted ray to unchanged local
    // terms, as POV-Ray's transmit does for a black pigment (clear glass).
    auto colour = [&](const char* prefix, const jt::Colour& c) {
        if (m.finish->transmission > 0.0)
            out.printf("%srgbt <%.9g, %.9g, %.9g, %.9g>", prefix, c.x, c.y, c.z,
                       m.finish->transmission);
        else
            out.vector((std::string(prefix) + "rgb ").c_str(), c);
    };
    const bool image = !m.finish->image_map.empty() && mapping;
    out.printf(image && mapping->uv ? " texture { uv_mapping pigment { " : " texture { pigment { ");
    if (image) {
        // Bilinear and linear (gamma 1), like JTracer's; the bottom row is v = 0 in both.
        const std::string path =
            std::filesystem::absolute(jt::asset_path(scene, m.finish->image_map));
        out.printf("image_map { %s \"%s\" gamma 1.0 interpolate 2",
                   std::string(image_format(path)).c_str(), path.c_str());
        if (!mapping->uv) out.printf(" map_type %d", mapping->map_type);
        out.printf(" }");
        if (!mapping->uv) write_rows(out, mapping->rows);
    } else if (m.finish->checker) {
        // The mirrored z flips the parity of floor(z) off the cube faces: the
        // two colours swap places.
        colour("checker ", *m.finish->checker);
        colour(" ", pigment);
        out.printf(" scale %.9g", m.finish->checker_size);
    } else {
        colour("", pigment);
    }
    out.vector(" } finish { ambient rgb ", ambient);
    out.printf(" diffuse %.9g brilliance %.9g", diffuse, 1.0 / m.finish->diffuse_k);
    if (mean(m.finish->specular) > 0.0)
        out.printf(" phong %.9g phong_size %.9g", mean(m.finish->specular), m.finish->specular_k);
    if (m.finish->reflection > 0.0) out.printf(" reflection { %.9g }", m.finish->reflection);
    out.printf(" } }");
    if (m.finish->transmission > 0.0) out.printf(" interior { ior %.9g }", m.finish->ior);
}

// POV-Ray's `matrix` lists the images of the x, y, z axes and the translation,
// each as a row.
void write_matrix(PovWriter& out, const jt::Affine& world) {
    glm::dmat3 s(1.0);
    s[2][2] = -1.0;
    glm::dmat3 linear = s * world.linear * s;
    out.printf(" matrix <");
    for (int axis = 0; axis < 3; ++axis)
        out.printf("%.9g, %.9g, %.9g, ", linear[axis].x, linear[axis].y, linear[axis].z);
    Vec3 t = mirror(world.translation);
    out.printf("%.9g, %.9g, %.9g>", t.x, t.y, t.z);
}

// A mesh2 of triangles: mirrored corners, the normals when given (smooth
// shading), the texture coordinates when given. Normals are one a vertex, or
// with `normal_per_corner` one for each corner of each triangle in turn.
void write_mesh2(PovWriter& out, const std::vector<Vec3>& positions,
                 const std::vector<Vec3>& normals, const std::vector<glm::dvec2>& uvs,
                 const std::vector<std::array<std::uint32_t, 3>>& triangles,
                 bool normal_per_corner = false) {
    out.printf("mesh2 {\n vertex_vectors { %zu", positions.size());
    for (const Vec3& v : positions) out.vector(", ", mirror(v));
    out.printf(" }\n");
    if (!normals.empty()) {
        out.printf(" normal_vectors { %zu", normals.size());
        for (const Vec3& n : normals) out.vector(", ", mirror(n));
        out.printf(" }\n");
    }
    if (!uvs.empty()) {
        out.printf(" uv_vectors { %zu", uvs.size());
        for (const glm::dvec2& uv : uvs) out.printf(", <%.9g, %.9g>", uv.x, uv.y);
        out.printf(" }\n");
    }
    out.printf(" face_indices { %zu", triangles.size());
    for (const auto& t : triangles) out.printf(", <%u, %u, %u>", t[0], t[1], t[2]);
    out.printf(" }\n");
    if (normal_per_corner) {
        out.printf(" normal_indices { %zu", triangles.size());
        for (std::size_t t = 0; t < triangles.size(); ++t)
            out.printf(", <%zu, %zu, %zu>", 3 * t, 3 * t + 1, 3 * t + 2);
        out.printf(" }\n");
    }
}

// A mesh's model as mesh2; false when it cannot be read or holds nothing.
bool write_model(PovWriter& out, const jt::Mesh& mesh, const jt::Scene& scene) {
    auto model = jt::shared_model(jt::asset_path(scene, mesh.file), scene.asset_folder);
    if (!model || (*model)->triangles.empty()) return false;
    const jt::Model& m = **model;
    std::vector<Vec3> positions(m.positions.begin(), m.positions.end()), normals;
    std::vector<glm::dvec2> uvs(m.uvs.begin(), m.uvs.end());
    // A corner without a normal makes its triangles flat in JTracer; POV-Ray
    // takes one normal list for all, so such a model is written flat.
    const bool smooth = mesh.shading == jt::kSmoothShading && !m.normals.empty() &&
                        std::none_of(m.normals.begin(), m.normals.end(),
                                     [](const glm::vec3& n) { return n == glm::vec3(0.0f); });
    if (smooth) normals.assign(m.normals.begin(), m.normals.end());
    // With smooth_angle, the corners without a file normal have generated
    // ones (docs/language.md §14.4): written one a corner.
    if (mesh.shading == jt::kSmoothShading && mesh.smooth_angle && !smooth &&
        jt::corners_without_normals(m) > 0) {
        const auto corners = jt::shared_corner_normals(*model, *mesh.smooth_angle);
        if (!corners) return false;
        for (const auto& triangle : **corners)
            normals.insert(normals.end(), triangle.begin(), triangle.end());
        write_mesh2(out, positions, normals, uvs, m.triangles, true);
        return true;
    }
    write_mesh2(out, positions, normals, uvs, m.triangles);
    return true;
}

// A cylinder whose caps carry their own image mapping: an open tube and two
// discs, one object for the transform.
void write_mapped_cylinder(PovWriter& out, const jt::Cylinder& c, const jt::Material& m,
                           const jt::Scene& scene) {
    out.printf("union {\n cylinder { <0, 0, 0>, <0, %.9g, 0>, %.9g open", c.height, c.radius);
    write_material(out, m, scene, around_y(2, Vec3(0.0), c.height));
    out.printf(" }\n");
    for (const double y : {0.0, c.height}) {
        out.printf(" disc { <0, %.9g, 0>, <0, %d, 0>, %.9g", y, y > 0.0 ? 1 : -1, c.radius);
        write_material(out, m, scene, cap_mapping(c.radius));
        out.printf(" }\n");
    }
}

void write_primitive(PovWriter& out, const jt::Primitive& p, const jt::Scene& scene) {
    // JTracer's own rule decides which primitives are left out.
    const auto placed = jt::object_transform(p.transforms);
    if (std::holds_alternative<jt::LeftOut>(placed)) return;
    const jt::Affine& world = std::get<jt::ObjectTransform>(placed).to_world;
    // Planes and spheres are written mirrored and then moved by the mirrored
    // map; the map of an untransformed primitive is the identity and is left out.
    std::optional<ImageMapping> mapping;
    if (const auto* sphere = jt::shape_if<jt::Sphere>(&p.shape)) {
        out.vector("sphere { ", mirror(sphere->center));
        out.printf(", %.9g", sphere->radius);
        mapping = around_y(1, sphere->center, 1.0);
    } else if (const auto* plane = jt::shape_if<jt::Plane>(&p.shape)) {
        auto normal = jt::unit_length(plane->normal);
        if (!normal) return;
        out.vector("plane { ", mirror(*normal));
        out.printf(", %.9g", plane->distance);
        mapping = plane_mapping(*normal, p.material.finish->map_size);
    } else if (const auto* cylinder = jt::shape_if<jt::Cylinder>(&p.shape)) {
        if (!p.material.finish->image_map.empty()) {
            write_mapped_cylinder(out, *cylinder, p.material, scene);
            if (!p.transforms.empty()) write_matrix(out, world);
            out.printf(" }\n");
            return;
        }
        out.printf("cylinder { <0, 0, 0>, <0, %.9g, 0>, %.9g", cylinder->height, cylinder->radius);
    } else if (const auto* triangle = jt::shape_if<jt::Triangle>(&p.shape)) {
        if (glm::cross(triangle->b - triangle->a, triangle->c - triangle->a) == Vec3(0.0)) return;
        write_mesh2(
            out, {triangle->a, triangle->b, triangle->c}, {},
            {glm::dvec2(triangle->uv_a), glm::dvec2(triangle->uv_b), glm::dvec2(triangle->uv_c)},
            {{0u, 1u, 2u}});
    } else if (const auto* mesh = jt::shape_if<jt::Mesh>(&p.shape)) {
        if (!write_model(out, *mesh, scene)) return;
    }
    if (jt::shape_is<jt::Triangle>(p.shape) || jt::shape_is<jt::Mesh>(p.shape))
        mapping = ImageMapping{true};
    write_material(out, p.material, scene, mapping);
    if (!p.transforms.empty()) write_matrix(out, world);
    out.printf(" }\n");
}

void write_camera(PovWriter& out, const jt::Camera& camera, int samples) {
    // docs/language.md §7: the ray is f + sx r + sy u with |sx| <= t * aspect, |sy| <= t.
    // POV-Ray spans `right` and `up` over the image and scales `direction` so that
    // `angle` is the full horizontal field of view: 2 atan(t * aspect).
    const jt::CameraFrame frame = jt::camera_frame(camera, 1, 1);
    double t = frame.tan_half_fov;
    double angle = 2.0 * std::atan(t * camera.aspect) * 180.0 / std::numbers::pi;
    out.vector("camera { perspective location ", mirror(frame.position));
    out.vector(" direction ", mirror(frame.forward));
    out.vector(" right ", mirror(frame.right) * camera.aspect);
    out.vector(" up ", mirror(frame.up));
    out.printf(" angle %.12g", angle);
    if (camera.aperture > 0.0) {
        // POV-Ray's blur samples are its rays per pixel, as JTracer's samples are.
        const double focus = camera.focus_distance ? *camera.focus_distance
                                                   : glm::length(camera.look_at - camera.position);
        out.vector(" focal_point ", mirror(frame.position + frame.forward * focus));
        out.printf(" aperture %.9g blur_samples %d, %d", 4.0 * camera.aperture, samples, samples);
    }
    out.printf(" }\n");
}

// docs/language.md §14.1: a sphere of light of radius r seen as a disk facing
// the lit point, M points of it tested for shadows: POV-Ray's circular,
// oriented area light of the disk's diameter, with n x n points, n^2 >= M.
void write_light(PovWriter& out, const jt::PointLight& light) {
    out.vector("light_source { ", mirror(light.position));
    out.vector(", rgb ", light.intensity);
    if (light.radius > 0.0) {
        int n = 1;
        while (n * n < light.shadow_samples) ++n;
        const double d = 2.0 * light.radius;
        out.printf(" area_light <%.9g, 0, 0>, <0, %.9g, 0>, %d, %d circular orient", d, d, n, n);
    }
    out.printf(" }\n");
}

// docs/language.md §14.3: every ray that misses sees the map at its
// direction d, u = 0.5 + atan2(d.x, -d.z) / 2 pi. POV-Ray's spherical u is
// the angle from its +x toward its +z; its z is -z here, so the picture's
// space turned a quarter about y (x to -z, z to -x, in POV-Ray's terms)
// makes them one. v is the latitude in both.
void write_sky(PovWriter& out, const jt::Scene& scene) {
    const std::string path =
        std::filesystem::absolute(jt::asset_path(scene, scene.settings.background_map));
    out.printf("sky_sphere { pigment { image_map { %s \"%s\" gamma 1.0 interpolate 2 map_type 1 }",
               std::string(image_format(path)).c_str(), path.c_str());
    write_rows(out, {Vec3(0, 0, -1), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0.0)});
    out.printf(" } }\n");
}

std::string convert(const jt::Scene& scene, int camera_index) {
    PovWriter out;
    const jt::RenderSettings& s = scene.settings;
    out.printf("// Written by jts-to-pov. Render with -A +WT2 File_Gamma=1.0 +W%d +H%d\n", s.width,
               s.height);
    out.printf("#version 3.7;\n");
    out.vector("global_settings { assumed_gamma 1.0 ambient_light rgb ", s.ambient_light);
    out.printf(" max_trace_level %d }\n", std::min(s.recurse_depth, 255) + 1);
    out.vector("background { rgb ", s.background);
    out.printf(" }\n");
    if (!s.background_map.empty()) write_sky(out, scene);
    if (camera_index >= 0)
        write_camera(out, scene.cameras[static_cast<std::size_t>(camera_index)], s.samples);
    for (const jt::PointLight& light : scene.lights)
        if (light.intensity != jt::Colour(0.0)) write_light(out, light);
    for (const jt::Primitive& p : scene.primitives) write_primitive(out, p, scene);
    return out.text();
}

}  // namespace

int main(int argc, char** argv) {
    constexpr const char* program = "jts-to-pov";
    if (argc != 3 || std::string_view(argv[1]).starts_with("-")) {
        std::cerr << "usage: jts-to-pov SCENE.jts OUT.pov\n"
                     "Writes a POV-Ray 3.7 scene that renders like the JTracer scene.\n";
        return jt::bench::exit_usage;
    }
    int status = 0;
    std::optional<jt::LoadedScene> loaded = jt::bench::load_checked_scene(program, argv[1], status);
    if (!loaded) return status;
    const jt::Scene& scene = loaded->parsed.scene;
    if (!jt::bench::write_text(program, argv[2], convert(scene, jt::active_camera_index(scene))))
        return jt::bench::exit_io;
    return 0;
}
