#pragma once
// Frames of the viewer's model alone, without GL or ImGui, with the same
// calls as HeadlessViewer's: the model's tests run the viewer this way.

#include "model/model_frame.hpp"
#include "viewer/viewer_test_files.hpp"

#include <chrono>

namespace jt::view {

struct ModelLoop {
    void frame(AppState& state) { model_frame(state); }
    bool run_until_complete(AppState& state, std::chrono::milliseconds timeout = test::kTimeout,
                            int settle_frames = 2) {
        return run_frames_until_complete(
            state, [&] { model_frame(state); }, timeout, settle_frames);
    }
    bool run_until_loaded(AppState& state, std::chrono::milliseconds timeout = test::kTimeout) {
        return run_frames_until_loaded(
            state, [&] { model_frame(state); }, timeout);
    }
};

}  // namespace jt::view
