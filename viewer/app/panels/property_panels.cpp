// The panels and editors that are a block's properties, drawn from the
// schema: render settings, lights, and an object's material and transforms.

#include "app/panels/panels.hpp"

#include "app/panels/property_fields.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/document_edits.hpp"
#include "model/edit_commands.hpp"
#include "model/picking.hpp"

#include <imgui.h>

#include <cstdio>
#include <functional>
#include <string>

namespace jt::view {

void settings_panel(AppState& state) {
    if (!panel_header("Render settings", "Render settings", true)) return;
    ImGui::BeginDisabled(!state.doc.loaded);
    RenderSettings& s = state.doc.scene.settings;
    const EditedBlock block{EditedBlock::Kind::settings, 0};
    settle_block(state.history, state.doc, block);
    const SceneDocument& doc = state.doc;
    const BlockSource* source = block_source(doc, block);
    bool changed = edit_properties(
        s, doc, [&](std::string_view name) { return field_source(doc, source, name); });
    {
        const FieldMark mark(&doc, field_source(doc, source, "background_map"));
        const bool typed =
            edit_file_name("background_map", s.background_map,
                           "A PNG, JPEG or BMP file, relative to the scene's folder, seen "
                           "wherever a ray meets nothing (equirectangular: its centre "
                           "straight down -z); empty: the background colour. Enter applies "
                           "it; the render follows the file when it changes on disk.");
        changed = (typed && !mark.read_only()) || changed;
    }
    if (changed) note_block_edited(state.history, state.doc, block);
    ImGui::EndDisabled();
}

void lights_panel(AppState& state) {
    auto& lights = state.doc.scene.lights;
    const Selection selection = current_selection(state.view, state.doc.scene);
    const int selected = selection.kind == Selection::Kind::light ? selection.index : -1;
    const bool reveal = state.view.reveal_selection && selected >= 0;
    if (reveal) ImGui::SetNextItemOpen(true);
    char title[48];
    std::snprintf(title, sizeof title, "Lights (%zu)###lights", lights.size());
    if (!panel_header(title, "Lights", false)) return;
    std::function<void()> command;
    if (button("Add point light", "Add a white light above the camera the view shows"))
        command = [&state] { add_light(state); };
    for (std::size_t i = 0; i < lights.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        char label[48];
        std::snprintf(label, sizeof label, "point_light %zu", i + 1);
        const bool chosen = static_cast<int>(i) == selected;
        if (reveal && chosen) ImGui::SetNextItemOpen(true);
        const bool open = ImGui::TreeNodeEx(label, chosen ? ImGuiTreeNodeFlags_Selected : 0);
        note_item(label, false);
        if (reveal && chosen) scroll_here_if_hidden();
        if (open) {
            const BlockRef ref{BlockKind::light, i};
            const std::string included = why_not_rewrite_block(state.doc, ref);
            if (button("Duplicate", "Add a copy of this light's block right after it", included))
                command = [&state, ref] { duplicate_block(state, ref); };
            same_line_if_fits("Delete");
            if (button("Delete", "Remove this light's block from the text (Ctrl+Z brings it back)",
                       included))
                command = [&state, ref] { delete_block(state, ref); };
            const EditedBlock block{EditedBlock::Kind::light, i};
            settle_block(state.history, state.doc, block);
            const BlockSource* source = block_source(state.doc, block);
            shared_text_line(state.doc, source);
            if (edit_properties(lights[i], state.doc, [&](std::string_view name) {
                    return field_source(state.doc, source, name);
                }))
                note_block_edited(state.history, state.doc, block);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (command) command();
}

bool material_editor(Material& m, const SceneDocument& doc, const BlockSource* primitive) {
    const auto source_of = [&](std::string_view name) {
        return material_field_source(doc, primitive, name);
    };
    bool changed = edit_properties(m, doc, source_of);
    const FieldMark mark(&doc, source_of("image_map"));
    const bool typed =
        edit_file_name("image_map", m.finish.edit().image_map,
                       "A PNG, JPEG or BMP file, relative to the scene's folder, mapped "
                       "onto the object (map_size is one tile); empty: none. Enter "
                       "applies it.");
    return (typed && !mark.read_only()) || changed;
}

std::optional<TransformCommand> transform_editor(std::vector<TransformOp>& transforms,
                                                 bool& changed, const SceneDocument& doc,
                                                 const BlockSource* primitive,
                                                 const std::string& why_not) {
    std::optional<TransformCommand> command;
    if (transforms.empty()) ImGui::TextDisabled("no transform operations");
    const std::size_t count = transforms.size();
    for (std::size_t i = 0; i < count; ++i) {
        ImGui::PushID(static_cast<int>(i));
        changed = edit_property(transform_op(transforms[i].kind).property, transforms[i], &doc,
                                transform_field_source(doc, primitive, i)) ||
                  changed;
        if (button("Up", "Move this operation one place earlier (applied before the one above)",
                   !why_not.empty() ? why_not.c_str()
                   : i == 0         ? "It is already the first"
                                    : ""))
            command = TransformCommand{TransformCommand::Kind::move, i, i - 1, {}};
        ImGui::SameLine();
        if (button("Down", "Move this operation one place later",
                   !why_not.empty() ? why_not.c_str()
                   : i + 1 == count ? "It is already the last"
                                    : ""))
            command = TransformCommand{TransformCommand::Kind::move, i, i + 1, {}};
        ImGui::SameLine();
        if (button("Remove", "Remove this operation from the transform", why_not))
            command = TransformCommand{TransformCommand::Kind::remove, i, 0, {}};
        ImGui::PopID();
    }
    if (button("Add operation", "Append an operation to the transform (applied last)", why_not))
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
