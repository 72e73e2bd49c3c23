#include "model/model_frame.hpp"

#include "model/app_actions.hpp"
#include "model/document_edits.hpp"

#include <thread>

namespace jt::view {

void model_frame(AppState& state) {
    reload_if_changed(state);
    take_finished_load(state);
    step_play(state, std::chrono::steady_clock::now());
    take_checked_text(state);
    check_edits(state.check, state.doc, state.files);
    update_render(state);
}

bool run_frames_until_complete(AppState& state, const std::function<void()>& frame,
                               std::chrono::milliseconds timeout, int settle_frames) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    frame();
    while (!render_complete(state.render) || state.files.loader.busy()) {
        const bool loading = state.files.loader.busy();
        if ((!state.render.started && !loading) || std::chrono::steady_clock::now() > deadline)
            return false;
        // Leave the cores to the render; the picture is only read at the end.
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        frame();
    }
    for (int i = 0; i < settle_frames; ++i) frame();
    return true;
}

bool run_frames_until_loaded(AppState& state, const std::function<void()>& frame,
                             std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    frame();
    while (state.files.loader.busy()) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        frame();
    }
    return true;
}

}  // namespace jt::view
