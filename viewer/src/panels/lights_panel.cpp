#include "panels/panels.hpp"
#include "panels/property_fields.hpp"

#include <imgui.h>

#include <string>

namespace jt::view {

void lights_panel(AppState& state) {
    auto& lights = state.doc.scene.lights;
    const std::string title = "Lights (" + std::to_string(lights.size()) + ")###lights";
    if (!ImGui::CollapsingHeader(title.c_str())) return;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        const std::string label = "point_light " + std::to_string(i + 1);
        if (ImGui::TreeNode(label.c_str())) {
            edit_properties(lights[i]);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

}  // namespace jt::view
