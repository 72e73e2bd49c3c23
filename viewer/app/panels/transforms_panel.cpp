#include "panels/panels.hpp"
#include "panels/property_fields.hpp"

#include <imgui.h>

namespace jt::view {

void transform_editor(std::vector<TransformOp>& transforms) {
    if (transforms.empty()) {
        ImGui::TextDisabled("no transform");
        return;
    }
    for (std::size_t i = 0; i < transforms.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        edit_property(transform_op(transforms[i].kind).property, transforms[i]);
        ImGui::PopID();
    }
}

}  // namespace jt::view
