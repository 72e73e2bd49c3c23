#include "panels/panels.hpp"

#include <imgui.h>

namespace jt::view {

void diagnostics_panel(AppState& state) {
    const auto& diagnostics = state.doc.diagnostics;
    const bool errors = state.doc.load_failed;
    const std::string title = "Diagnostics (" + std::to_string(diagnostics.size()) + ")###diag";
    if (errors) ImGui::SetNextItemOpen(true);
    if (!ImGui::CollapsingHeader(title.c_str())) return;
    if (diagnostics.empty()) {
        ImGui::TextDisabled("No errors or warnings.");
        return;
    }
    if (errors && state.doc.loaded)
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f),
                           "Showing the last good scene until the file is fixed.");
    const std::string file = state.doc.diagnostics_path.filename().string();
    for (const Diagnostic& d : diagnostics) {
        const bool error = d.severity == Severity::error;
        const ImVec4 colour =
            error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(1.0f, 0.85f, 0.4f, 1.0f);
        std::string where = file;
        if (d.pos.line > 0) {
            where += ':';
            where += std::to_string(d.pos.line);
            where += ':';
            where += std::to_string(d.pos.column);
        }
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::TextWrapped("%s: %s: %s", where.c_str(), error ? "error" : "warning",
                           d.message.c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace jt::view
