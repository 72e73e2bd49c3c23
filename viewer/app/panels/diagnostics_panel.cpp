#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"

#include <imgui.h>

#include <cstdio>

namespace jt::view {

namespace {

void make_text(const SceneDocument& doc, DiagnosticsText& text) {
    text.generation = doc.diagnostics_generation;
    text.count = doc.diagnostics.size();
    text.entries.clear();
    const std::string file = doc.diagnostics_path.filename().string();
    for (const Diagnostic& d : doc.diagnostics) {
        // As the CLI prints it: the message, then the source line and a caret
        // under the column, in the monospaced font so that the caret lines up.
        const std::string formatted =
            format_diagnostic(d, file, doc.diagnostics_source, doc.diagnostics_files);
        const std::size_t first_line = formatted.find('\n');
        DiagnosticsText::Entry entry;
        entry.error = d.severity == Severity::error;
        entry.message = formatted.substr(0, first_line);
        if (first_line != std::string::npos && first_line + 1 < formatted.size()) {
            entry.quote = formatted.substr(first_line + 1);
            while (!entry.quote.empty() && entry.quote.back() == '\n') entry.quote.pop_back();
        }
        text.entries.push_back(std::move(entry));
    }
}

}  // namespace

void diagnostics_panel(AppState& state, DiagnosticsText& text) {
    const auto& diagnostics = state.doc.diagnostics;
    // A file failed to open while another stayed: not the shown file's last
    // good scene (which has no fault), but the other file's errors.
    const bool other = diagnostics_of_another_file(state.doc);
    const bool errors = state.doc.load_failed || other;
    char title[48];
    std::snprintf(title, sizeof title, "Diagnostics (%zu)###diag", diagnostics.size());
    text.first_in_view = false;
    // The status line's link: the header at the top of the sidebar, and the
    // panel open (typed text's errors leave it as the user left it).
    const bool reveal = text.scroll_to;
    if (reveal) {
        ImGui::SetScrollHereY(0.0f);
        text.scroll_to = false;
    }
    if (errors || reveal) ImGui::SetNextItemOpen(true);
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
    if (text.generation != state.doc.diagnostics_generation || text.count != diagnostics.size())
        make_text(state.doc, text);
    for (const DiagnosticsText::Entry& entry : text.entries) {
        const ImVec4 colour =
            entry.error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(1.0f, 0.85f, 0.4f, 1.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(entry.message.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
        note_item(entry.message.c_str(), false);
        if (&entry == &text.entries.front()) {
            // Whole within the sidebar's window, not scrolled past either edge.
            const float top = ImGui::GetWindowPos().y;
            const float bottom = top + ImGui::GetWindowHeight();
            text.first_in_view =
                ImGui::GetItemRectMin().y >= top && ImGui::GetItemRectMax().y <= bottom;
        }
        if (!entry.quote.empty()) {
            push_monospace_font();
            ImGui::TextUnformatted(entry.quote.c_str());
            pop_monospace_font();
        }
    }
}

}  // namespace jt::view
