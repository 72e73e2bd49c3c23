#include "panels/panels.hpp"
#include "panels/property_fields.hpp"
#include "ui_items.hpp"

#include <imgui.h>

#include <string>

namespace jt::view {

void lights_panel(AppState& state) {
    auto& lights = state.doc.scene.lights;
    const std::string title = "Lights (" + std::to_string(lights.size()) + ")###lights";
    if (!panel_header(title.c_str(), "Lights", false)) return;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        const std::string label = "point_light " + std::to_string(i + 1);
        const bool open = ImGui::TreeNode(label.c_str());
        note_item(label.c_str(), false);
        if (open) {
            edit_properties(lights[i]);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

}  // namespace jt::view
