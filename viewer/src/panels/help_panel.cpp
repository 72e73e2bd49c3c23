#include "panels/panels.hpp"

#include <imgui.h>

namespace jt::view {

void help_panel() {
    if (!ImGui::CollapsingHeader("Help")) return;
    static const char* const rows[][2] = {
        {"R", "reload the scene file"},
        {"C", "next camera"},
        {"S", "save the image (PNG or BMP by name)"},
        {"Ctrl+S", "save the scene (edits written in place)"},
        {"Ctrl+Z", "undo"},
        {"Ctrl+Shift+Z", "redo"},
        {"Space", "pause / resume the render"},
        {"F", "fit the image to the window / actual pixels"},
        {"H", "hide / show the panels"},
        {"Esc", "quit"},
        {"Left drag", "orbit (free camera)"},
        {"Right/middle drag", "pan"},
        {"Wheel", "dolly"},
        {"Drop a .jts", "open it"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        for (const auto& row : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
    }
}

}  // namespace jt::view
