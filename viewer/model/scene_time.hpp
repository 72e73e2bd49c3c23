#pragma once
// The scene's time (docs/language.md §15.4): the value of `clock` the viewer
// renders at, set by the time slider or by playing. Moving it computes the
// scene again from its text at the new clock and renders that; the file and
// the undo history are not touched, and panel edits stay as they were.

#include "jtracer/source_map.hpp"

#include <chrono>
#include <string_view>

namespace jt::view {

struct AppState;
struct SceneDocument;

// The word `clock` stands in a value that is a name or an expression: a
// property's, a define's or a named material's, in the main text or in any
// file it includes (not in a comment, a string or another word such as
// `clockwise`).
bool text_uses_clock(std::string_view text, const SceneSource& source);

// One loop of play, from clock 0 to 1; then it starts over at 0.
inline constexpr std::chrono::milliseconds kPlayLoop{4000};

struct TimeState {
    bool playing = false;
    std::chrono::steady_clock::time_point last_step;
};

// Computes the scene at `clock` (finite); false, with state.message saying
// why, when it cannot be now (a field being dragged, no scene, a text with
// errors at that clock). Never writes the file or records an undo step.
bool set_clock(AppState& state, double clock);

// Play and pause. Playing starts from the clock shown (from 0 at the end).
void toggle_play(AppState& state, std::chrono::steady_clock::time_point now);
// While playing: moves the clock on by the time since the last step, looping
// at 1 back to 0. Called once a frame; does nothing when not playing.
void step_play(AppState& state, std::chrono::steady_clock::time_point now);

}  // namespace jt::view
