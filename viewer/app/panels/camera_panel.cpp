#include "app/panels/panels.hpp"
#include "app/panels/property_fields.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include "jtracer/validate.hpp"

#include <cstdio>
#include <functional>

namespace jt::view {

namespace {

// A camera's name, or "camera 2" written into `unnamed` for one without a name.
const char* camera_label(const Scene& scene, int i, char (&unnamed)[32]) {
    if (!scene.cameras[i].name.empty()) return scene.cameras[i].name.c_str();
    std::snprintf(unnamed, sizeof unnamed, "camera %d", i + 1);
    return unnamed;
}

// Why "Make active" cannot be pressed for the selected camera, or empty.
const char* why_not_make_active(const Scene& scene, int selected) {
    if (scene.cameras[selected].name.empty())
        return "Only a named camera can be made active: give it a name: in the file";
    if (selected == active_camera_index(scene))
        return "This camera is already the one jtracer-cli renders (active_camera)";
    return "";
}

// The selected scene camera's name and numbers, and the commands on it. The
// commands run after its fields are drawn: they replace the camera list.
void scene_camera_editor(AppState& state, int selected) {
    ImGui::Separator();
    ImGui::TextDisabled("scene camera %d", selected + 1);
    Camera& camera = state.doc.scene.cameras[static_cast<std::size_t>(selected)];
    const std::size_t index = static_cast<std::size_t>(selected);
    std::function<void()> command;
    if (state.fields.camera_name_for != selected || !state.fields.camera_name_editing)
        state.fields.camera_name_input = camera.name;
    state.fields.camera_name_for = selected;
    const bool entered = ImGui::InputText("name", &state.fields.camera_name_input,
                                          ImGuiInputTextFlags_EnterReturnsTrue);
    state.fields.camera_name_editing = ImGui::IsItemActive();
    note_item("name", true);
    tooltip("Type a new name and press Enter to rename the camera (active_camera follows)");
    if (entered && state.fields.camera_name_input != camera.name)
        command = [&state, index, name = state.fields.camera_name_input] {
            rename_camera(state, index, name);
        };
    const EditedBlock block{EditedBlock::Kind::camera, index};
    settle_block(state.history, state.doc, block);
    const BlockSource* source = block_source(state.doc, block);
    shared_text_line(state.doc, source);
    if (edit_properties(camera, state.doc, [&](std::string_view name) {
            return field_source(state.doc, source, name);
        }))
        note_block_edited(state.history, state.doc, block);
    const Scene& scene = state.doc.scene;
    const char* no_size = scene.settings.width > 0 && scene.settings.height > 0
                              ? ""
                              : "Set the image's width and height first";
    if (button("Set aspect from image", "aspect = width / height of render_settings", no_size))
        command = [&state, index] { set_aspect_from_image(state, index); };
    same_line_if_fits("Add camera");
    if (button("Add camera", "Add the view as a new camera (a copy of this one)"))
        command = [&state] { add_camera(state); };
    same_line_if_fits("Duplicate");
    const std::string included = why_not_rewrite_block(state.doc, {BlockKind::camera, index});
    if (button("Duplicate", "Add a copy of this camera's block, named anew", included))
        command = [&state, index] { duplicate_block(state, {BlockKind::camera, index}); };
    same_line_if_fits("Delete");
    if (button("Delete", "Remove this camera's block from the text",
               // A const char* on each branch: a std::string one would build a
               // string of the message every frame.
               !included.empty()          ? included.c_str()
               : scene.cameras.size() < 2 ? "The only camera: every render needs one"
                                          : ""))
        command = [&state, index] { delete_block(state, {BlockKind::camera, index}); };
    if (command) command();
}

}  // namespace

// Every read of the scene goes through `scene` and selected_camera() at the
// moment of reading: a command run earlier in this frame (Undo, a shortcut)
// may have replaced the scene and its camera list.
void camera_panel(AppState& state) {
    if (!panel_header("Camera", "Camera", true)) return;
    const Scene& scene = state.doc.scene;
    const int selected = selected_camera(state.view, state.doc.scene);
    char unnamed[32];
    const char* current = state.view.free_camera_active ? "free camera"
                          : selected < 0                ? "(none)"
                                                        : camera_label(scene, selected, unnamed);
    if (ImGui::BeginCombo("View", current)) {
        int chosen = -1;
        bool free = false;
        for (int i = 0; i < static_cast<int>(scene.cameras.size()); ++i)
            if (ImGui::Selectable(camera_label(scene, i, unnamed),
                                  !state.view.free_camera_active && i == selected))
                chosen = i;
        if (ImGui::Selectable("free camera", state.view.free_camera_active)) free = true;
        ImGui::EndCombo();
        if (chosen >= 0) select_camera(state, chosen);
        if (free) use_free_camera(state.view, state.doc.scene);
    }
    note_item("View", true);
    tooltip(
        "Which camera the view shows (C: next camera). Dragging on the image switches to the "
        "free camera.");
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped(
        "Drag on the image: left orbits, right pans, wheel dollies. "
        "(Middle drag, Space+drag, Ctrl+wheel: pan and zoom the image.)");
    ImGui::PopStyleColor();
    if (button("Reset to scene camera", "Leave the free camera and show the selected scene camera",
               state.view.free_camera_active ? "" : "The view already shows a scene camera")) {
        reset_free_camera(state.view, state.doc.scene);
        state.view.free_camera_active = false;
    }
    if (!state.view.free_camera_active && selected >= 0) {
        same_line_if_fits("Make active");
        const char* why = why_not_make_active(scene, selected);
        if (button("Make active",
                   "Make this camera the scene's active_camera (what jtracer-cli "
                   "renders); Save scene to keep it",
                   why)) {
            const std::string name = scene.cameras[selected].name;
            edit_scene(state, [&](Scene& s) { s.settings.active_camera = name; });
        }
    }
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    ImGui::InputText("##name", &state.fields.new_camera_name);
    note_item("camera name", true);
    tooltip("The name of the camera that Copy to scene adds");
    same_line_if_fits("Copy to scene");
    const char* why_not_copy = !state.doc.loaded || selected < 0 ? "No scene with a camera is open"
                               : state.fields.new_camera_name.empty()
                                   ? "Type a name for the new camera first"
                                   : "";
    if (button("Copy to scene", "Add the current view to the scene as a new camera", why_not_copy))
        copy_free_camera_to_scene(state, state.fields.new_camera_name);
    if (state.view.free_camera_active) {
        const FreeCamera& free = state.view.free_camera;
        ImGui::Text("position <%.3g, %.3g, %.3g>", free.position.x, free.position.y,
                    free.position.z);
        ImGui::Text("look_at  <%.3g, %.3g, %.3g>", free.look_at.x, free.look_at.y, free.look_at.z);
    }
    if (state.view.free_camera_active) {
        double fov = state.view.free_camera.fov;
        if (edit_number("free fov", fov, 0.5f, 1.0, 179.0,
                        [] { return std::string("must be from 1 to 179 degrees"); }))
            state.view.free_camera.fov = fov;
        tooltip("The free camera's vertical field of view, in degrees");
    }
    if (!state.view.free_camera_active && selected >= 0) scene_camera_editor(state, selected);
}

}  // namespace jt::view
