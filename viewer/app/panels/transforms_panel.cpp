#include "app/panels/panels.hpp"
#include "app/panels/property_fields.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"

#include <imgui.h>

#include <string>

namespace jt::view {

std::optional<TransformCommand> transform_editor(std::vector<TransformOp>& transforms,
                                                 bool& changed) {
    std::optional<TransformCommand> command;
    if (transforms.empty()) ImGui::TextDisabled("no transform operations");
    const std::size_t count = transforms.size();
    for (std::size_t i = 0; i < count; ++i) {
        ImGui::PushID(static_cast<int>(i));
        changed =
            edit_property(transform_op(transforms[i].kind).property, transforms[i]) || changed;
        if (button("Up", "Move this operation one place earlier (applied before the one above)",
                   i == 0 ? "It is already the first" : ""))
            command = TransformCommand{TransformCommand::Kind::move, i, i - 1, {}};
        ImGui::SameLine();
        if (button("Down", "Move this operation one place later",
                   i + 1 == count ? "It is already the last" : ""))
            command = TransformCommand{TransformCommand::Kind::move, i, i + 1, {}};
        ImGui::SameLine();
        if (button("Remove", "Remove this operation from the transform"))
            command = TransformCommand{TransformCommand::Kind::remove, i, 0, {}};
        ImGui::PopID();
    }
    if (button("Add operation", "Append an operation to the transform (applied last)"))
        ImGui::OpenPopup("add operation");
    if (ImGui::BeginPopup("add operation")) {
        for (const TransformOpSpec& spec : transform_ops()) {
            const std::string name(spec.property.name);
            if (ImGui::MenuItem(name.c_str()))
                command = TransformCommand{TransformCommand::Kind::add, 0, 0, spec.kind};
            note_item(name.c_str(), false);
        }
        ImGui::EndPopup();
    }
    return command;
}

}  // namespace jt::view
