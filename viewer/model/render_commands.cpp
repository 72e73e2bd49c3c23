#include "model/render_commands.hpp"

#include "model/app_actions.hpp"

#include "jtracer/limits.hpp"
#include "jtracer/validate.hpp"
#include "model/render_region.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace jt::view {

void toggle_pause(AppState& state) {
    state.render.paused = !state.render.paused;
    if (state.render.paused) {
        state.render.renderer.pause();
        state.message = "Paused";
        return;
    }
    state.message = "Rendering";
    // Continue the paused render when it still answers what should be shown;
    // otherwise (edited while paused) update_render starts a new one.
    std::string note;
    const std::optional<RenderRequest> request = render_request(state, note);
    if (!state.render.started || request != state.render.started || !state.render.renderer.resume())
        state.render.started.reset();
}

std::optional<RenderRequest> render_request(const AppState& state, std::string& note) {
    note.clear();
    if (!state.doc.loaded) {
        note = "No scene loaded";
        return std::nullopt;
    }
    const Scene& scene = state.doc.scene;
    if (scene.cameras.empty()) {
        note = "The scene has no camera";
        return std::nullopt;
    }
    RenderRequest request;
    request.scene_revision = state.doc.revision;
    request.primitive_count = scene.primitives.size();
    request.options.camera = selected_camera(state.view, state.doc.scene);
    if (state.view.free_camera_active) {
        request.free_camera = state.view.free_camera;
        request.options.camera = static_cast<int>(scene.cameras.size());
    }
    const RenderSettings& settings = scene.settings;
    request.options.width = settings.width;
    request.options.height = settings.height;
    if (settings.width <= 0 || settings.height <= 0) {
        note = "width/height are not set: previewing at 640x480";
        request.options.width = 640;
        request.options.height = 480;
    }
    if (static_cast<long long>(request.options.width) * request.options.height >
        state.config.max_pixels) {
        note = "The image is too large to preview (" + std::to_string(request.options.width) + "x" +
               std::to_string(request.options.height) + ")";
        return std::nullopt;
    }
    request.options.samples = std::clamp(settings.samples, kMinSamples, kMaxSamples);
    request.options.threads = state.config.render_threads;
    request.options.previews = true;
    request.options.region =
        render_region_rect(state.view, request.options.width, request.options.height);
    // The frames come first: a frame drawn late is a late picture however fast
    // the render is (and with a software GL the frame needs a core too).
    request.options.background = state.config.render_in_background;
    return request;
}

Scene scene_to_render(const SceneDocument& doc, const RenderRequest& request) {
    Scene scene = doc.scene;
    if (request.free_camera) scene.cameras.push_back(camera_from(*request.free_camera, "viewer"));
    return scene;
}

namespace {

// The first error validation finds in what a render would show, or empty. An
// edit can make the scene invalid (a zero plane normal, say). The document's
// own scene is not validated again when the check of its diagnostics, still
// current, found no errors (a changed model file ends the check's currency).
std::string validation_error(const AppState& state, const Scene& scene,
                             const RenderRequest& request) {
    const CheckState& check = state.check;
    if (!request.free_camera && check.checked_revision == state.doc.revision &&
        check.error_free_revision == state.doc.revision)
        return {};
    for (const Diagnostic& d : validate_scene(scene, SceneSource{}))
        if (d.severity == Severity::error) return d.message;
    return {};
}

// Waits, at most config.first_pass_wait (opened_first_pass_wait for a render
// of a preparation made ahead), for the render just started to finish its
// first pass (the render's wakeup ends the wait at once).
void wait_for_first_pass(AppState& state) {
    const ViewerConfig& config = state.config;
    const std::chrono::milliseconds wait =
        state.render.renderer.renders_adopted()
            ? std::max(config.first_pass_wait, config.opened_first_pass_wait)
            : config.first_pass_wait;
    const auto deadline = std::chrono::steady_clock::now() + wait;
    for (;;) {
        const std::uint64_t seen = state.wakeup.count();
        if (state.render.renderer.passes_since_start() > 0 || !state.render.renderer.active())
            return;
        if (!state.wakeup.wait(seen, deadline)) return;
    }
}

}  // namespace

void update_render(AppState& state) {
    if (state.render.paused) {
        std::string note;
        state.render.edit_waiting = render_request(state, note) != state.render.started;
    } else {
        state.render.edit_waiting = false;
        std::optional<RenderRequest> request = render_request(state, state.render.render_note);
        if (request && clear_region_for_new_view(state, *request))
            request = render_request(state, state.render.render_note);
        if (request && request == state.render.rejected) {
            state.render.render_note = state.render.rejected_reason;
        } else if (request && request != state.render.started) {
            // An unedited scene renders as the document holds it, without a
            // copy (and, just opened, with the preparation started for it).
            std::shared_ptr<const Scene> scene =
                !request->free_camera && !scene_edited(state.doc)
                    ? state.doc.original
                    : std::make_shared<const Scene>(scene_to_render(state.doc, *request));
            if (const std::string error = validation_error(state, *scene, *request);
                !error.empty()) {
                // Keep the last image rather than render nonsense; say why.
                state.render.rejected = std::move(request);
                state.render.rejected_reason = "Not rendered: " + error;
                state.render.render_note = state.render.rejected_reason;
            } else {
                state.render.rejected.reset();
                state.render.converging = converging_effects(*scene, *request);
                state.render.renderer.start(std::move(scene), request->options);
                state.render.started = std::move(request);
                state.render.display_complete = false;
                wait_for_first_pass(state);
            }
        }
    }
    // Read `finished` and the progress before fetching: a fetch after them has
    // every pixel they count.
    const bool finished = state.render.renderer.finished();
    const RenderProgress progress = state.render.renderer.progress();
    if (auto changed = state.render.renderer.fetch(state.render.display))
        state.render.display_changed = holding_both(state.render.display_changed, *changed);
    state.render.passes_shown = progress.finished ? progress.pass_count : progress.pass;
    if (finished && state.render.started) state.render.display_complete = true;
}

void keep_render_for(RenderState& render, std::uint64_t from, std::uint64_t to) {
    if (render.started && render.started->scene_revision == from)
        render.started->scene_revision = to;
    if (render.rejected && render.rejected->scene_revision == from)
        render.rejected->scene_revision = to;
}

std::optional<PixelRect> take_display_changes(RenderState& render) {
    return std::exchange(render.display_changed, std::nullopt);
}

std::string converging_effects(const Scene& scene, const RenderRequest& request) {
    const bool soft = std::any_of(scene.lights.begin(), scene.lights.end(),
                                  [](const PointLight& light) { return light.radius > 0.0; });
    // The free camera is a pinhole; one sample a pixel is the lens's centre alone.
    const auto camera = static_cast<std::size_t>(request.options.camera);
    const bool lens = !request.free_camera && request.options.samples > 1 &&
                      camera < scene.cameras.size() && scene.cameras[camera].aperture > 0.0;
    if (soft && lens) return "soft shadows and lens";
    if (soft) return "soft shadows";
    return lens ? "lens" : "";
}

std::string pass_label(const RenderProgress& p, int target_samples, const std::string& converging) {
    if (p.pass_name.rfind("preview", 0) == 0) {
        // The previews trace hard shadows through the lens's centre.
        if (converging.empty()) return p.pass_name;
        const bool soft = converging.find("soft shadows") != std::string::npos;
        const bool lens = converging.find("lens") != std::string::npos;
        return p.pass_name + (soft && lens ? " (hard shadows, sharp)"
                              : soft       ? " (hard shadows)"
                                           : " (sharp)");
    }
    // The core names its full-resolution passes by the samples they reach.
    const int reached = std::max(std::atoi(p.pass_name.c_str()), 1);
    if (target_samples <= 1)
        return converging.empty() ? "full resolution" : "full resolution with " + converging;
    if (converging.empty() && reached <= 1) return "full resolution";
    const std::string sample =
        "sample " + std::to_string(reached) + " of " + std::to_string(target_samples);
    return converging.empty() ? sample : converging + ": " + sample;
}

std::string render_title_status(const RenderState& render) {
    if (!render.started) return render.paused ? "paused" : "";
    const RenderProgress p = render.renderer.progress();
    char text[96];
    if (render.paused) return render.edit_waiting ? "paused, edit waiting" : "paused";
    if (render_complete(render)) {
        std::snprintf(text, sizeof text, "done, %d sample%s, %.1f s", p.samples_done,
                      p.samples_done == 1 ? "" : "s", p.seconds);
        return text;
    }
    std::snprintf(text, sizeof text, "%s %d%%",
                  pass_label(p, render.started->options.samples, render.converging).c_str(),
                  static_cast<int>(p.fraction * 100.0));
    return text;
}

bool render_complete(const RenderState& render) {
    return render.started && render.display_complete && !render.paused;
}

bool waiting_for_workers(const FileState& files, const RenderState& render) {
    if (files.loader.in_flight()) return true;
    if (files.loader.busy()) return false;  // a finished load waits to be taken in
    return render.started && !render.paused && render.renderer.active() &&
           render.renderer.passes_since_start() == 0;
}

std::chrono::milliseconds workers_frame_wait(const AppState& state) {
    const RenderState& render = state.render;
    const bool render_running = render.started && !render.paused && render.renderer.active();
    const bool moving = render_running || state.drags.object || state.time.playing;
    return state.files.loader.in_flight() && !moving ? idle_frame_wait : worker_frame_wait;
}

}  // namespace jt::view
