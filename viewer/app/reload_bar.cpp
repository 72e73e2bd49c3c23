#include "app/reload_bar.hpp"

#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"

#include <imgui.h>

#include <algorithm>
#include <string_view>

namespace jt::view {

namespace {

const ImVec4 kWarning(1.0f, 0.7f, 0.3f, 1.0f);
const ImVec4 kRemoved(1.0f, 0.5f, 0.45f, 1.0f);
const ImVec4 kAdded(0.5f, 0.9f, 0.5f, 1.0f);

void choices(AppState& state, ReloadBarState& bar, bool unchanged) {
    if (button("Reload, drop my edits", "Show the file as it is on disk; your edits are lost"))
        resolve_reload(state, ReloadChoice::drop_edits);
    if (!unchanged && state.files.reapply_problem.empty()) {
        same_line_if_fits("Reload, re-apply my edits");
        if (button("Reload, re-apply my edits",
                   "Take the file's new text and make your edits to it again"))
            resolve_reload(state, ReloadChoice::reapply_edits);
    }
    same_line_if_fits("Keep mine");
    if (button("Keep mine",
               "Ignore the file's text for now; Save scene will ask before replacing it"))
        resolve_reload(state, ReloadChoice::keep_edits);
    same_line_if_fits("Show differences");
    if (button(bar.show_differences ? "Hide differences" : "Show differences",
               "The lines of your text (red, -) against the files' on disk (green, +)"))
        bar.show_differences = !bar.show_differences;
}

// Compared every frame the differences show: nothing is copied.
bool same_texts(const std::vector<std::string>& kept, const std::vector<SourceFile>& files) {
    return std::equal(kept.begin(), kept.end(), files.begin(), files.end(),
                      [](const std::string& a, const SourceFile& b) { return a == b.text; });
}

void differences(const AppState& state, ReloadBarState& bar, float max_height) {
    const SceneDocument& doc = state.doc;
    const LoadAttempt& newer = *state.files.pending_reload;
    if (bar.revision != doc.revision || bar.generation != doc.file_generation ||
        bar.draft != doc.draft || bar.theirs != newer.text ||
        !same_texts(bar.theirs_included, newer.source.files)) {
        bar.diff = reload_differences(doc, newer);
        bar.revision = doc.revision;
        bar.generation = doc.file_generation;
        bar.draft = doc.draft;
        bar.theirs = newer.text;
        bar.theirs_included.clear();
        for (const SourceFile& file : newer.source.files) bar.theirs_included.push_back(file.text);
    }
    const TextDiff& diff = bar.diff;
    ImGui::Text("Yours to the files': %d line%s removed (-), %d added (+)%s", diff.removed,
                diff.removed == 1 ? "" : "s", diff.added,
                diff.coarse ? "; too many to match up line by line" : "");
    const float line_h = ImGui::GetTextLineHeightWithSpacing();
    const float height =
        std::min(max_height, line_h * static_cast<float>(diff.lines.size() + 1) + 8.0f);
    ImGui::BeginChild("##differences", ImVec2(0, height), true,
                      ImGuiWindowFlags_HorizontalScrollbar);
    push_monospace_font();
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(diff.lines.size()));
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const DiffLine& line = diff.lines[static_cast<std::size_t>(i)];
            if (line.kind == DiffLine::Kind::file) {
                ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
                ImGui::TextUnformatted(line.text.data(), line.text.data() + line.text.size());
                ImGui::PopStyleColor();
                continue;
            }
            const bool removed = line.kind == DiffLine::Kind::removed;
            const bool added = line.kind == DiffLine::Kind::added;
            if (removed || added) ImGui::PushStyleColor(ImGuiCol_Text, removed ? kRemoved : kAdded);
            // The number, then the line beside it: neither copied (a frame
            // showing the differences allocates nothing).
            ImGui::Text("%5d %c ", removed ? line.old_line : line.new_line,
                        removed ? '-'
                        : added ? '+'
                                : ' ');
            ImGui::SameLine(0.0f, 0.0f);
            ImGui::TextUnformatted(line.text.data(), line.text.data() + line.text.size());
            if (removed || added) ImGui::PopStyleColor();
        }
    pop_monospace_font();
    ImGui::EndChild();
    note_window("differences");
}

}  // namespace

float reload_bar(AppState& state, ReloadBarState& bar, const ScreenRect& area) {
    if (!state.files.pending_reload || area.width() <= 0.0f) {
        bar.show_differences = false;
        return 0.0f;
    }
    const float width = area.width();
    ImGui::SetNextWindowPos(ImVec2(area.x0, area.y0));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, area.height()));
    ImGui::Begin("##reload_bar", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize);
    // The file's name as a view into its path: drawn every frame, it is not copied.
    const std::string& path = state.doc.path.native();
    const std::string_view name = std::string_view(path).substr(path.rfind('/') + 1);
    const int name_size = static_cast<int>(name.size());
    // The file that changed: the scene's, or one it includes.
    const std::string& changed = state.files.changed_on_disk;
    const bool unchanged = changed.empty();
    ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
    if (unchanged)
        ImGui::TextWrapped("%.*s is unchanged on disk. Reloading it would drop your unsaved edits.",
                           name_size, name.data());
    else
        ImGui::TextWrapped("%s changed on disk%s, and you have unsaved edits.", changed.c_str(),
                           state.files.pending_reload->ok ? "" : " (it has errors)");
    ImGui::PopStyleColor();
    choices(state, bar, unchanged);
    if (state.files.pending_reload && !unchanged && !state.files.reapply_problem.empty())
        ImGui::TextWrapped("(your edits cannot be re-applied to the new text: %s)",
                           state.files.reapply_problem.c_str());
    if (state.files.pending_reload && bar.show_differences)
        differences(state, bar, area.height() * 0.45f);
    const float height = ImGui::GetWindowHeight();
    note_window("reload bar");
    ImGui::End();
    return std::min(height, area.height());
}

}  // namespace jt::view
