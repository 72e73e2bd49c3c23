#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"

#include <imgui.h>

namespace jt::view {

void help_panel() {
    if (!panel_header("Help", "Help", false)) return;
    static const char* const rows[][2] = {
        {"R", "reload the scene file"},
        {"C", "next camera"},
        {"S", "save the image (PNG or BMP by name; never replaces a file)"},
        {"Ctrl+S", "save the scene (edits written in place)"},
        {"Ctrl+Z", "undo"},
        {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
        {"Space", "pause / resume the render (when let go without a drag)"},
        {"F", "fit the whole image to the window"},
        {"1", "actual pixels (1:1)"},
        {"+ / -", "zoom the image in / out (about the mouse)"},
        {"Ctrl+wheel", "zoom the image about the mouse"},
        {"Middle drag, Space+drag", "pan the image (the camera stays)"},
        {"Ctrl+drag", "render only that rectangle (Render region)"},
        {"Ctrl+click image",
         "focus the camera on the surface under the cursor: its focus_distance becomes that "
         "surface's depth along the view direction (blur needs an aperture and samples above "
         "1); one undo step"},
        {"Alt+drag",
         "move the selected object or light in the plane facing the camera (with nothing "
         "selected, the one under the cursor); one undo step"},
        {"Alt+Shift+drag", "the same along one axis: x, y or z, whichever it moves along most"},
        {"Delete, X", "delete the selected object or light (Ctrl+Z brings it back)"},
        {"Ctrl+D, Shift+D", "duplicate the selection; the copy is selected"},
        {". (period)", "frame the selection: the view's camera turns to it and comes close"},
        {"A", "show snapshot A / the live image"},
        {"H", "hide / show the panels"},
        {"T", "show / hide the text editor"},
        {"Esc", "cancel a move (Alt+drag); close a popup or picker; with none open, twice quits"},
        {"Ctrl+Q", "quit (asks first about unsaved edits)"},
        {"Left drag", "orbit (free camera)"},
        {"Right drag", "pan (free camera)"},
        {"Wheel", "dolly (free camera)"},
        {"Ctrl+click field",
         "type a number field's value (Enter takes it; dragging it changes it)"},
        {"Drop a .jts", "open it"},
        {"Panel edge", "drag to resize the panel"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        // As wide as the longest key that cannot wrap.
        ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed,
                                ImGui::CalcTextSize("Alt+Shift+drag").x);
        ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
        for (const auto& row : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", row[0]);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", row[1]);
        }
        ImGui::EndTable();
    }
}

}  // namespace jt::view
