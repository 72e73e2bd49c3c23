#include "app/panels/panels.hpp"
#include "app/panels/property_fields.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"

#include <imgui.h>

#include <functional>
#include <string>

namespace jt::view {

void lights_panel(AppState& state) {
    auto& lights = state.doc.scene.lights;
    const Selection selection = current_selection(state.view, state.doc.scene);
    const int selected = selection.kind == Selection::Kind::light ? selection.index : -1;
    const bool reveal = state.view.reveal_selection && selected >= 0;
    if (reveal) ImGui::SetNextItemOpen(true);
    const std::string title = "Lights (" + std::to_string(lights.size()) + ")###lights";
    if (!panel_header(title.c_str(), "Lights", false)) return;
    std::function<void()> command;
    if (button("Add point light", "Add a white light above the camera the view shows"))
        command = [&state] { add_light(state); };
    for (std::size_t i = 0; i < lights.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        const std::string label = "point_light " + std::to_string(i + 1);
        const bool chosen = static_cast<int>(i) == selected;
        if (reveal && chosen) ImGui::SetNextItemOpen(true);
        const bool open =
            ImGui::TreeNodeEx(label.c_str(), chosen ? ImGuiTreeNodeFlags_Selected : 0);
        note_item(label.c_str(), false);
        if (reveal && chosen) scroll_here_if_hidden();
        if (open) {
            const BlockRef ref{BlockKind::light, i};
            if (button("Duplicate", "Add a copy of this light's block right after it"))
                command = [&state, ref] { duplicate_block(state, ref); };
            same_line_if_fits("Delete");
            if (button("Delete", "Remove this light's block from the text (Ctrl+Z brings it back)"))
                command = [&state, ref] { delete_block(state, ref); };
            if (edit_properties(lights[i])) note_scene_changed(state.doc);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (command) command();
}

}  // namespace jt::view
