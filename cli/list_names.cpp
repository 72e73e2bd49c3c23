#include "list_names.hpp"

#include "jtracer/frontend/render_flags.hpp"
#include "jtracer/scene_file.hpp"

#include <iostream>

namespace jt::cli {

using namespace frontend;

int list_cameras(const std::string& scene_path) {
    const Expected<LoadedScene> loaded = load_scene_file(scene_path, {.source_map = false});
    if (!loaded) {
        std::cerr << "jtracer-cli: " << loaded.error().message << "\n";
        return exit_io_error;
    }
    for (const Camera& camera : loaded->parsed.scene.cameras) std::cout << camera.name << "\n";
    return exit_ok;
}

int list_defines(const std::string& scene_path) {
    // The source map records every definition, in file order.
    const Expected<LoadedScene> loaded = load_scene_file(scene_path);
    if (!loaded) {
        std::cerr << "jtracer-cli: " << loaded.error().message << "\n";
        return exit_io_error;
    }
    for (const DefinitionSource& d : loaded->parsed.source.definitions)
        if (!d.material_properties) std::cout << d.name << "\n";  // a material is no value
    return exit_ok;
}

}  // namespace jt::cli
