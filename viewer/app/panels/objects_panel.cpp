#include "panels/panels.hpp"
#include "panels/property_fields.hpp"
#include "ui_items.hpp"

#include <imgui.h>

#include <string>
#include <variant>

namespace jt::view {

namespace {

void shape_editor(Shape& shape) {
    std::visit([](auto& s) { edit_properties(s); }, shape);
}

}  // namespace

void objects_panel(AppState& state) {
    auto& primitives = state.doc.scene.primitives;
    const std::string title = "Objects (" + std::to_string(primitives.size()) + ")###objects";
    if (!panel_header(title.c_str(), "Objects", false)) return;
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        Primitive& p = primitives[i];
        ImGui::PushID(static_cast<int>(i));
        const Colour& c = p.material.pigment;
        ImGui::ColorButton("##swatch", ImVec4(float(c.x), float(c.y), float(c.z), 1.0f),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::SameLine();
        const std::string label = std::string(keyword_of(p.shape)) + " " + std::to_string(i + 1);
        const bool open = ImGui::TreeNode(label.c_str());
        note_item(label.c_str(), false);
        if (open) {
            shape_editor(p.shape);
            ImGui::Separator();
            ImGui::TextDisabled("material");
            material_editor(p.material);
            ImGui::Separator();
            ImGui::TextDisabled("transform");
            transform_editor(p.transforms);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

}  // namespace jt::view
