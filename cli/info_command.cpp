#include "info_command.hpp"

#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/render_flags.hpp"
#include "jtracer/parallel_chunks.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/scene_info.hpp"
#include "jtracer/validate.hpp"
#include "jtracer/vector_unit.hpp"

#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace jt::cli {

using nlohmann::json;
using namespace frontend;

namespace {

json vec(const Vec3& v) {
    return json::array({v.x, v.y, v.z});
}
json box_json(const WorldBox& b) {
    return b.empty() ? json() : json{{"lower", vec(*b.lower)}, {"upper", vec(*b.upper)}};
}

// Everything `info` reports, as JSON; the text form is printed from it.
Expected<json> describe(const Scene& scene) {
    const Expected<SceneInfo> info = scene_info(scene);
    if (!info) return info.error();
    json out;
    json meshes = json::array();
    for (const MeshInfo& m : info->meshes) {
        json parts = json::array();
        for (const MeshPartInfo& part : m.parts)
            parts.push_back({{"name", part.name},
                             {"base_colour", part.base ? vec(*part.base) : json()},
                             {"texture", part.texture},
                             {"vertex_colours", part.vertex_colours},
                             {"triangles", part.triangles}});
        meshes.push_back({{"file", m.file},
                          {"path", m.path.string()},
                          {"triangles", m.triangles},
                          {"vertices", m.vertices},
                          {"normals", m.normals},
                          {"shading", m.shading},
                          {"bbox", box_json(m.world_box)},
                          {"load_seconds", m.load_seconds},
                          {"read_before", m.read_before},
                          {"materials", m.materials},
                          {"parts", parts}});
    }
    out["primitives"] = info->primitives;
    out["meshes"] = meshes;
    out["bbox"] = box_json(info->world_box);
    out["unbounded"] = info->unbounded;
    out["left_out"] = info->left_out;

    json maps = json::array();
    for (const ImageMapInfo& map : info->image_maps)
        maps.push_back({{"path", map.path.string()},
                        {"width", map.width},
                        {"height", map.height},
                        {"bytes", map.bytes}});
    out["image_maps"] = maps;
    const std::optional<ImageMapInfo>& sky = info->background_map;
    out["background_map"] = sky ? json{{"path", sky->path.string()},
                                       {"width", sky->width},
                                       {"height", sky->height},
                                       {"bytes", sky->bytes}}
                                : json();

    json lights = json::array();
    for (const PointLight& l : scene.lights)
        lights.push_back({{"position", vec(l.position)},
                          {"intensity", vec(l.intensity)},
                          {"radius", l.radius},
                          {"shadow_samples", l.shadow_samples}});
    out["lights"] = lights;

    json cameras = json::array();
    const int active = active_camera_index(scene);
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const Camera& c = scene.cameras[i];
        cameras.push_back(
            {{"name", c.name},
             {"position", vec(c.position)},
             {"look_at", vec(c.look_at)},
             {"direction", vec(glm::normalize(c.look_at - c.position))},
             {"fov", c.fov},
             {"aperture", c.aperture},
             // The default: the distance to look_at (docs/language.md §14.2).
             {"focus_distance", c.focus_distance.value_or(glm::length(c.look_at - c.position))},
             {"active", static_cast<int>(i) == active}});
    }
    out["cameras"] = cameras;
    const SceneMemory& memory = info->memory;
    out["memory"] = {{"models", memory.models},
                     {"image_maps", memory.image_maps},
                     {"primitives", memory.primitives},
                     {"embree", memory.embree},
                     {"total", memory.total()}};
    out["vector_unit"] = vector_unit_name(vector_unit().unit);
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
        // With materials "file": each part of the model and what colours it.
        for (const json& part : m["parts"]) {
            const std::string name = part["name"].get<std::string>();
            std::cout << "  part " << (name.empty() ? "(no material)" : "\"" + name + "\"") << ": "
                      << part["triangles"] << " triangles";
            if (!part["base_colour"].is_null())
                std::cout << ", base colour " << vec_text(part["base_colour"]);
            if (!part["texture"].get<std::string>().empty())
                std::cout << ", texture " << part["texture"].get<std::string>();
            if (part["vertex_colours"].get<bool>()) std::cout << ", vertex colours";
            std::cout << "\n";
        }
    }
    std::cout << "world box: " << box_text(d["bbox"]);
    if (d["unbounded"].get<int>() > 0)
        std::cout << " (and " << d["unbounded"] << " unbounded planes)";
    std::cout << "\n";
    for (const json& map : d["image_maps"])
        std::cout << "image map " << map["path"].get<std::string>() << ": " << map["width"] << "x"
                  << map["height"] << ", " << mib(map["bytes"].get<std::size_t>()) << "\n";
    if (const json& sky = d["background_map"]; !sky.is_null())
        std::cout << "background map " << sky["path"].get<std::string>() << ": " << sky["width"]
                  << "x" << sky["height"] << ", " << mib(sky["bytes"].get<std::size_t>()) << "\n";
    for (const json& l : d["lights"]) {
        std::cout << "point light at " << vec_text(l["position"]) << ", intensity "
                  << vec_text(l["intensity"]);
        // Soft shadows only when they are: a radius of 0 is the point light.
        if (l["radius"].get<double>() > 0.0)
            std::cout << ", radius " << l["radius"] << " (" << l["shadow_samples"]
                      << " shadow samples)";
        std::cout << "\n";
    }
    for (const json& c : d["cameras"])
        std::cout << "camera \"" << c["name"].get<std::string>() << "\""
                  << (c["active"].get<bool>() ? " (active)" : "") << ": at "
                  << vec_text(c["position"]) << " looking at " << vec_text(c["look_at"])
                  << " (direction " << vec_text(c["direction"]) << "), fov " << c["fov"]
                  << (c["aperture"].get<double>() > 0.0
                          ? ", aperture " + c["aperture"].dump() + ", in focus at " +
                                c["focus_distance"].dump()
                          : std::string())
                  << "\n";
    const json& memory = d["memory"];
    std::cout << "memory of the prepared scene: " << mib(memory["total"].get<std::size_t>())
              << " (models " << mib(memory["models"].get<std::size_t>()) << ", image maps "
              << mib(memory["image_maps"].get<std::size_t>())
              << ", Embree's acceleration structure and triangles "
              << mib(memory["embree"].get<std::size_t>()) << ")\n";
    std::cout << "vector unit of JTracer's batched tests: " << d["vector_unit"].get<std::string>()
              << " (" << kVectorUnitVariable << "=sse2 or avx picks one; the image is the same)\n";
}

}  // namespace

int run_info_command(int argc, char** argv) {
    std::string scene_path;
    bool json_output = false;
    CLI::App app{"jtracer-cli info: what a scene holds once loaded.", "jtracer-cli info"};
    app.footer(
        "Prints the primitives of each kind; each mesh with its file, triangles, vertices,\n"
        "where its normals come from, its box in world space and the time it took to read\n"
        "(with materials \"file\", each part of the model: its material, base colour,\n"
        "texture and vertex colours);\n"
        "the scene's world box; each image map's and the background map's size and memory;\n"
        "the lights; the cameras and where they look; and the prepared scene's memory,\n"
        "Embree's counted as it builds (info prepares the scene as a render would);\n"
        "and the vector unit JTracer's own batched tests run on.\n"
        "The scene's warnings go to stderr, as a render prints them.\n"
        "\n"
        "Examples:\n"
        "  jtracer-cli info scenes/mesh.jts\n"
        "  jtracer-cli info scenes/mesh.jts --json\n"
        "  jtracer-cli info scenes/orbit.jts --clock 0.5\n"
        "\n"
        "Exit codes: 0 ok, 1 errors in the scene, 2 bad command line, 3 a file that cannot\n"
        "be read.\n");
    app.add_option("scene", scene_path, "The scene file (.jts)")->required();
    app.add_flag("--json", json_output, "Print it all as one JSON object");
    // The scene a render with these values would hold: a camera that moves
    // with clock is shown where it stands at that clock.
    std::vector<std::string> defines;
    std::optional<double> clock;
    add_scene_value_flags(app, defines, clock);
    if (std::optional<int> code = parse_command_line(app, argc, argv, "jtracer-cli info", [&] {
            check_defines_at_their_clocks(defines, clock, {});
        }))
        return *code;
    ParseOptions options = scene_value_options(defines, clock);
    options.source_map = false;
    Expected<LoadedScene> loaded = load_scene_file(scene_path, options);
    if (!loaded) {
        std::cerr << "jtracer-cli info: " << loaded.error().message << "\n";
        return exit_io_error;
    }
    std::vector<Diagnostic> diagnostics = check_scene(
        *loaded, {.validation = {.run_chunks = parallel_chunks(), .primitives_as_parsed = true}});
    // The image's size is a render's to set (--width, --height), and info,
    // which takes neither, describes the scene whatever size it renders at.
    std::erase_if(diagnostics, asks_for_frame_size);
    // Warnings too, as a render prints them: a mesh left out (a model of
    // lines only) or part of a model dropped shows here as 0 triangles or a
    // smaller box, which only the warning explains.
    if (!diagnostics.empty()) std::cerr << format_diagnostics(diagnostics, *loaded);
    if (has_errors(diagnostics)) return exit_scene_error;
    const Expected<json> description = describe(loaded->parsed.scene);
    if (!description) {
        std::cerr << "jtracer-cli info: " << description.error().message << "\n";
        return exit_io_error;
    }
    if (json_output)
        // Paths are bytes, not always UTF-8 (a folder named in Latin-1): such a
        // byte is replaced (U+FFFD) rather than thrown at.
        std::cout << description->dump(-1, ' ', false, json::error_handler_t::replace) << "\n";
    else
        print_text(*description);
    return exit_ok;
}

}  // namespace jt::cli
