#include "app_actions.hpp"
#include "panels/panels.hpp"

#include <imgui.h>

#include <cstdio>

namespace jt::view {

std::string render_status(const AppState& state) {
    if (!state.render_note.empty() && !state.started) return state.render_note;
    const RenderProgress p = state.renderer.progress();
    if (!state.started) return "idle";
    if (p.pass_count == 0) return state.paused ? "paused" : "preparing the scene";
    char text[256];
    const double mrays = p.seconds > 0 ? static_cast<double>(p.rays) / p.seconds / 1e6 : 0.0;
    std::snprintf(text, sizeof text, "pass %d/%d (%s) | %d/%d samples | %.2f s | %.2f Mrays/s%s",
                  p.pass + 1, p.pass_count, p.pass_name.c_str(), p.samples_done,
                  state.started->options.samples, p.seconds, mrays,
                  state.paused             ? " | paused"
                  : render_complete(state) ? " | done"
                                           : "");
    return text;
}

void status_line(AppState& state) {
    const RenderProgress p = state.renderer.progress();
    const std::string status = render_status(state);
    ImGui::SetNextItemWidth(160);
    ImGui::ProgressBar(static_cast<float>(p.fraction), ImVec2(160, 0));
    ImGui::SameLine();
    ImGui::TextUnformatted(status.c_str());
    const std::string error = state.renderer.error();
    if (!error.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", error.c_str());
    }
    if (!state.render_note.empty() && state.started) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "| %s", state.render_note.c_str());
    }
    ImGui::TextDisabled("%s", state.message.c_str());
}

}  // namespace jt::view
