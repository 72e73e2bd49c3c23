#include "scene_info.hpp"

#include "jtracer/affine.hpp"
#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/render_flags.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/validate.hpp"

#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>

namespace jt::cli {

using nlohmann::json;
using namespace frontend;

namespace {

struct Box {
    Vec3 lower{std::numeric_limits<double>::infinity()};
    Vec3 upper{-std::numeric_limits<double>::infinity()};
    bool empty() const { return lower.x > upper.x; }
    void add(const Vec3& p) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    void add(const Box& b) {
        if (!b.empty()) add(b.lower), add(b.upper);
    }
};

json vec(const Vec3& v) {
    return json::array({v.x, v.y, v.z});
}
json box_json(const Box& b) {
    return b.empty() ? json() : json{{"lower", vec(b.lower)}, {"upper", vec(b.upper)}};
}

// The world box of an object-space box seen through `to_world`: its eight
// corners' (a sphere's is then a little large when rotated, never small).
Box world_box(const Box& local, const Affine& to_world) {
    Box world;
    if (local.empty()) return world;
    for (int corner = 0; corner < 8; ++corner)
        world.add(apply_point(to_world, {corner & 1 ? local.upper.x : local.lower.x,
                                         corner & 2 ? local.upper.y : local.lower.y,
                                         corner & 4 ? local.upper.z : local.lower.z}));
    return world;
}

struct LoadedModel {
    Expected<Model> model = Error{""};
    double seconds = 0.0;
};

std::size_t model_bytes(const Model& m) {
    return m.positions.size() * sizeof(m.positions[0]) + m.normals.size() * sizeof(m.normals[0]) +
           m.uvs.size() * sizeof(m.uvs[0]) + m.triangles.size() * sizeof(m.triangles[0]);
}

bool has_normals(const Model& m) {
    return std::any_of(m.normals.begin(), m.normals.end(),
                       [](const glm::vec3& n) { return n != glm::vec3(0.0f); });
}

// Everything `info` reports, as JSON; the text form is printed from it.
Expected<json> describe(const Scene& scene) {
    json out;
    std::map<std::string, int> counts;
    for (std::string_view keyword : {"sphere", "plane", "cylinder", "triangle", "mesh"})
        counts[std::string(keyword)] = 0;
    std::map<std::filesystem::path, LoadedModel> models;  // each file read once, timed
    Box scene_box;
    int unbounded = 0, left_out = 0;
    json meshes = json::array();
    std::size_t bytes_models = 0;
    for (const Primitive& p : scene.primitives) {
        ++counts[std::string(keyword_of(p.shape))];
        const auto transform = object_transform(p.transforms);
        if (!std::holds_alternative<ObjectTransform>(transform)) {
            ++left_out;
            continue;
        }
        const Affine& to_world = std::get<ObjectTransform>(transform).to_world;
        Box world;
        if (const auto* s = std::get_if<Sphere>(&p.shape)) {
            world = world_box({s->center - s->radius, s->center + s->radius}, to_world);
        } else if (const auto* c = std::get_if<Cylinder>(&p.shape)) {
            world = world_box({{-c->radius, 0.0, -c->radius}, {c->radius, c->height, c->radius}},
                              to_world);
        } else if (const auto* t = std::get_if<Triangle>(&p.shape)) {
            for (const Vec3& corner : {t->a, t->b, t->c}) world.add(apply_point(to_world, corner));
        } else if (std::holds_alternative<Plane>(p.shape)) {
            ++unbounded;
        } else if (const auto* m = std::get_if<Mesh>(&p.shape)) {
            const std::filesystem::path path = asset_path(scene, m->file);
            auto [at, fresh] = models.try_emplace(path);
            if (fresh) {
                const auto start = std::chrono::steady_clock::now();
                at->second.model = read_model(path, scene.asset_folder);
                at->second.seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (at->second.model) bytes_models += model_bytes(*at->second.model);
            }
            const LoadedModel& loaded = at->second;
            if (!loaded.model) return loaded.model.error();
            const Model& model = *loaded.model;
            for (const auto& triangle : model.triangles)
                for (std::uint32_t corner : triangle)
                    world.add(apply_point(to_world, Vec3(model.positions[corner])));
            meshes.push_back({{"file", m->file},
                              {"path", path.string()},
                              {"triangles", model.triangles.size()},
                              {"vertices", model.positions.size()},
                              {"normals", has_normals(model) ? "file" : "generated"},
                              {"shading", m->shading},
                              {"bbox", box_json(world)},
                              {"load_seconds", loaded.seconds},
                              {"read_before", !fresh}});  // the same file as an earlier mesh
        }
        scene_box.add(world);
    }
    out["primitives"] = counts;
    out["meshes"] = meshes;
    out["bbox"] = box_json(scene_box);
    out["unbounded"] = unbounded;  // planes: no box holds them
    out["left_out"] = left_out;    // flattened by a zero scale, or out of range

    json maps = json::array();
    std::size_t bytes_maps = 0;
    for (const std::filesystem::path& path : named_files(scene).images) {
        const Expected<std::shared_ptr<const Texture>> texture = load_texture(path);
        if (!texture) return texture.error();
        const std::size_t bytes = (*texture)->rgb8.size() + (*texture)->rgb16.size() * 2;
        bytes_maps += bytes;
        maps.push_back({{"path", path.string()},
                        {"width", (*texture)->width},
                        {"height", (*texture)->height},
                        {"bytes", bytes}});
    }
    out["image_maps"] = maps;

    json lights = json::array();
    for (const PointLight& l : scene.lights)
        lights.push_back({{"position", vec(l.position)}, {"intensity", vec(l.intensity)}});
    out["lights"] = lights;

    json cameras = json::array();
    const int active = active_camera_index(scene);
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const Camera& c = scene.cameras[i];
        cameras.push_back({{"name", c.name},
                           {"position", vec(c.position)},
                           {"look_at", vec(c.look_at)},
                           {"direction", vec(glm::normalize(c.look_at - c.position))},
                           {"fov", c.fov},
                           {"active", static_cast<int>(i) == active}});
    }
    out["cameras"] = cameras;
    // The scene's own data once prepared: the models' vertices and triangles
    // and the decoded image maps (4 bytes a channel); not the acceleration
    // structure Embree builds over them.
    out["memory"] = {
        {"models", bytes_models},
        {"image_maps", bytes_maps},
        {"primitives", scene.primitives.size() * sizeof(Primitive)},
        {"total", bytes_models + bytes_maps + scene.primitives.size() * sizeof(Primitive)}};
    return out;
}

std::string vec_text(const json& v) {
    char text[96];
    std::snprintf(text, sizeof text, "<%g, %g, %g>", v[0].get<double>(), v[1].get<double>(),
                  v[2].get<double>());
    return text;
}

std::string box_text(const json& b) {
    if (b.is_null()) return "none";
    return vec_text(b["lower"]) + " to " + vec_text(b["upper"]);
}

std::string mib(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MiB", static_cast<double>(bytes) / (1 << 20));
    return text;
}

void print_text(const json& d) {
    std::cout << "primitives:";
    for (const auto& [kind, count] : d["primitives"].items())
        std::cout << " " << kind << " " << count;
    std::cout << "\n";
    for (const json& m : d["meshes"]) {
        char read[48];
        std::snprintf(read, sizeof read, "read in %.3f s", m["load_seconds"].get<double>());
        std::cout << "mesh " << m["file"].get<std::string>() << ": " << m["triangles"]
                  << " triangles, " << m["vertices"] << " vertices, normals "
                  << m["normals"].get<std::string>() << ", " << m["shading"].get<std::string>()
                  << "; world box " << box_text(m["bbox"]) << "; "
                  << (m["read_before"].get<bool>() ? "the file of an earlier mesh" : read) << "\n";
    }
    std::cout << "world box: " << box_text(d["bbox"]);
    if (d["unbounded"].get<int>() > 0)
        std::cout << " (and " << d["unbounded"] << " unbounded planes)";
    std::cout << "\n";
    for (const json& map : d["image_maps"])
        std::cout << "image map " << map["path"].get<std::string>() << ": " << map["width"] << "x"
                  << map["height"] << ", " << mib(map["bytes"].get<std::size_t>()) << "\n";
    for (const json& l : d["lights"])
        std::cout << "point light at " << vec_text(l["position"]) << ", intensity "
                  << vec_text(l["intensity"]) << "\n";
    for (const json& c : d["cameras"])
        std::cout << "camera \"" << c["name"].get<std::string>() << "\""
                  << (c["active"].get<bool>() ? " (active)" : "") << ": at "
                  << vec_text(c["position"]) << " looking at " << vec_text(c["look_at"])
                  << " (direction " << vec_text(c["direction"]) << "), fov " << c["fov"] << "\n";
    const json& memory = d["memory"];
    std::cout << "memory of the prepared scene (estimated, without the acceleration structure): "
              << mib(memory["total"].get<std::size_t>()) << " (models "
              << mib(memory["models"].get<std::size_t>()) << ", image maps "
              << mib(memory["image_maps"].get<std::size_t>()) << ")\n";
}

}  // namespace

int run_info_command(int argc, char** argv) {
    std::string scene_path;
    bool json_output = false;
    CLI::App app{"jtracer-cli info: what a scene holds once loaded.", "jtracer-cli info"};
    app.footer(
        "Prints the primitives of each kind; each mesh with its file, triangles, vertices,\n"
        "where its normals come from, its box in world space and the time it took to read;\n"
        "the scene's world box; each image map's size and memory; the lights; the cameras\n"
        "and where they look; and an estimate of the prepared scene's memory.\n"
        "\n"
        "Examples:\n"
        "  jtracer-cli info scenes/mesh.jts\n"
        "  jtracer-cli info scenes/mesh.jts --json\n"
        "\n"
        "Exit codes: 0 ok, 1 errors in the scene, 2 bad command line, 3 a file that cannot\n"
        "be read.\n");
    app.add_option("scene", scene_path, "The scene file (.jts)")->required();
    app.add_flag("--json", json_output, "Print it all as one JSON object");
    if (std::optional<int> code = parse_command_line(app, argc, argv, "jtracer-cli info"))
        return *code;
    Expected<LoadedScene> loaded = load_scene_file(scene_path, {.source_map = false});
    if (!loaded) {
        std::cerr << "jtracer-cli info: " << loaded.error().message << "\n";
        return exit_io_error;
    }
    std::vector<Diagnostic> diagnostics = check_scene(*loaded);
    name_setting_flags(diagnostics);
    if (has_errors(diagnostics)) {
        std::cerr << format_diagnostics(diagnostics, loaded->path, loaded->text);
        return exit_scene_error;
    }
    const Expected<json> description = describe(loaded->parsed.scene);
    if (!description) {
        std::cerr << "jtracer-cli info: " << description.error().message << "\n";
        return exit_io_error;
    }
    if (json_output)
        std::cout << description->dump() << "\n";
    else
        print_text(*description);
    return exit_ok;
}

}  // namespace jt::cli
