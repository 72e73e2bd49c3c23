#include "jtracer/camera_edit.hpp"

#include "edit/scene_blocks.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/source_edit.hpp"
#include "jtracer/value_text.hpp"

#include <algorithm>
#include <charconv>
#include <optional>

namespace jt {

namespace {

bool name_taken(const Scene& scene, std::string_view name,
                std::optional<std::size_t> except = std::nullopt) {
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (i != except && scene.cameras[i].name == name) return true;
    return false;
}

// Why `name` cannot be camera `index`'s (nullopt: a new camera), if it cannot.
std::optional<std::string> name_problem(const Scene& scene, std::string_view name,
                                        std::optional<std::size_t> index) {
    if (name.empty()) return "a camera needs a name";
    if (!is_writable_string(name))
        return "the name \"" + std::string(name) +
               "\" cannot be written in a .jts string (printable ASCII without '\"')";
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (i != index && scene.cameras[i].name == name)
            return "camera " + std::to_string(i + 1) + " is already named \"" + std::string(name) +
                   "\": camera names must differ";
    return std::nullopt;
}

// The first value of `camera` outside its range, if any.
std::optional<std::string> value_problem(const Camera& camera) {
    for (const PropertySpec<Camera>& property : schema_of<Camera>().properties)
        if (auto problem = value_problem(property, camera)) return problem;
    return std::nullopt;
}

Expected<std::string> write(const SceneText& scene, const Scene& edited) {
    SourceEditResult result = apply_scene_edits(scene.text, scene.source, scene.scene, edited);
    if (!result.ok()) return Error{result.error};
    return std::move(result.text);
}

}  // namespace

std::string unique_camera_name(const Scene& scene, std::string_view base) {
    if (!name_taken(scene, base)) return std::string(base);
    // "front 2" counts on from 2; "front" from 1.
    std::string_view stem = base;
    int number = 1;
    const std::size_t space = base.rfind(' ');
    if (space != std::string_view::npos && space + 1 < base.size()) {
        const std::string_view digits = base.substr(space + 1);
        int parsed = 0;
        const auto [end, ec] =
            std::from_chars(digits.data(), digits.data() + digits.size(), parsed);
        if (ec == std::errc{} && end == digits.data() + digits.size() && parsed > 0) {
            stem = base.substr(0, space);
            number = parsed;
        }
    }
    for (;;) {
        std::string candidate = std::string(stem) + " " + std::to_string(++number);
        if (!name_taken(scene, candidate)) return candidate;
    }
}

Expected<std::string> add_camera(const SceneText& scene, const Camera& camera) {
    if (auto problem = name_problem(scene.scene, camera.name, std::nullopt)) return Error{*problem};
    if (auto problem = value_problem(camera)) return Error{*problem};
    Scene edited = scene.scene;
    edited.cameras.push_back(camera);
    return write(scene, edited);
}

Expected<std::string> set_camera(const SceneText& scene, std::size_t camera,
                                 const Camera& changed) {
    Expected<const BlockSource*> found = edit::find_block(scene, {BlockKind::camera, camera});
    if (!found) return found.error();
    const Camera& before = scene.scene.cameras[camera];
    Scene edited = scene.scene;
    if (changed.name != before.name) {
        if (auto problem = name_problem(scene.scene, changed.name, camera)) return Error{*problem};
        // An active_camera naming it follows it to its new name.
        if (!before.name.empty() && edited.settings.active_camera == before.name &&
            !name_taken(scene.scene, before.name, camera))
            edited.settings.active_camera = changed.name;
    }
    if (auto problem = value_problem(changed))
        return Error{"camera " + std::to_string(camera + 1) + ": " + *problem};
    edited.cameras[camera] = changed;
    return write(scene, edited);
}

Expected<std::string> rename_camera(const SceneText& scene, std::size_t camera,
                                    std::string_view name) {
    Expected<const BlockSource*> found = edit::find_block(scene, {BlockKind::camera, camera});
    if (!found) return found.error();
    Camera renamed = scene.scene.cameras[camera];
    renamed.name = std::string(name);
    return set_camera(scene, camera, renamed);
}

Expected<std::string> set_aspect_from_image(const SceneText& scene, std::size_t camera) {
    Expected<const BlockSource*> found = edit::find_block(scene, {BlockKind::camera, camera});
    if (!found) return found.error();
    const RenderSettings& settings = scene.scene.settings;
    if (settings.width <= 0 || settings.height <= 0)
        return Error{"the image has no size yet: set render_settings' width and height first"};
    Camera changed = scene.scene.cameras[camera];
    changed.aspect = static_cast<double>(settings.width) / settings.height;
    return set_camera(scene, camera, changed);
}

}  // namespace jt
