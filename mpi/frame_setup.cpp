#include "frame_setup.hpp"

#include "jtracer/scene_file.hpp"
#include "jtracer/validate.hpp"

namespace jt::mpi {

namespace {

std::string camera_names(const Scene& scene) {
    std::string names;
    for (const Camera& c : scene.cameras) names += (names.empty() ? "\"" : ", \"") + c.name + "\"";
    return names.empty() ? "none" : names;
}

}  // namespace

FrameSetup set_up_frame(const Options& o) {
    FrameSetup setup;
    LoadedScene loaded = load_scene_file(o.scene_path);
    if (!loaded.read_ok()) {
        setup.exit_code = exit_io_error;
        setup.message = "jtracer-mpi: " + loaded.io_error + "\n";
        return setup;
    }
    // The overrides come before validation, so that the checks see what renders.
    Scene& scene = loaded.parsed.scene;
    if (o.width) scene.settings.width = *o.width;
    if (o.height) scene.settings.height = *o.height;
    if (o.samples) scene.settings.samples = *o.samples;
    if (o.camera) {
        if (find_camera(scene, *o.camera) < 0) {
            setup.exit_code = exit_usage;
            setup.message = "jtracer-mpi: --camera: the scene has no camera named \"" + *o.camera +
                            "\" (its cameras: " + camera_names(scene) + ")\n";
            return setup;
        }
        scene.settings.active_camera = *o.camera;
    }
    std::vector<Diagnostic> diagnostics = check_scene(loaded);
    const bool errors = has_errors(diagnostics);
    if (o.quiet && !errors) diagnostics.clear();  // quiet drops warnings, never errors
    setup.message = format_diagnostics(diagnostics, loaded.path, loaded.text);
    if (errors) {
        setup.exit_code = exit_scene_error;
        return setup;
    }
    setup.scene = std::move(scene);
    const RenderSettings& s = setup.scene.settings;
    setup.render.width = s.width;
    setup.render.height = s.height;
    setup.render.samples = s.samples;
    setup.render.camera = active_camera_index(setup.scene);
    setup.render.threads = o.threads;
    setup.render.previews = false;
    setup.output = o.output.value_or(s.filename);
    return setup;
}

}  // namespace jt::mpi
