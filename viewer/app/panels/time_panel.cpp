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

void time_panel(AppState& state) {
    if (!state.doc.uses_clock) return;
    const auto now = std::chrono::steady_clock::now();
    const bool playing = state.time.playing;
    // As wide playing as paused, so that the slider stays under the mouse.
    const float width = std::max(ImGui::CalcTextSize("Play").x, ImGui::CalcTextSize("Pause").x) +
                        2.0f * ImGui::GetStyle().FramePadding.x;
    if (button(playing ? "Pause" : "Play",
               playing ? "Stop at this clock"
                       : "Play the scene's time: clock runs from 0 to 1 in 4 seconds, then "
                         "again from 0 (each step renders anew; the file is not changed)",
               "", width))
        toggle_play(state, now);
    ImGui::SameLine();
    float shown = static_cast<float>(state.doc.options.clock);
    const bool moved = ImGui::SliderFloat("clock", &shown, 0.0f, 1.0f, "%.3f");
    note_item("clock", true);
    tooltip(
        "The value of clock in the scene: moving it renders the scene at that time. The "
        "file is not changed; jtracer-cli --clock V renders the same image. Ctrl+click "
        "types a value.");
    if (moved) {
        state.time.playing = false;  // scrubbing takes the clock from play
        set_clock(state, ui_rounded(static_cast<double>(shown)));
    }
}

}  // namespace jt::view
