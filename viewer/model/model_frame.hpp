#pragma once
// The model's side of a frame, and the loops that run frames until a load or
// a render is done: what --screenshot and the tests wait with, with or without
// the frame code around it.

#include "model/app_state.hpp"

#include <chrono>
#include <functional>

namespace jt::view {

// What a frame does to the model when nothing is drawn and no input comes:
// takes in a changed file or a finished load, checks the edits, brings the
// render up to date (viewer_frame does the same around its panels).
void model_frame(AppState& state);

// Runs `frame` until the render of the current scene is complete and in
// state.render.display, then `settle_frames` more. False on timeout or when there is
// nothing to render.
bool run_frames_until_complete(AppState& state, const std::function<void()>& frame,
                               std::chrono::milliseconds timeout, int settle_frames);
// Runs `frame` until no open or reload is in flight (and once more, which
// takes the result in). False on timeout.
bool run_frames_until_loaded(AppState& state, const std::function<void()>& frame,
                             std::chrono::milliseconds timeout);

}  // namespace jt::view
