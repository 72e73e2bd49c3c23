#include "model/camera_commands.hpp"

#include "model/app_actions.hpp"
#include "model/picking.hpp"

#include "jtracer/pick.hpp"
#include "jtracer/schema.hpp"

#include "jtracer/validate.hpp"
#include "jtracer/value_text.hpp"

#include <glm/geometric.hpp>

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
    keep_camera_selection(view, scene, before.cameras);
}

void keep_camera_selection(ViewState& view, const Scene& scene,
                           const std::vector<Camera>& cameras_before) {
    const auto& cameras = scene.cameras;
    const int count = static_cast<int>(cameras.size());
    const int old = view.camera_index;
    if (old >= 0 && old < static_cast<int>(cameras_before.size())) {
        const std::string& name = cameras_before[old].name;
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
    // Typed text with errors is the document (the panels are read-only): a
    // camera added to the last good scene would be in no text, lost when the
    // text parses.
    if (state.doc.draft) {
        state.message = "Not added: the text has errors; fix them first";
        return false;
    }
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

bool focus_camera_at(AppState& state, int x, int y) {
    if (state.doc.draft) {  // as copy_free_camera_to_scene
        state.message = "Not focused: the text has errors; fix them first";
        return false;
    }
    if (state.view.free_camera_active) {
        state.message =
            "The free camera has no lens: choose a scene camera (View) to focus it with Ctrl+click";
        return false;
    }
    const int index = selected_camera(state.view, state.doc.scene);
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    if (index < 0 || !frame) {
        state.message = "No rendered image to focus on yet";
        return false;
    }
    const std::optional<PickedPrimitive> hit = pick_primitive(*frame, x, y);
    const std::optional<CameraRay> ray = camera_ray(*frame, {x + 0.5, y + 0.5});
    if (!hit || !ray) {
        state.message = "Nothing there to focus on: Ctrl+click a surface (the background has none)";
        return false;
    }
    Camera& camera = state.doc.scene.cameras[static_cast<std::size_t>(index)];
    // Section 5's f, and the hit as the tracer places it: origin + t * d.
    const Vec3 f = glm::normalize(camera.look_at - camera.position);
    const Vec3 point = ray->origin + ray->direction * hit->distance;
    const double depth = glm::dot(point - camera.position, f);
    if (!(depth > 0.0) || !std::isfinite(depth)) {
        state.message = "That surface is not in front of the camera: nothing to focus on";
        return false;
    }
    const std::string label = camera_label(camera, index);
    if (camera.focus_distance == depth) {
        state.message = label + " is focused there already (focus_distance " +
                        number_text(ui_rounded(depth)) + ")";
        return false;
    }
    edit_scene(state, [&](Scene& scene) {
        scene.cameras[static_cast<std::size_t>(index)].focus_distance = depth;
    });
    const Primitive& p = state.doc.scene.primitives[static_cast<std::size_t>(hit->primitive)];
    state.message = label + ": focus_distance " + number_text(ui_rounded(depth)) + " (on " +
                    std::string(keyword_of(p.shape)) + " " + std::to_string(hit->primitive + 1) +
                    ")";
    if (camera.aperture == 0.0) state.message += "; aperture is 0, so all stays sharp";
    return true;
}

}  // namespace jt::view
