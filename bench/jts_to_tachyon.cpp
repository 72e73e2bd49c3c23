// jts-to-tachyon: writes a Tachyon scene (.dat) that renders what a .jts scene
// means, so that the benchmark can race the two renderers on the same picture.
//
// It reads the file with the core's own parser, so it sees exactly what
// JTracer sees. Tachyon is left-handed (its right vector is up x view), so every
// point and direction is mirrored in z, which shows the same image. The camera:
// Tachyon's image plane lies at distance 1 and is 1 / ZOOM high, so
// ZOOM = 1 / (2 tan(fov / 2)), and ASPECTRATIO = (width / height) / aspect.
// Tachyon's shading is JTracer's term by term (docs/language.md §8.1), with
// scalar coefficients:
//   ambient_light * ambient * pigment -> AMBIENT (their mean) times COLOR
//   diffuse * pigment * dot(N, L)     -> DIFFUSE (the largest channel); a
//                                        coloured diffuse is folded into COLOR
//   specular * dot(R, V)^specular_k   -> PHONG PLASTIC (the mean) PHONG_SIZE
//                                        (render with -shade_phong)
//   reflection                        -> SPECULAR, recurse_depth + 1 -> RAYDEPTH
// and no gamma. diffuse_k other than 1 has no counterpart. A capped cylinder is
// an FCYLINDER (open) closed by two RINGs of inner radius 0.
//
// --silhouette MASK.jts writes both renderers' scenes in silhouette form
// (bench/check_silhouettes.py): every primitive flat in one of seven colours
// chosen by its index, no lights, no reflection, a black background. Each
// renderer's image then says which primitive every pixel sees.

#include "converter_cli.hpp"
#include "jtracer/diagnostics.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/validate.hpp"
#include "render/camera_rays.hpp"
#include "world_shapes.hpp"

#include <glm/geometric.hpp>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace {

using jt::Vec3;
using jt::bench::mirror_z;
using jt::bench::TextWriter;

// Up to this many distinct materials become TEXDEFs; Tachyon finds a named
// texture by a linear search and holds at most 32768, so scenes with more
// distinct materials get each texture written inline.
constexpr std::size_t max_named_textures = 1024;

double mean(const jt::Colour& c) {
    return (c.x + c.y + c.z) / 3.0;
}

// The body of a Tachyon texture: "AMBIENT a DIFFUSE d ... TEXFUNC 0".
std::string texture_body(const jt::Material& m, const jt::Colour& ambient_light) {
    jt::Colour colour = m.pigment;
    double diffuse = std::max({m.finish->diffuse.x, m.finish->diffuse.y, m.finish->diffuse.z});
    if (diffuse > 0.0) colour = m.pigment * m.finish->diffuse / diffuse;
    double ambient = mean(ambient_light * m.finish->ambient * m.pigment);
    if (ambient > 0.0) ambient = mean(colour) > 0.0 ? ambient / mean(colour) : 0.0;
    TextWriter out;
    out.printf("AMBIENT %.9g DIFFUSE %.9g SPECULAR %.9g OPACITY 1", ambient, diffuse,
               m.finish->reflection);
    if (mean(m.finish->specular) > 0.0)
        out.printf(" PHONG PLASTIC %.9g PHONG_SIZE %.9g", mean(m.finish->specular),
                   m.finish->specular_k);
    out.triple(" COLOR ", colour);
    out.printf(" TEXFUNC 0");
    return out.text();
}

// The texture of every primitive, as Tachyon's scene refers to it: a TEXDEF's
// name, or the inline "TEXTURE ..." when there are too many distinct ones.
class Textures {
  public:
    Textures(const jt::Scene& scene, TextWriter& out) {
        std::map<std::string, std::string> names;
        std::vector<std::string> bodies;
        for (const jt::Primitive& p : scene.primitives)
            bodies.push_back(texture_body(p.material, scene.settings.ambient_light));
        for (const std::string& body : bodies) names.emplace(body, "");
        const bool named = names.size() <= max_named_textures;
        if (named) {
            int next = 0;
            for (auto& [body, name] : names) {
                char label[16];
                std::snprintf(label, sizeof label, "m%d", next++);
                name = label;
                out.printf("TEXDEF %s %s\n", name.c_str(), body.c_str());
            }
        }
        for (const std::string& body : bodies)
            references_.push_back(named ? names[body] : "TEXTURE " + body);
    }
    const std::string& of(std::size_t primitive) const { return references_[primitive]; }

  private:
    std::vector<std::string> references_;
};

// Every shape in world space, mirrored.
void write_shapes(TextWriter& out, const jt::bench::WorldShapes& shapes, const Textures& textures) {
    for (const jt::bench::WorldSphere& sphere : shapes.spheres) {
        out.triple("SPHERE CENTER ", mirror_z(sphere.center));
        out.printf(" RAD %.9g %s\n", sphere.radius, textures.of(sphere.primitive).c_str());
    }
    for (const jt::bench::WorldCylinder& cylinder : shapes.cylinders) {
        const std::string& texture = textures.of(cylinder.primitive);
        const Vec3 base = mirror_z(cylinder.base), apex = mirror_z(cylinder.apex);
        const Vec3 axis = glm::normalize(apex - base);
        out.triple("FCYLINDER BASE ", base);
        out.triple(" APEX ", apex);
        out.printf(" RAD %.9g %s\n", cylinder.radius, texture.c_str());
        out.triple("RING CENTER ", base);
        out.triple(" NORMAL ", -axis);
        out.printf(" INNER 0 OUTER %.9g %s\n", cylinder.radius, texture.c_str());
        out.triple("RING CENTER ", apex);
        out.triple(" NORMAL ", axis);
        out.printf(" INNER 0 OUTER %.9g %s\n", cylinder.radius, texture.c_str());
    }
    for (const jt::bench::WorldPlane& plane : shapes.planes) {
        out.triple("PLANE CENTER ", mirror_z(plane.point));
        out.triple(" NORMAL ", mirror_z(plane.normal));
        out.printf(" %s\n", textures.of(plane.primitive).c_str());
    }
}

void write_camera(TextWriter& out, const jt::RenderSettings& s, const jt::Camera& camera) {
    const jt::CameraFrame frame = jt::camera_frame(camera, s.width, s.height);
    out.printf("CAMERA\n  PROJECTION PERSPECTIVE\n");
    out.printf("  ZOOM %.12g\n", 0.5 / frame.tan_half_fov);
    out.printf("  ASPECTRATIO %.12g\n", (double(s.width) / s.height) / camera.aspect);
    out.printf("  ANTIALIASING 0\n  RAYDEPTH %d\n", std::min(s.recurse_depth, 255) + 1);
    out.triple("  CENTER ", mirror_z(frame.position));
    out.triple("\n  VIEWDIR ", mirror_z(frame.forward));
    out.triple("\n  UPDIR ", mirror_z(frame.up));
    out.printf("\nEND_CAMERA\n");
}

// The Tachyon scene, or a diagnostic at the first primitive it cannot show.
std::variant<std::string, jt::Diagnostic> convert(const jt::LoadedScene& loaded) {
    const jt::Scene& scene = loaded.parsed.scene;
    const jt::RenderSettings& s = scene.settings;
    TextWriter out;
    out.printf(
        "# Written by jts-to-tachyon. Render with -numthreads 2 -shade_phong "
        "-format BMP\nBEGIN_SCENE\n");
    out.printf("RESOLUTION %d %d\n", s.width, s.height);
    const int camera_index = jt::active_camera_index(scene);
    if (camera_index >= 0) write_camera(out, s, scene.cameras[std::size_t(camera_index)]);
    out.triple("BACKGROUND ", s.background);
    out.printf("\n");
    for (const jt::PointLight& light : scene.lights) {
        if (light.intensity == jt::Colour(0.0)) continue;
        out.triple("LIGHT CENTER ", mirror_z(light.position));
        out.triple(" RAD 0 COLOR ", light.intensity);
        out.printf("\n");
    }
    const jt::bench::WorldShapes shapes = jt::bench::world_shapes(scene);
    // Tachyon has neither ellipsoids nor elliptic cylinders.
    if (shapes.first_unplaceable) {
        const std::size_t i = *shapes.first_unplaceable;
        jt::SourcePos pos;
        if (i < loaded.parsed.source.primitives.size())
            pos = loaded.parsed.source.primitives[i].keyword_span.pos;
        return jt::Diagnostic{jt::Severity::error, pos,
                              "Tachyon cannot show this primitive: it is a triangle or mesh, or "
                              "its transform is not a rotation and a uniform scale"};
    }
    const Textures textures(scene, out);
    write_shapes(out, shapes, textures);
    out.printf("END_SCENE\n");
    return out.text();
}

// The scene with every primitive flat in the colour of its index, lit by the
// ambient term alone: colour k in 1..7 has red = bit 0, green = bit 1, blue = bit 2.
jt::Scene silhouette_scene(jt::Scene scene) {
    scene.settings.ambient_light = jt::Colour(1.0);
    scene.settings.background = jt::Colour(0.0);
    scene.settings.recurse_depth = 0;
    scene.settings.samples = 1;
    scene.lights.clear();
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        const int k = int(i % 7) + 1;
        jt::Material m;
        m.pigment = jt::Colour(k & 1, (k >> 1) & 1, (k >> 2) & 1);
        m.finish.edit().ambient = jt::Colour(1.0);
        scene.primitives[i].material = m;
    }
    return scene;
}

constexpr const char* program = "jts-to-tachyon";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string_view> args(argv + 1, argv + argc);
    std::string silhouette;
    if (args.size() == 4 && args[2] == "--silhouette") {
        silhouette = args[3];
        args.resize(2);
    }
    if (args.size() != 2 || args[0].starts_with("-") || args[1].starts_with("-")) {
        std::cerr << "usage: jts-to-tachyon SCENE.jts OUT.dat [--silhouette MASK.jts]\n"
                     "Writes a Tachyon scene that renders like the JTracer scene; with\n"
                     "--silhouette, both scenes in flat colours that name each primitive.\n";
        return jt::bench::exit_usage;
    }
    int status = 0;
    std::optional<jt::LoadedScene> loaded = jt::bench::load_checked_scene(program, argv[1], status);
    if (!loaded) return status;
    if (!silhouette.empty()) loaded->parsed.scene = silhouette_scene(loaded->parsed.scene);

    auto converted = convert(*loaded);
    if (const auto* problem = std::get_if<jt::Diagnostic>(&converted)) {
        std::cerr << jt::format_diagnostic(*problem, loaded->path, loaded->text);
        return jt::bench::exit_scene_errors;
    }
    if (!silhouette.empty() &&
        !jt::bench::write_text(program, silhouette, jt::serialize_scene(loaded->parsed.scene)))
        return jt::bench::exit_io;
    if (!jt::bench::write_text(program, argv[2], std::get<std::string>(converted)))
        return jt::bench::exit_io;
    return 0;
}
