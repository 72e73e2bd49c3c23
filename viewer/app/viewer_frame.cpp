#include "app/viewer_frame.hpp"

#include "app/image_drawing.hpp"
#include "app/image_input.hpp"
#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"

#include <imgui.h>

#include <algorithm>

namespace jt::view {

namespace {

constexpr const char* unsaved_popup = "Unsaved edits";

// The sidebar's width: the user's (dragged at its right edge), kept within
// what leaves room for the image.
float sidebar_width(const AppState& state, float window_width) {
    const float font = ImGui::GetFontSize();
    const float least = 20.0f * font;
    const float most = std::max(least, window_width - 12.0f * font);
    return std::clamp(state.view.sidebar_width * font, std::min(least, window_width * 0.6f),
                      std::min(most, window_width * 0.75f));
}

float sidebar(AppState& state, FrameState& frame, float window_width, float height) {
    const float width = sidebar_width(state, window_width);
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, height), ImVec2(window_width, height));
    ImGui::Begin("JTracer", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
    // A drag on the right edge resized the window in Begin: remember it. Only
    // a drag: a window too small for the user's width squeezes the panel, and
    // that width is not the user's.
    if (ImGui::GetWindowWidth() != width && ImGui::IsMouseDown(ImGuiMouseButton_Left))
        state.view.sidebar_width = ImGui::GetWindowWidth() / ImGui::GetFontSize();
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 7.5f);
    ImGui::Checkbox("Text editor", &frame.text_editor.open);
    note_item("Text editor", true);
    tooltip("The scene's text beside the image (T): typing re-renders once it parses");
    // A draft (typed text not yet checked, or with errors) is the document
    // now: the panels show the last good scene, and edits to it would be lost
    // when the draft parses. The note shares the checkbox's line: a line of
    // its own, there after every keystroke, moved the panels under the mouse.
    const bool draft = state.doc.draft.has_value();
    if (draft) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "panels read-only");
        tooltip("The text is being edited: the panels are read-only until it parses");
    }
    file_panel(state);
    if (draft) ImGui::BeginDisabled();
    camera_panel(state);
    settings_panel(state);
    objects_panel(state);
    lights_panel(state);
    if (draft) ImGui::EndDisabled();
    diagnostics_panel(state, frame.diagnostics);
    help_panel();
    ImGui::PopItemWidth();
    const float drawn = ImGui::GetWindowWidth();
    note_window("panel");
    ImGui::End();
    return drawn;
}

float status_height() {
    const ImGuiStyle& style = ImGui::GetStyle();
    return ImGui::GetFrameHeightWithSpacing() + ImGui::GetTextLineHeightWithSpacing() +
           style.WindowPadding.y * 2.0f;
}

// `inspected`: the pixel inspector's text when its box does not fit the image.
void status_window(AppState& state, FrameState& frame, float y, float width,
                   const std::string& inspected) {
    ImGui::SetNextWindowPos(ImVec2(0, y));
    ImGui::SetNextWindowSize(ImVec2(width, status_height()));
    ImGui::Begin(
        "##status", nullptr,
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    status_line(state, inspected, &frame.diagnostics, frame.text_editor.open);
    note_window("status");
    ImGui::End();
}

// Save / Discard / Cancel before a command that would drop unsaved edits.
void unsaved_prompt(AppState& state) {
    if (!state.files.unsaved_prompt) return;
    if (!ImGui::IsPopupOpen(unsaved_popup)) ImGui::OpenPopup(unsaved_popup);
    const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(unsaved_popup, nullptr,
                                ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove))
        return;
    const bool quitting = state.files.unsaved_prompt->kind == GuardedCommand::Kind::quit;
    const std::vector<std::string> names = unsaved_file_names(state);
    ImGui::Text("%s %s unsaved edits.", listed_names(names).c_str(),
                names.size() > 1 ? "have" : "has");
    ImGui::TextUnformatted(quitting ? "Save them before quitting?"
                                    : "Save them before opening another file?");
    std::optional<UnsavedChoice> choice;
    // One row, always: the popup sizes itself to its contents, and a row
    // wrapped to the width of the hidden frame that measures it
    // (same_line_if_fits) would make its first drawn frame a row taller, and
    // centred higher, than the next: a click on a button seen in that frame
    // lands beside it.
    if (button("Save", "Write the edits into the file, then go on")) choice = UnsavedChoice::save;
    ImGui::SameLine();
    if (button("Discard", "Throw the edits away and go on")) choice = UnsavedChoice::discard;
    ImGui::SameLine();
    if (button("Cancel", "Keep the edits and stay (Esc)")) choice = UnsavedChoice::cancel;
    if (choice) {
        resolve_unsaved(state, *choice);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace

void viewer_frame(AppState& state, FrameState& frame, const FrameInfo& info) {
    collect_ui_items(&frame.ui_items);
    const ImGuiIO& io = ImGui::GetIO();
    const float w = io.DisplaySize.x, h = io.DisplaySize.y;
    reload_if_changed(state);
    take_finished_load(state);
    take_checked_text(state);
    step_play(state, std::chrono::steady_clock::now());
    const EditMark before = begin_edit_tracking(state.history, state.doc);
    // Keys zoom about the image as the last frame placed it.
    handle_shortcuts(state, frame,
                     place_in_area(state, frame, frame.image_area, info.framebuffer_scale));

    // A reveal asked for by now is shown by the panels below; one a panel's
    // own button asks for (they act after the panel is drawn) is the next frame's.
    const bool revealing = state.view.reveal_selection;
    ScreenRect area{0, 0, w, h};
    if (state.view.show_ui) {
        const float status_h = std::min(status_height(), h);
        area.x0 = sidebar(state, frame, w, h - status_h);
        area.y1 = h - status_h;
        if (frame.text_editor.open) {
            // 45% of the width right of the panels, at least 30 font widths,
            // but never all of it: in a narrow window (800x500, a 2x screen's
            // 1600x1000) the image, its toolbar and the reload bar over it
            // keep a third beside the text.
            const float rest = w - area.x0;
            const float editor_w =
                std::min(std::max(rest * 0.45f, ImGui::GetFontSize() * 30.0f), rest * 0.65f);
            area.x1 = w - editor_w;
            text_editor(state, frame.text_editor, area.x1, 0.0f, w, area.y1);
        }
        area.y0 += reload_bar(state, frame.reload_bar, area);
        // The inspector's text from the last frame (inspect_hovered_pixel comes later).
        const std::string& inspected = state.view.inspected;
        const bool in_status =
            !inspected.empty() && !inspector_box_fits(inspected, frame.image_area);
        static const std::string none;
        status_window(state, frame, h - status_h, w, in_status ? inspected : none);
        if (frame.presenter.has_image())
            image_toolbar(state, frame, place_in_area(state, frame, area, info.framebuffer_scale));
        // Once the panel edge is let go: a drag writes the file once, not every frame.
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) remember_settings(state.view, state.config);
    }
    if (revealing) state.view.reveal_selection = false;  // the panels have shown it
    unsaved_prompt(state);
    track_edits(state.history, state.doc, before, ImGui::IsAnyItemActive());
    check_edits(state.check, state.doc, state.files);
    update_render(state);
    const std::optional<PixelRect> changed = take_display_changes(state.render);
    if (changed) frame.presenter.upload(state.render.display, changed);
    update_compare_texture(state, frame, changed.has_value());
    const ImagePlace image = place_in_area(state, frame, area, info.framebuffer_scale);
    handle_image_mouse(state, image);
    // After the mouse: what is drawn is where this frame's zoom and pan put it.
    const ImagePlace drawn = place_in_area(state, frame, area, info.framebuffer_scale);
    inspect_hovered_pixel(state, drawn);
    frame.image_area = drawn.area;
    frame.image_rect = drawn.where;
    ImDrawList* draw_list = ImGui::GetBackgroundDrawList();
    draw_list->PushClipRect(ImVec2(area.x0, area.y0), ImVec2(area.x1, area.y1), true);
    draw_image(state, frame, draw_list, drawn);
    frame.overlay.draw(state, draw_list, drawn.where, drawn.width, drawn.height);
    draw_regions(state, draw_list, drawn);
    draw_list->PopClipRect();
    collect_ui_items(nullptr);
}

std::string window_title(const AppState& state) {
    std::string title = "JTracer";
    if (!state.doc.path.empty()) {
        title += " - " + state.doc.path.filename().string();
        if (has_unsaved_work(state)) title += " *";
    }
    if (const std::string status = render_title_status(state.render); !status.empty())
        title += " - " + status;
    return title;
}

}  // namespace jt::view
