#include "app_actions.hpp"
#include "panels/panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include "jtracer/validate.hpp"

#include <algorithm>

namespace jt::view {

void camera_panel(AppState& state) {
    if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const auto& cameras = state.doc.scene.cameras;
    auto label = [&](int i) {
        return cameras[i].name.empty() ? "camera " + std::to_string(i + 1) : cameras[i].name;
    };
    const std::string current = state.free_camera_active ? "free camera"
                                : cameras.empty()        ? "(none)"
                                                         : label(state.camera_index);
    if (ImGui::BeginCombo("View", current.c_str())) {
        for (int i = 0; i < static_cast<int>(cameras.size()); ++i)
            if (ImGui::Selectable(label(i).c_str(),
                                  !state.free_camera_active && i == state.camera_index))
                select_camera(state, i);
        if (ImGui::Selectable("free camera", state.free_camera_active)) use_free_camera(state);
        ImGui::EndCombo();
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("Drag on the image: left orbits, right/middle pans, wheel dollies.");
    ImGui::PopStyleColor();
    if (ImGui::Button("Reset to scene camera")) {
        reset_free_camera(state);
        state.free_camera_active = false;
    }
    if (!state.free_camera_active && !cameras.empty()) {
        const std::string& name = cameras[state.camera_index].name;
        const bool is_active =
            label(state.camera_index) == label(std::max(0, active_camera_index(state.doc.scene)));
        ImGui::SameLine();
        ImGui::BeginDisabled(is_active || name.empty());
        if (ImGui::Button("Make active"))
            edit_scene(state, [&](Scene& s) { s.settings.active_camera = name; });
        ImGui::EndDisabled();
    }
    ImGui::SetNextItemWidth(140);
    ImGui::InputText("##name", &state.new_camera_name);
    ImGui::SameLine();
    ImGui::BeginDisabled(state.new_camera_name.empty() || !state.doc.loaded);
    if (ImGui::Button("Copy to scene")) copy_free_camera_to_scene(state, state.new_camera_name);
    ImGui::EndDisabled();
    if (state.free_camera_active) {
        FreeCamera& free = state.free_camera;
        ImGui::Text("position <%.3g, %.3g, %.3g>", free.position.x, free.position.y,
                    free.position.z);
        ImGui::Text("look_at  <%.3g, %.3g, %.3g>", free.look_at.x, free.look_at.y, free.look_at.z);
    }
}

}  // namespace jt::view
