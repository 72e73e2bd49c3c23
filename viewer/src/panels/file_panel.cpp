#include "app_actions.hpp"
#include "panels/panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace jt::view {

namespace {

const ImVec4 warning_colour(1.0f, 0.7f, 0.3f, 1.0f);

// The file changed on disk while there are unsaved edits: nothing happens
// until the user says which to keep.
void reload_choice(AppState& state) {
    if (!state.pending_reload) return;
    ImGui::PushStyleColor(ImGuiCol_Text, warning_colour);
    ImGui::TextWrapped("%s was reloaded, but you have unsaved edits.",
                       state.doc.path.filename().c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("Reload, drop my edits")) resolve_reload(state, ReloadChoice::drop_edits);
    if (state.reapply_problem.empty()) {
        ImGui::SameLine();
        if (ImGui::Button("Reload, re-apply my edits"))
            resolve_reload(state, ReloadChoice::reapply_edits);
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep mine")) resolve_reload(state, ReloadChoice::keep_edits);
    if (!state.reapply_problem.empty())
        ImGui::TextDisabled("(edits cannot be re-applied: %s)", state.reapply_problem.c_str());
}

// Save scene was refused because the file changed on disk.
void save_conflict_choice(AppState& state) {
    if (state.save_conflict.empty() || state.pending_reload) return;
    ImGui::PushStyleColor(ImGuiCol_Text, warning_colour);
    ImGui::TextWrapped("Not saved: %s.", state.save_conflict.c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("Reload (choose what to keep)")) reload_scene(state);
    ImGui::SameLine();
    if (ImGui::Button("Save anyway")) save_scene_anyway(state);
    ImGui::SameLine();
    if (ImGui::Button("Cancel##conflict")) state.save_conflict.clear();
}

}  // namespace

void file_panel(AppState& state) {
    if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::TextWrapped("%s", state.doc.path.empty() ? "(no scene)" : state.doc.path.c_str());
    ImGui::SetNextItemWidth(-70);
    const bool enter = ImGui::InputTextWithHint("##open", "scene.jts", &state.open_path_input,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && !state.open_path_input.empty())
        request_open(state, state.open_path_input);
    if (!state.recent.paths().empty()) {
        ImGui::SetNextItemWidth(-70);
        if (ImGui::BeginCombo("Recent", state.recent.paths().front().c_str())) {
            std::string chosen;
            for (const std::string& path : state.recent.paths())
                if (ImGui::Selectable(path.c_str())) chosen = path;
            ImGui::EndCombo();
            if (!chosen.empty()) request_open(state, chosen);
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
    if (state.loader.busy()) ImGui::TextDisabled("Loading...");
    reload_choice(state);
    save_conflict_choice(state);
    ImGui::SetNextItemWidth(-110);
    ImGui::InputText("##image", &state.save_image_path);
    ImGui::SameLine();
    if (ImGui::Button("Save image (S)")) save_image(state, state.save_image_path);
}

}  // namespace jt::view
