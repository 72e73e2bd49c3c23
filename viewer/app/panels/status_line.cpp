#include "app/panels/panels.hpp"
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

std::string render_status(const AppState& state) {
    if (!state.render.render_note.empty() && !state.render.started) return state.render.render_note;
    if (!state.render.started) return state.render.paused ? "paused" : "idle";
    const RenderProgress p = state.render.renderer.progress();
    const int samples = state.render.started->options.samples;
    if (p.pass_count == 0) return state.render.paused ? "paused" : "preparing the scene";
    const double mrays = p.seconds > 0 ? static_cast<double>(p.rays) / p.seconds / 1e6 : 0.0;
    char speed[48];
    std::snprintf(speed, sizeof speed, "%.1f Mrays/s", mrays);
    if (state.render.paused) {
        std::string text = "paused at " + pass_label(p, samples, state.render.converging);
        text +=
            state.render.edit_waiting ? " | edit waiting: Space renders it" : " | Space resumes";
        return text;
    }
    if (render_complete(state.render))
        return "done: " + std::to_string(p.samples_done) +
               (p.samples_done == 1 ? " sample" : " samples") + " in " + seconds_text(p.seconds) +
               " | " + speed;
    std::string text = pass_label(p, samples, state.render.converging) + " | " +
                       seconds_text(p.seconds) + " elapsed";
    // The ETA once enough is done to extrapolate from.
    if (p.fraction > 0.02 && p.fraction < 1.0)
        text += ", about " + seconds_text(p.seconds * (1.0 - p.fraction) / p.fraction) + " left";
    return text + " | " + speed;
}

void status_line(AppState& state, const std::string& inspected) {
    const RenderProgress p = state.render.renderer.progress();
    const std::string status = render_status(state);
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
    if (inspected.empty()) {
        ImGui::TextDisabled("%s", state.message.c_str());
        return;
    }
    std::string line = inspected;  // its lines side by side
    for (std::size_t at = line.find('\n'); at != std::string::npos; at = line.find('\n', at))
        line.replace(at, 1, " | ");
    ImGui::TextUnformatted(line.c_str());
}

}  // namespace jt::view
