#include "panels/panels.hpp"
#include "panels/widgets.hpp"

#include <imgui.h>

#include <string>
#include <variant>

namespace jt::view {

namespace {

const char* shape_name(const Shape& shape) {
    if (std::holds_alternative<Sphere>(shape)) return "sphere";
    if (std::holds_alternative<Plane>(shape)) return "plane";
    return "cylinder";
}

void shape_editor(Shape& shape) {
    if (auto* s = std::get_if<Sphere>(&shape)) {
        edit_vector("center", s->center);
        edit_number("radius", s->radius, 0.01f, 1e-4, 1e6);
    } else if (auto* p = std::get_if<Plane>(&shape)) {
        edit_vector("normal", p->normal, 0.01f);
        edit_number("distance", p->distance, 0.01f);
    } else if (auto* c = std::get_if<Cylinder>(&shape)) {
        edit_number("radius", c->radius, 0.01f, 1e-4, 1e6);
        edit_number("height", c->height, 0.01f, 1e-4, 1e6);
    }
}

}  // namespace

void objects_panel(AppState& state) {
    auto& primitives = state.doc.scene.primitives;
    const std::string title = "Objects (" + std::to_string(primitives.size()) + ")###objects";
    if (!ImGui::CollapsingHeader(title.c_str())) return;
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        Primitive& p = primitives[i];
        ImGui::PushID(static_cast<int>(i));
        const Colour& c = p.material.pigment;
        ImGui::ColorButton("##swatch", ImVec4(float(c.x), float(c.y), float(c.z), 1.0f),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::SameLine();
        const std::string label = std::string(shape_name(p.shape)) + " " + std::to_string(i + 1);
        if (ImGui::TreeNode(label.c_str())) {
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
