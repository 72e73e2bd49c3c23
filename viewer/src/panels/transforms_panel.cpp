#include "panels/panels.hpp"
#include "panels/widgets.hpp"

#include <imgui.h>

namespace jt::view {

void transform_editor(std::vector<TransformOp>& transforms) {
    if (transforms.empty()) {
        ImGui::TextDisabled("no transform");
        return;
    }
    for (std::size_t i = 0; i < transforms.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        TransformOp& op = transforms[i];
        switch (op.kind) {
            case TransformKind::translate:
                edit_vector("translate", op.vector);
                break;
            case TransformKind::scale:
                edit_vector("scale", op.vector, 0.01f);
                break;
            case TransformKind::xrotate:
                edit_number("xrotate", op.degrees, 0.5f);
                break;
            case TransformKind::yrotate:
                edit_number("yrotate", op.degrees, 0.5f);
                break;
            case TransformKind::zrotate:
                edit_number("zrotate", op.degrees, 0.5f);
                break;
        }
        ImGui::PopID();
    }
}

}  // namespace jt::view
