#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <filesystem>

namespace jt::view {

namespace {

const ImVec4 warning_colour(1.0f, 0.7f, 0.3f, 1.0f);

// Save scene was refused because the file changed on disk.
void save_conflict_choice(AppState& state) {
    if (state.files.save_conflict.empty() || state.files.pending_reload) return;
    ImGui::PushStyleColor(ImGuiCol_Text, warning_colour);
    ImGui::TextWrapped("Not saved: %s.", state.files.save_conflict.c_str());
    ImGui::PopStyleColor();
    if (!state.files.save_conflict_drafts.empty()) {
        // A reload keeps text typed in included files: it would not choose.
        if (button("Revert typed text",
                   "Drop what you typed in the changed file and keep the file as it is "
                   "on disk"))
            revert_conflicting_drafts(state);
    } else if (button("Reload (choose what to keep)",
                      "Read the file again, then choose between its "
                      "text and your edits")) {
        reload_scene(state);
    }
    same_line_if_fits("Save anyway");
    if (button("Save anyway", "Replace what is on disk with your edited scene"))
        save_scene_anyway(state);
    same_line_if_fits("Cancel##conflict");
    if (button("Cancel##conflict", "Do not save now")) state.files.save_conflict.clear();
}

// Save scene as would replace an existing file.
void save_as_choice(AppState& state) {
    if (state.files.save_as_conflict.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, warning_colour);
    ImGui::TextWrapped("%s exists.", state.files.save_as_conflict.c_str());
    ImGui::PopStyleColor();
    // The file the question names, even when the field was changed since:
    // a path typed after the question was never asked about.
    if (button("Replace it", "Write the scene over that file")) {
        const std::filesystem::path asked = state.files.save_as_conflict;
        save_scene_as(state, asked, /*replace=*/true);
    }
    same_line_if_fits("Cancel##save_as");
    if (button("Cancel##save_as", "Do not save now")) state.files.save_as_conflict.clear();
}

const char* why_not_save(const AppState& state) {
    if (has_included_drafts(state.editor)) return "";  // text typed in an included file
    if (!state.doc.loaded) return "No scene is open";
    if (!has_unsaved_edits(state.doc)) return "No unsaved edits: the file holds this scene";
    return "";
}

}  // namespace

void file_panel(AppState& state) {
    if (!panel_header("File", "File", true)) return;
    const float font = ImGui::GetFontSize();
    // What is under way with the file, on the file's line: a line of its own
    // moved every field below it by a row (for every reload, a frame or
    // more) under a mouse about to click one. Where it does not fit, the
    // bar above the image and the status line say it.
    const char* path = state.doc.path.empty() ? "(no scene)" : state.doc.path.c_str();
    const char* note = state.files.pending_reload  ? "changed on disk: choose above the image"
                       : state.files.loader.busy() ? "loading..."
                                                   : nullptr;
    if (note && ImGui::CalcTextSize(path).x + ImGui::GetStyle().ItemSpacing.x +
                        ImGui::CalcTextSize(note).x <=
                    ImGui::GetContentRegionAvail().x) {
        ImGui::TextUnformatted(path);
        ImGui::SameLine();
        ImGui::TextColored(warning_colour, "%s", note);
    } else {
        ImGui::TextWrapped("%s", path);
    }
    ImGui::SetNextItemWidth(-font * 4.0f);
    const bool enter = ImGui::InputTextWithHint(
        "##open", "scene.jts", &state.fields.open_path_input, ImGuiInputTextFlags_EnterReturnsTrue);
    note_item("open path", true);
    tooltip(
        "The path of a .jts file to open (Enter opens it; a relative path: beside the scene "
        "file). You can also drop a file on the window.");
    ImGui::SameLine();
    if ((button("Open", "Open the file named on the left (asks first if you have unsaved edits)",
                state.fields.open_path_input.empty() ? "Type the path of a .jts file first" : "") ||
         enter) &&
        !state.fields.open_path_input.empty())
        open_typed_path(state);
    if (!state.files.recent.paths().empty()) {
        ImGui::SetNextItemWidth(-font * 4.0f);
        if (ImGui::BeginCombo("Recent", state.files.recent.paths().front().c_str())) {
            std::string chosen;
            for (const std::string& path : state.files.recent.paths())
                if (ImGui::Selectable(path.c_str())) chosen = path;
            ImGui::EndCombo();
            if (!chosen.empty()) request_open_guarded(state, chosen);
        }
        note_item("Recent", true);
        tooltip("Files opened before, newest first");
    }
    if (button("Reload (R)", "Read the file again (asks first if you have unsaved edits)",
               state.doc.path.empty() ? "No file is open" : ""))
        reload_scene(state);
    same_line_if_fits("Save scene (Ctrl+S)");
    if (button("Save scene (Ctrl+S)",
               "Write your edits into the file, changing only the values you edited",
               why_not_save(state)))
        save_scene(state);
    same_line_if_fits("Undo");
    if (button("Undo", "Undo the last edit (Ctrl+Z)",
               state.history.undo.can_undo() ? "" : "Nothing to undo"))
        undo(state);
    same_line_if_fits("Redo");
    if (button("Redo", "Redo the edit undone last (Ctrl+Shift+Z or Ctrl+Y)",
               state.history.undo.can_redo() ? "" : "Nothing to redo"))
        redo(state);
    if (document_is_blank(state.doc) &&
        button("Start a scene",
               "Fill this empty file with an image size, a camera and a light, then add objects "
               "in the Objects panel (Ctrl+Z takes it back)"))
        start_new_scene(state);
    save_conflict_choice(state);
    ImGui::SetNextItemWidth(-font * 8.5f);
    ImGui::InputTextWithHint("##scene_as", "copy.jts", &state.fields.save_scene_path);
    note_item("save scene path", true);
    tooltip("Where Save scene as writes the edited scene (a relative path: beside the scene file)");
    ImGui::SameLine();
    if (button("Save scene as", "Write the edited scene to this file and keep editing that one",
               !state.doc.loaded                      ? "No scene is open"
               : state.fields.save_scene_path.empty() ? "Type the new file's path first"
                                                      : ""))
        save_scene_as(state, state.fields.save_scene_path, /*replace=*/false);
    save_as_choice(state);
    ImGui::SetNextItemWidth(-font * 8.5f);
    ImGui::InputText("##image", &state.fields.save_image_path);
    note_item("save image path", true);
    tooltip(
        "Where S saves the image, PNG or BMP by the name's ending. An existing file is never "
        "replaced: name-001.png, name-002.png, ... are used instead.");
    ImGui::SameLine();
    if (button("Save image (S)", "Save the image as shown now under the name on the left",
               state.render.display.width <= 0        ? "Nothing has rendered yet"
               : state.fields.save_image_path.empty() ? "Type the image's path first"
                                                      : ""))
        save_image(state, state.fields.save_image_path);
}

}  // namespace jt::view
