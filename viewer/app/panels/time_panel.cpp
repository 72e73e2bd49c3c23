// The time slider and play button: shown when the scene's values use `clock`
// (docs/language.md §15.4). They set the clock the scene is computed at;
// the file is never changed.

#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "jtracer/value_text.hpp"
#include "model/scene_time.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>

namespace jt::view {

void time_panel(AppState& state, float right) {
    if (!state.doc.uses_clock) return;
    const auto now = std::chrono::steady_clock::now();
    const bool playing = state.time.playing;
    // As wide playing as paused, so that the slider stays under the mouse.
    const float width = std::max(ImGui::CalcTextSize("Play").x, ImGui::CalcTextSize("Pause").x) +
                        2.0f * ImGui::GetStyle().FramePadding.x;
    const char* label = playing ? "Pause" : "Play";
    if (ImGui::Button(label, ImVec2(width, 0.0f))) toggle_play(state, now);
    note_item(label, true);
    const bool play_hovered = ImGui::IsItemHovered();
    const ImVec2 play_min = ImGui::GetItemRectMin();
    // Beside Play where the image area has room for a slider that can be
    // dragged, else on a row of its own: never past `right`, where the text
    // editor's window or the window's edge would hide its value.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float label_width = ImGui::CalcTextSize("clock").x + style.ItemInnerSpacing.x;
    const float least = ImGui::GetFontSize() * 6.0f, most = ImGui::GetFontSize() * 12.0f;
    if (right - (ImGui::GetItemRectMax().x + style.ItemSpacing.x) - label_width >= least)
        ImGui::SameLine();
    ImGui::SetNextItemWidth(
        std::clamp(right - ImGui::GetCursorScreenPos().x - label_width, least, most));
    float shown = static_cast<float>(state.doc.options.clock);
    // A clock typed is taken when the typing ends: 0.5 does not render at 0 first.
    const bool moved = slider_float("clock", shown, 0.0f, 1.0f, "%.3f");
    note_item("clock", true);
    tooltip(
        "The value of clock in the scene: moving it renders the scene at that time. The "
        "file is not changed; jtracer-cli --clock V renders the same image. Ctrl+click "
        "types a value.");
    if (play_hovered) {
        // Under the slider's row, or else above Play: where ImGui puts a
        // tooltip (under the mouse, or beside it when there is no room under
        // it) it covered the slider's value, which is what moves while playing.
        const float below = ImGui::GetItemRectMax().y + style.ItemSpacing.y;
        const bool fits_below =
            below + 4.0f * ImGui::GetTextLineHeightWithSpacing() < ImGui::GetIO().DisplaySize.y;
        ImGui::SetNextWindowPos(fits_below ? ImVec2(play_min.x, below)
                                           : ImVec2(play_min.x, play_min.y - style.ItemSpacing.y),
                                ImGuiCond_Always, ImVec2(0.0f, fits_below ? 0.0f : 1.0f));
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
        ImGui::TextUnformatted(playing ? "Stop at this clock"
                                       : "Play the scene's time: clock runs from 0 to 1 in 4 "
                                         "seconds, then again from 0 (each step renders anew; "
                                         "the file is not changed)");
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    if (moved) {
        state.time.playing = false;  // scrubbing takes the clock from play
        set_clock(state, ui_rounded(static_cast<double>(shown)));
    }
}

}  // namespace jt::view
