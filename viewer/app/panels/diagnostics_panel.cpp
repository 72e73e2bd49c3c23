#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"

#include <imgui.h>

#include <cstdio>

namespace jt::view {

void diagnostics_panel(AppState& state) {
    const auto& diagnostics = state.doc.diagnostics;
    // A file failed to open while another stayed: not the shown file's last
    // good scene (which has no fault), but the other file's errors.
    const bool other = diagnostics_of_another_file(state.doc);
    const bool errors = state.doc.load_failed || other;
    char title[48];
    std::snprintf(title, sizeof title, "Diagnostics (%zu)###diag", diagnostics.size());
    if (errors) ImGui::SetNextItemOpen(true);
    if (!panel_header(title, "Diagnostics", false)) return;
    if (diagnostics.empty()) {
        ImGui::TextDisabled("No errors or warnings.");
        return;
    }
    if (other) {
        char said[512];
        std::snprintf(said, sizeof said, "Could not open %s: still showing %s.",
                      state.doc.diagnostics_path.filename().c_str(),
                      state.doc.path.filename().c_str());
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", said);
        ImGui::PopStyleColor();
        note_item(said, false);
    } else if (errors && state.doc.loaded) {
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f),
                           "Showing the last good scene until the file is fixed.");
        note_item("Showing the last good scene until the file is fixed.", false);
    }
    const std::string file = state.doc.diagnostics_path.filename().string();
    for (const Diagnostic& d : diagnostics) {
        const bool error = d.severity == Severity::error;
        const ImVec4 colour =
            error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(1.0f, 0.85f, 0.4f, 1.0f);
        // As the CLI prints it: the message, then the source line and a caret
        // under the column, in the monospaced font so that the caret lines up.
        const std::string text =
            format_diagnostic(d, file, state.doc.diagnostics_source, state.doc.diagnostics_files);
        const std::size_t first_line = text.find('\n');
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::TextWrapped("%s", text.substr(0, first_line).c_str());
        ImGui::PopStyleColor();
        if (first_line != std::string::npos && first_line + 1 < text.size()) {
            std::string quote = text.substr(first_line + 1);
            while (!quote.empty() && quote.back() == '\n') quote.pop_back();
            push_monospace_font();
            ImGui::TextUnformatted(quote.c_str());
            pop_monospace_font();
        }
    }
}

}  // namespace jt::view
