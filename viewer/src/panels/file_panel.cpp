#include "app_actions.hpp"
#include "panels/panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace jt::view {

void file_panel(AppState& state) {
    if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::TextWrapped("%s", state.doc.path.empty() ? "(no scene)" : state.doc.path.c_str());
    ImGui::SetNextItemWidth(-70);
    const bool enter = ImGui::InputTextWithHint("##open", "scene.jts", &state.open_path_input,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && !state.open_path_input.empty())
        open_scene(state, state.open_path_input);
    if (!state.recent.paths().empty()) {
        ImGui::SetNextItemWidth(-70);
        if (ImGui::BeginCombo("Recent", state.recent.paths().front().c_str())) {
            std::string chosen;
            for (const std::string& path : state.recent.paths())
                if (ImGui::Selectable(path.c_str())) chosen = path;
            ImGui::EndCombo();
            if (!chosen.empty()) open_scene(state, chosen);
        }
    }
    if (ImGui::Button("Reload (R)")) reload_scene(state);
    ImGui::SameLine();
    ImGui::BeginDisabled(!has_unsaved_edits(state.doc));
    if (ImGui::Button("Save scene (Ctrl+S)")) save_scene(state);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!state.undo.can_undo());
    if (ImGui::Button("Undo")) undo(state);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!state.undo.can_redo());
    if (ImGui::Button("Redo")) redo(state);
    ImGui::EndDisabled();
    ImGui::SetNextItemWidth(-110);
    ImGui::InputText("##image", &state.save_image_path);
    ImGui::SameLine();
    if (ImGui::Button("Save image (S)")) save_image(state, state.save_image_path);
}

}  // namespace jt::view
