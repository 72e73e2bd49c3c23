#include "app/panels/panels.hpp"
#include "app/panels/property_fields.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "jtracer/texture.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace jt::view {

namespace {

bool shape_editor(Shape& shape, const SceneDocument& doc, const BlockSource* source) {
    return visit_shape(
        [&](auto& s) {
            return edit_properties(
                s, doc, [&](std::string_view name) { return field_source(doc, source, name); });
        },
        shape);
}

// "sphere 3": the object's keyword and its place among all objects.
struct ObjectName {
    char text[48];
};
ObjectName object_name(const Primitive& p, std::size_t index) {
    ObjectName name;
    const std::string_view keyword = keyword_of(p.shape);
    std::snprintf(name.text, sizeof name.text, "%.*s %zu", static_cast<int>(keyword.size()),
                  keyword.data(), index + 1);
    return name;
}

// The rows of the list: every object in scene order, or the ones the filter
// lets through.
struct ShownObjects {
    const std::vector<int>* filtered = nullptr;  // nullptr: all of them
    int count = 0;
    int operator[](int row) const {
        return filtered ? (*filtered)[static_cast<std::size_t>(row)] : row;
    }
};

ShownObjects shown_objects(TextFields& fields, const SceneDocument& doc) {
    const auto& primitives = doc.scene.primitives;
    if (fields.object_filter.empty()) return {nullptr, static_cast<int>(primitives.size())};
    if (fields.filtered_for != fields.object_filter || fields.filtered_revision != doc.revision) {
        fields.filtered.clear();
        for (std::size_t i = 0; i < primitives.size(); ++i)
            if (std::string_view(object_name(primitives[i], i).text).find(fields.object_filter) !=
                std::string_view::npos)
                fields.filtered.push_back(static_cast<int>(i));
        fields.filtered_for = fields.object_filter;
        fields.filtered_revision = doc.revision;
    }
    return {&fields.filtered, static_cast<int>(fields.filtered.size())};
}

// The row that lists object `i`, or -1 when the filter hides it.
int row_of(const ShownObjects& shown, int i) {
    if (!shown.filtered) return i < shown.count ? i : -1;
    const auto at = std::find(shown.filtered->begin(), shown.filtered->end(), i);
    return at == shown.filtered->end() ? -1 : static_cast<int>(at - shown.filtered->begin());
}

// One row a listed object; only the rows in view are drawn (ImGuiListClipper),
// so that a scene of 100,000 objects lists as fast as one of ten.
void object_list(AppState& state, const ShownObjects& shown, int selected) {
    auto& primitives = state.doc.scene.primitives;
    const float row = ImGui::GetTextLineHeightWithSpacing();
    const float height =
        std::min(static_cast<float>(shown.count), 10.0f) * row + ImGui::GetStyle().WindowPadding.y;
    if (state.view.reveal_selection && selected >= 0) scroll_here_if_hidden();  // the sidebar's
    ImGui::BeginChild("##object_list", ImVec2(0, std::max(height, row)), true);
    if (state.view.reveal_selection && selected >= 0) {
        const int at = row_of(shown, selected);
        if (at >= 0)
            ImGui::SetScrollY(static_cast<float>(at) * row - ImGui::GetWindowHeight() * 0.4f);
    }
    ImGuiListClipper clipper;
    clipper.Begin(shown.count, row);
    while (clipper.Step())
        for (int k = clipper.DisplayStart; k < clipper.DisplayEnd; ++k) {
            const int i = shown[k];
            const Primitive& p = primitives[static_cast<std::size_t>(i)];
            ImGui::PushID(i);
            const Colour& c = p.material.pigment;
            ImGui::ColorButton("##swatch", ImVec4(float(c.x), float(c.y), float(c.z), 1.0f),
                               ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
            ImGui::SameLine();
            const ObjectName label = object_name(p, static_cast<std::size_t>(i));
            if (ImGui::Selectable(label.text, i == selected))
                select(state.view,
                       i == selected ? Selection{} : Selection{Selection::Kind::primitive, i});
            note_item(label.text, false);
            ImGui::PopID();
        }
    ImGui::EndChild();
}

// Whether the primitive's text has a block with that keyword (the source map
// describes the base text, which has the edited scene's structure).
bool has_child(const SceneDocument& doc, std::size_t primitive, std::string_view keyword) {
    if (primitive >= doc.source.primitives.size()) return false;
    for (const BlockSource& child : children_of(doc.source, doc.source.primitives[primitive]))
        if (child.keyword == keyword) return true;
    return false;
}

// A mesh's model file, and the button that reads it again (the watcher does
// so by itself when the file's stamp moves; a copy tool may keep the stamp).
void model_file_row(AppState& state, const Mesh& mesh, std::size_t i,
                    std::function<void()>& command) {
    ImGui::TextUnformatted(("model: " + mesh.file).c_str());
    tooltip(asset_path(state.doc.scene, mesh.file).string().c_str());
    same_line_if_fits("Reload model");
    if (button("Reload model",
               "Read the model file again and render it, even if the scene text did not change"))
        command = [&state, i] { reload_model(state, i); };
}

// "<1, 0.5, 2.25>" to six digits, as jtracer-cli info prints it: a model's
// single-precision corners in full would be noise.
std::string figure_vector(const Vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "<%g, %g, %g>", v.x, v.y, v.z);
    return text;
}

// A line of text, recorded under itself so that the tests can find it;
// wrapped at the panel's edge (a box's two corners need more than its width).
void figure_line(const std::string& text) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    note_item(text.c_str(), false);
}

// With materials "file": each part of the model with a swatch of its base
// colour (docs/language.md §14.5); faces without a material show none.
void part_rows(const std::vector<MeshPartInfo>& parts) {
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const MeshPartInfo& part = parts[i];
        ImGui::PushID(static_cast<int>(i));
        if (part.base) {
            const ImVec4 swatch(static_cast<float>(part.base->x), static_cast<float>(part.base->y),
                                static_cast<float>(part.base->z), 1.0f);
            ImGui::ColorButton("##base", swatch,
                               ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                               ImVec2(ImGui::GetTextLineHeight(), ImGui::GetTextLineHeight()));
            ImGui::SameLine();
        }
        std::string line = part.name.empty() ? "(no material)" : part.name;
        line += ": " + std::to_string(part.triangles) + " triangles";
        if (part.base) line += ", base " + figure_vector(*part.base);
        if (!part.texture.empty()) line += ", texture " + part.texture;
        if (part.vertex_colours) line += ", vertex colours";
        figure_line(line);
        ImGui::PopID();
    }
}

// What the selected mesh's model holds and where it lies (scene_info.hpp), as
// jtracer-cli info prints it.
void mesh_figure_rows(AppState& state, int primitive) {
    const Expected<MeshInfo>& figures = mesh_figures(state, primitive);
    if (!figures) {
        ImGui::TextDisabled("the model does not load: see Diagnostics");
        return;
    }
    figure_line(std::to_string(figures->triangles) + " triangles, " +
                std::to_string(figures->vertices) + " vertices, normals " +
                (figures->normals == "file"   ? "from the file"
                 : figures->normals == "none" ? "none (shaded flat)"
                                              : figures->normals));
    if (figures->world_box.empty()) {
        ImGui::TextDisabled("no triangle in the world (none, or flattened)");
    } else {
        figure_line("bounds " + figure_vector(*figures->world_box.lower) + " to " +
                    figure_vector(*figures->world_box.upper));
        figure_line("size " + figure_vector(figures->world_box.size()));
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("file %s", figures->path.string().c_str());
    ImGui::PopTextWrapPos();
    part_rows(figures->parts);
}

}  // namespace

void add_object_menu(AppState& state) {
    if (button("Add object", "Add a new object in front of the camera the view shows"))
        ImGui::OpenPopup("add object");
    if (ImGui::BeginPopup("add object")) {
        for (ShapeKind kind : kShapeKinds) {
            const std::string label(keyword_of(kind));
            if (ImGui::MenuItem(label.c_str())) add_object(state, kind);
            note_item(label.c_str(), false);
        }
        ImGui::Separator();
        ImGui::TextDisabled("mesh of a model file (OBJ, PLY, STL, glTF)");
        const bool enter =
            ImGui::InputTextWithHint("##mesh_file", "models/knot.ply", &state.fields.new_mesh_file,
                                     ImGuiInputTextFlags_EnterReturnsTrue);
        note_item("Mesh file", false);
        tooltip("The model's path, relative to the scene's folder");
        ImGui::SameLine();
        if ((button(
                 "Add mesh", "Add a mesh of this file in front of the camera, scaled to fit",
                 state.fields.new_mesh_file.empty() ? "Type the path of a model file first" : "") ||
             enter) &&
            !state.fields.new_mesh_file.empty() && add_mesh(state, state.fields.new_mesh_file))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

// Commands that change the list run after it is drawn: the panel holds
// references into the scene while it draws.
void objects_panel(AppState& state) {
    auto& primitives = state.doc.scene.primitives;
    const Selection selection = current_selection(state.view, state.doc.scene);
    const int selected = selection.kind == Selection::Kind::primitive ? selection.index : -1;
    // Empty, it is where a scene starts: open, with the Add object menu.
    if ((state.view.reveal_selection && selected >= 0) || (state.doc.loaded && primitives.empty()))
        ImGui::SetNextItemOpen(true);
    char title[48];
    std::snprintf(title, sizeof title, "Objects (%zu)###objects", primitives.size());
    if (!panel_header(title, "Objects", false)) return;
    add_object_menu(state);
    ImGui::InputTextWithHint("##filter", "filter, e.g. sphere or plane 2",
                             &state.fields.object_filter);
    note_item("Object filter", false);
    tooltip(
        "Lists only the objects whose name holds this text. A click on the image selects "
        "the object under it.");
    const ShownObjects shown = shown_objects(state.fields, state.doc);
    if (primitives.empty())
        ImGui::TextDisabled("No objects yet: Add object puts one in front of the camera");
    else if (shown.count == 0)
        ImGui::TextDisabled("no object matches");
    else
        object_list(state, shown, selected);
    if (selected < 0) {
        ImGui::TextDisabled("Click an object here or in the image to edit it");
        return;
    }
    const auto i = static_cast<std::size_t>(selected);
    Primitive& p = primitives[i];
    std::function<void()> command;
    ImGui::PushID(selected);
    ImGui::Separator();
    ImGui::TextUnformatted(object_name(p, i).text);
    const BlockRef ref{BlockKind::primitive, i};
    const std::string included = why_not_rewrite_block(state.doc, ref);
    if (button("Duplicate", "Add a copy of this object's block right after it", included))
        command = [&state, ref] { duplicate_block(state, ref); };
    same_line_if_fits("Delete");
    if (button("Delete", "Remove this object's block from the text (Ctrl+Z brings it back)",
               included))
        command = [&state, ref] { delete_block(state, ref); };
    // The shape, material and transform fields all edit this one block.
    const EditedBlock block{EditedBlock::Kind::primitive, i};
    settle_block(state.history, state.doc, block);
    const BlockSource* source = block_source(state.doc, block);
    shared_text_line(state.doc, source);
    if (shape_editor(p.shape, state.doc, source))
        note_block_edited(state.history, state.doc, block);
    if (const auto* mesh = shape_if<Mesh>(&p.shape)) {
        model_file_row(state, *mesh, i, command);
        mesh_figure_rows(state, selected);
    }
    ImGui::Separator();
    ImGui::TextDisabled("material");
    if (const DefinitionSource* named = named_material(state.doc, source)) {
        ImGui::SameLine();
        ImGui::TextDisabled("from %s, tinted fields inherited", named->name.c_str());
        tooltip(
            "This object names a shared material (material: NAME;). A tinted field shows "
            "the shared material's value; editing it writes the value into this object's "
            "own material { } block, and the shared material stays as it is.");
    }
    if (!has_child(state.doc, i, "material")) {
        ImGui::SameLine();
        if (button("Add material block",
                   "Write this object's material into its block, to edit it there", included))
            command = [&state, i] { add_material_block(state, i); };
    }
    if (material_editor(p.material, state.doc, source))
        note_block_edited(state.history, state.doc, block);
    ImGui::Separator();
    ImGui::TextDisabled("transform");
    if (!has_child(state.doc, i, "transform")) {
        ImGui::SameLine();
        if (button("Add transform block", "Give this object an empty transform block", included))
            command = [&state, i] { add_transform_block(state, i); };
    }
    bool transform_changed = false;
    if (std::optional<TransformCommand> op =
            transform_editor(p.transforms, transform_changed, state.doc, source, included))
        command = [&state, i, op = *op] {
            switch (op.kind) {
                case TransformCommand::Kind::add:
                    add_transform_op(state, i, op.op);
                    break;
                case TransformCommand::Kind::move:
                    move_transform_op(state, i, op.index, op.to);
                    break;
                case TransformCommand::Kind::remove:
                    remove_transform_op(state, i, op.index);
                    break;
            }
        };
    if (transform_changed) note_block_edited(state.history, state.doc, block);
    ImGui::PopID();
    if (command) command();
}

}  // namespace jt::view
