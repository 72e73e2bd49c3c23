#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/app_actions.hpp"

#include <imgui.h>

#include <cstdio>
#include <string>

namespace jt::view {

namespace {

std::string seconds_text(double seconds) {
    char text[32];
    if (seconds < 60)
        std::snprintf(text, sizeof text, "%.1f s", seconds);
    else
        std::snprintf(text, sizeof text, "%d min %02d s", static_cast<int>(seconds) / 60,
                      static_cast<int>(seconds) % 60);
    return text;
}

}  // namespace

void render_status(const AppState& state, std::string& text) {
    text.clear();
    if (!state.render.render_note.empty() && !state.render.started) {
        text += state.render.render_note;
        return;
    }
    if (!state.render.started) {
        text += state.render.paused ? "paused" : "idle";
        return;
    }
    const RenderProgress p = state.render.renderer.progress();
    const int samples = state.render.started->options.samples;
    if (p.pass_count == 0) {
        text += state.render.paused ? "paused" : "preparing the scene";
        return;
    }
    char done[48];
    std::snprintf(done, sizeof done, "done: %d %s", p.samples_done,
                  p.samples_done == 1 ? "sample" : "samples");
    // Paused after its last sample, the render has nothing left to resume:
    // the pause only holds edits back until Space.
    if (state.render.paused && state.render.display_complete && !state.render.edit_waiting) {
        text += done;
        text += ", paused | edits wait for Space";
        return;
    }
    if (state.render.paused) {
        text += "paused at ";
        text += pass_label(p, samples, state.render.converging);
        text +=
            state.render.edit_waiting ? " | edit waiting: Space renders it" : " | Space resumes";
        return;
    }
    const double mrays = p.seconds > 0 ? static_cast<double>(p.rays) / p.seconds / 1e6 : 0.0;
    char speed[48];
    std::snprintf(speed, sizeof speed, "%.1f Mrays/s", mrays);
    if (render_complete(state.render)) {
        text += done;
        text += " in ";
        text += seconds_text(p.seconds);
        text += " | ";
        text += speed;
        return;
    }
    text += pass_label(p, samples, state.render.converging);
    text += " | ";
    text += seconds_text(p.seconds);
    text += " elapsed";
    // The ETA once enough is done to extrapolate from.
    if (p.fraction > 0.02 && p.fraction < 1.0) {
        text += ", about ";
        text += seconds_text(p.seconds * (1.0 - p.fraction) / p.fraction);
        text += " left";
    }
    text += " | ";
    text += speed;
}

std::string render_status(const AppState& state) {
    std::string text;
    render_status(state, text);
    return text;
}

namespace {

// "Show 2 errors": scrolls the sidebar to the Diagnostics panel. On the
// message's line, where it moves no other control when it comes and goes.
void show_errors_link(const AppState& state, DiagnosticsText& diagnostics) {
    std::size_t errors = 0;
    for (const Diagnostic& d : state.doc.diagnostics)
        if (d.severity == Severity::error) ++errors;
    if (errors == 0) return;
    char label[64];
    std::snprintf(label, sizeof label, "Show %zu error%s###show errors", errors,
                  errors == 1 ? "" : "s");
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    const bool clicked = ImGui::SmallButton(label);
    ImGui::PopStyleColor();
    tooltip("Scroll the panels to Diagnostics, which lists them");
    note_item("show errors", true);
    if (clicked) diagnostics.scroll_to = true;
    ImGui::SameLine();
}

}  // namespace

void status_line(AppState& state, const std::string& inspected, DiagnosticsText* diagnostics,
                 bool text_editor_open) {
    const RenderProgress p = state.render.renderer.progress();
    static std::string status;  // one status line; its storage kept from frame to frame
    render_status(state, status);
    const float font = ImGui::GetFontSize();
    const float fraction = render_complete(state.render) ? 1.0f : static_cast<float>(p.fraction);
    ImGui::ProgressBar(fraction, ImVec2(font * 10.0f, 0));
    ImGui::SameLine();
    if (state.render.paused)
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s", status.c_str());
    else
        ImGui::TextUnformatted(status.c_str());
    const std::string error = state.render.renderer.error();
    if (!error.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", error.c_str());
    }
    if (!state.render.render_note.empty() && state.render.started) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "| %s",
                           state.render.render_note.c_str());
    }
    if (diagnostics && !diagnostics->first_in_view && !text_editor_open)
        show_errors_link(state, *diagnostics);
    if (inspected.empty()) {
        ImGui::TextDisabled("%s", shown_message(state).c_str());
        return;
    }
    std::string line = inspected;  // its lines side by side
    for (std::size_t at = line.find('\n'); at != std::string::npos; at = line.find('\n', at))
        line.replace(at, 1, " | ");
    ImGui::TextUnformatted(line.c_str());
}

}  // namespace jt::view
