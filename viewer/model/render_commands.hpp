#pragma once
// The render: what should be rendered now (render_request), starting it when
// that changes, pausing, taking its pixels in, and how its state reads.

#include "model/app_state.hpp"

#include <chrono>
#include <optional>
#include <string>

namespace jt::view {

// Pauses the render, or continues it from where it paused.
void toggle_pause(AppState& state);

// Starts a render when what should be shown changed (and gives its first pass
// up to config.first_pass_wait to be done), then moves the finished pixels
// into state.render.display and notes where (state.render.display_changed).
void update_render(AppState& state);
// The rectangle of state.render.display changed since the last call, or nothing:
// what the frame code sends to the texture.
std::optional<PixelRect> take_display_changes(RenderState& render);
// The scene of revision `from` is, unchanged, the scene of revision `to` (a
// text taken in, or an undo, that reads as the scene shown): a render
// started for `from`, or refused for it, answers `to` as well, so that it
// goes on rather than starting again from its first preview.
void keep_render_for(RenderState& render, std::uint64_t from, std::uint64_t to);
// The render that update_render would start now, or nothing (with the reason
// in `note`) when there is nothing to render.
std::optional<RenderRequest> render_request(const AppState& state, std::string& note);
// The scene a request renders: the document's, with the free camera added
// when it renders.
Scene scene_to_render(const SceneDocument& doc, const RenderRequest& request);

// What the passes after the first full-resolution one refine, besides the
// edges: "soft shadows" (a light with a radius), "lens" (the camera rendered
// has an aperture and more than one sample), both joined by "and", or empty.
std::string converging_effects(const Scene& scene, const RenderRequest& request);

// A pass as a user reads it: "preview 1/8", "full resolution", "sample 4 of 16";
// with `converging` ("soft shadows and lens") the full-resolution passes say
// what they refine, "soft shadows and lens: sample 4 of 16", and the previews
// what they leave out: "preview 1/8 (hard shadows, sharp)".
std::string pass_label(const RenderProgress& progress, int target_samples,
                       const std::string& converging = {});

// The render's state for the window title: "preview 1/8 34%", "paused",
// "paused, edit waiting", "done, 16 samples, 2.1 s"; empty before any render.
std::string render_title_status(const RenderState& render);

// True once the render of the current scene has rendered every pass.
bool render_complete(const RenderState& render);

// True while the next frame would show nothing new until a worker reports: a
// file is loading, or the render just started has no pass done yet. The frame
// loop then sleeps until state.wakeup (or input) wakes it, so that the picture
// is taken in as soon as it exists rather than at the next frame tick, and no
// frame takes cores from the render meanwhile.
bool waiting_for_workers(const FileState& files, const RenderState& render);

// How long the frame loop sleeps, waking at once for input or a worker's report.
// Idle (the render complete, nothing loading): long enough to poll the files.
inline constexpr std::chrono::milliseconds idle_frame_wait{200};
// While waiting_for_workers with a render running: its progress is drawn this often.
inline constexpr std::chrono::milliseconds worker_frame_wait{50};

// The sleep while waiting_for_workers: idle_frame_wait for a load while no
// render runs and nothing else moves (an object drag, the clock playing):
// nothing on screen changes until the loader wakes the loop, and with software
// OpenGL each frame drawn meanwhile takes a core from the parse, the
// validation and the preparation ahead. worker_frame_wait otherwise.
std::chrono::milliseconds workers_frame_wait(const AppState& state);

}  // namespace jt::view
