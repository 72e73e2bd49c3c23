// Embeds JTracer as another program would: parses a scene from a string,
// renders it and checks the sphere in the middle is lit red and the corner
// is the background; reads a model file, which needs the installed model
// reader module. Prints the version; exits non-zero on any surprise.

#include <jtracer/model_file.hpp>
#include <jtracer/parser.hpp>
#include <jtracer/render_job.hpp>
#include <jtracer/validate.hpp>
#include <jtracer/version.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

int main() {
    const jt::ParseResult parsed = jt::parse_scene(R"(
        render_settings { width: 32; height: 32; background: <0, 0, 1>; }
        cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }
        scene {
            sphere { material { pigment: <1, 0, 0>; diffuse: <1, 1, 1>; } }
            point_light { position: <0, 0, 10>; intensity: <1, 1, 1>; }
        }
    )");
    jt::RenderOptions options;
    options.width = parsed.scene.settings.width;
    options.height = parsed.scene.settings.height;
    options.camera = jt::active_camera_index(parsed.scene);
    const jt::Expected<std::shared_ptr<const jt::PreparedScene>> prepared =
        jt::prepare_scene(parsed.scene);
    if (!prepared) {
        std::printf("%s\n", prepared.error().message.c_str());
        return 1;
    }
    const jt::Image8 image = jt::render_image(*prepared, options);
    const std::uint8_t* centre = image.pixel(16, 16);
    const std::uint8_t* corner = image.pixel(0, 0);
    std::printf("JTracer %s: centre %d,%d,%d corner %d,%d,%d\n", jt::version_string(), centre[0],
                centre[1], centre[2], corner[0], corner[1], corner[2]);
    const bool ok =
        centre[0] > 200 && centre[1] == 0 && centre[2] == 0 && corner[0] == 0 && corner[2] == 255;

    const std::filesystem::path folder = std::filesystem::temp_directory_path();
    const std::filesystem::path quad = folder / "jtracer_consumer_quad.obj";
    std::ofstream(quad) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    const jt::Expected<jt::Model> model = jt::read_model(quad, folder);
    std::filesystem::remove(quad);
    if (!model) {
        std::printf("%s\n", model.error().message.c_str());
        return 1;
    }
    std::printf("quad.obj: %zu triangles\n", model->triangles.size());
    return ok && model->triangles.size() == 2 ? 0 : 1;
}
