#include "model/camera_commands.hpp"

#include "model/app_actions.hpp"

#include "jtracer/validate.hpp"
#include "jtracer/value_text.hpp"

#include <algorithm>

namespace jt::view {

namespace {

int scene_camera_index(const Scene& scene) {
    return std::max(active_camera_index(scene), 0);
}

std::string camera_label(const Camera& camera, int index) {
    return camera.name.empty() ? "camera " + std::to_string(index + 1) : camera.name;
}

}  // namespace

void keep_camera_selection(ViewState& view, const Scene& scene, const Scene& before) {
    const auto& cameras = scene.cameras;
    const int count = static_cast<int>(cameras.size());
    const int old = view.camera_index;
    if (old >= 0 && old < static_cast<int>(before.cameras.size())) {
        const std::string& name = before.cameras[old].name;
        if (old < count && cameras[old].name == name) return;
        if (const int same = name.empty() ? -1 : find_camera(scene, name); same >= 0) {
            view.camera_index = same;
            return;
        }
    }
    if (old < 0 || old >= count) view.camera_index = scene_camera_index(scene);
}

int selected_camera(const ViewState& view, const Scene& scene) {
    const int count = static_cast<int>(scene.cameras.size());
    if (count == 0) return -1;
    return std::clamp(view.camera_index, 0, count - 1);
}

void select_camera(AppState& state, int index) {
    const int count = static_cast<int>(state.doc.scene.cameras.size());
    if (count == 0) return;
    state.view.camera_index = std::clamp(index, 0, count - 1);
    state.view.free_camera_active = false;
    state.message = "Camera: " + camera_label(state.doc.scene.cameras[state.view.camera_index],
                                              state.view.camera_index);
}

void next_camera(AppState& state) {
    const int count = static_cast<int>(state.doc.scene.cameras.size());
    if (count == 0) return;
    select_camera(state, state.view.free_camera_active ? state.view.camera_index
                                                       : (state.view.camera_index + 1) % count);
}

void use_free_camera(ViewState& view, const Scene& scene) {
    if (view.free_camera_active || scene.cameras.empty()) return;
    reset_free_camera(view, scene);
    view.free_camera_active = true;
}

void reset_free_camera(ViewState& view, const Scene& scene) {
    const auto& cameras = scene.cameras;
    if (cameras.empty()) return;
    view.free_camera = free_camera_from(cameras[selected_camera(view, scene)]);
}

bool copy_free_camera_to_scene(AppState& state, const std::string& name) {
    if (!state.doc.loaded || state.doc.scene.cameras.empty()) return false;
    if (find_camera(state.doc.scene, name) >= 0) {
        state.message = "A camera is already called \"" + name + "\": choose another name";
        return false;
    }
    const Scene before = state.doc.scene;
    const FreeCamera from =
        state.view.free_camera_active
            ? state.view.free_camera
            : free_camera_from(
                  state.doc.scene.cameras[selected_camera(state.view, state.doc.scene)]);
    Camera camera = camera_from(from, name);
    if (state.view.free_camera_active) {  // moved with the mouse: short numbers in the file
        camera.position = ui_rounded(camera.position);
        camera.look_at = ui_rounded(camera.look_at);
    }
    const DocumentVersion version = version_of(state.doc);
    state.doc.scene.cameras.push_back(std::move(camera));
    state.history.undo.record(version);
    note_command_edit(state.history, state.doc);
    state.view.camera_index = static_cast<int>(state.doc.scene.cameras.size()) - 1;
    state.view.free_camera_active = false;
    state.message = "Added camera \"" + name + "\" (Save scene to keep it)";
    return true;
}

}  // namespace jt::view
