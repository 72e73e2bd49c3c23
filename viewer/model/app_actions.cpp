#include "model/app_actions.hpp"

#include "model/render_region.hpp"

#include "jtracer/limits.hpp"
#include "jtracer/model_cache.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/validate.hpp"
#include "model/image_files.hpp"
#include "model/object_drag.hpp"
#include "model/ui_rounding.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace jt::view {

namespace {

int scene_camera_index(const Scene& scene) {
    return std::max(active_camera_index(scene), 0);
}

void after_scene_replaced(AppState& state, const Scene& before) {
    keep_camera_selection(state.view, state.doc.scene, before);
    state.history.undo.clear();
    state.history.edit_base.reset();
    state.files.pending_reload.reset();
    state.files.save_conflict.clear();
    note_command_edit(state.history, state.doc);
}

bool has_located(const std::vector<Diagnostic>& diagnostics) {
    for (const Diagnostic& d : diagnostics)
        if (d.pos.line > 0) return true;
    return false;
}

std::string camera_label(const Camera& camera, int index) {
    return camera.name.empty() ? "camera " + std::to_string(index + 1) : camera.name;
}

}  // namespace

void keep_camera_selection(ViewState& view, const Scene& scene, const Scene& before) {
    const auto& cameras = scene.cameras;
    const int count = static_cast<int>(cameras.size());
    const int old = view.camera_index;
    if (old >= 0 && old < static_cast<int>(before.cameras.size())) {
        const std::string& name = before.cameras[old].name;
        if (old < count && cameras[old].name == name) return;
        if (const int same = name.empty() ? -1 : find_camera(scene, name); same >= 0) {
            view.camera_index = same;
            return;
        }
    }
    if (old < 0 || old >= count) view.camera_index = scene_camera_index(scene);
}

namespace {

void finish_open(AppState& state, const std::filesystem::path& path, LoadAttempt attempt) {
    const bool ok = attempt.ok;
    const bool first = !state.doc.loaded;
    const Scene before = state.doc.scene;
    accept_load(state.doc, path, std::move(attempt));
    if (ok || first) {
        state.files.watcher = FileWatcher(state.config.watch_interval);
        state.files.watcher.watch(path);
    }
    if (ok) {
        state.view.camera_index = scene_camera_index(state.doc.scene);
        state.view.free_camera_active = false;
        after_scene_replaced(state, before);
        state.files.recent.add(path);
        state.fields.open_path_input = path.string();
        state.message = "Opened " + path.string();
    } else if (document_is_blank(state.doc)) {
        state.message = path.filename().string() +
                        " is empty: Start a scene in the File panel, or type one in the Text "
                        "editor (T)";
    } else if (state.doc.diagnostics_source.empty() && !has_located(state.doc.diagnostics)) {
        state.message = "Could not open " + path.string() + ": see Diagnostics";
    } else {
        state.message = path.filename().string() + " has errors: see Diagnostics" +
                        (state.doc.loaded && !first ? " (still showing the last good scene)" : "");
    }
}

// The open file, read again, has errors: with no unsaved edits the text
// editor shows it with its errors (accept_broken_file); the last good scene
// and image stay.
void show_broken_file(AppState& state, LoadAttempt attempt) {
    accept_broken_file(state.doc, std::move(attempt));
    // The scene is not replaced (no new revision, no render); the history
    // was of the text before.
    state.history.undo.clear();
    state.history.edit_base.reset();
    state.files.pending_reload.reset();
    state.files.save_conflict.clear();
    state.history.typing = false;
    state.check.checker.cancel();
    state.message = state.doc.path.filename().string() +
                    (state.doc.loaded ? " has errors: the text editor (T) shows them; the image is "
                                        "of the last good scene"
                                      : " has errors");
}

void finish_reload(AppState& state, LoadAttempt attempt) {
    const std::string name = state.doc.path.filename().string();
    if (!attempt.read) {
        // Nothing to show instead: the viewer's text is all there is now.
        accept_load(state.doc, state.doc.path, std::move(attempt));
        state.message = state.doc.file_deleted
                            ? name +
                                  " was deleted: the viewer keeps its text; Save scene writes "
                                  "it again"
                            : name + " cannot be read: see Diagnostics";
        return;
    }
    if (!attempt.ok && !has_unsaved_edits(state.doc)) {
        show_broken_file(state, std::move(attempt));
        return;
    }
    if (!has_unsaved_edits(state.doc)) {
        const Scene before = state.doc.scene;
        accept_load(state.doc, state.doc.path, std::move(attempt));
        after_scene_replaced(state, before);
        state.message = "Reloaded " + name;
        return;
    }
    // Replacing the scene now would throw the edits away: ask first.
    // The same text again: the only choice is whether to drop the edits, and
    // the diagnostics stay those of the edited scene.
    const bool unchanged = attempt.text == state.doc.disk_text;
    state.files.reapply_problem.clear();
    if (!unchanged) {
        if (const Expected<Scene> reapplied = reapply_edits(state.doc, attempt); !reapplied)
            state.files.reapply_problem = reapplied.error().message;
        state.doc.load_failed = !attempt.ok;
        state.doc.diagnostics = attempt.diagnostics;
        state.doc.diagnostics_source = attempt.text;
    }
    const bool broken = !attempt.ok;
    state.files.pending_reload = std::move(attempt);
    state.message = unchanged
                        ? name +
                              " is unchanged on disk; reloading it would drop your "
                              "unsaved edits: choose in the bar above the image"
                        : name + " changed on disk" + (broken ? " (it has errors)" : "") +
                              " while you have unsaved edits: choose in the bar above the image";
}

}  // namespace

void open_scene(AppState& state, const std::filesystem::path& path) {
    request_open(state, path);
    state.files.loader.wait();
    take_finished_load(state);
}

void request_open(AppState& state, const std::filesystem::path& path) {
    state.files.loader.request(path, LoadPurpose::open);
    state.message = "Opening " + path.string();
}

void reload_scene(AppState& state) {
    if (state.doc.path.empty()) return;
    state.files.loader.request(state.doc.path, LoadPurpose::reload);
}

namespace {

// After a model or image file changed (or is to be read again): the scene's
// diagnostics are checked and its render started again, so that a file that
// no longer loads is reported where the scene names it and keeps the last
// image (update_render), and one that loads is shown.
void files_changed(AppState& state, bool models) {
    if (models) {
        state.render.renderer.forget_prepared();
        state.view.mesh_figures.reset();
    }
    state.check.checked_revision.reset();
    state.render.rejected.reset();
    state.render.started.reset();
}

bool assets_changed(AppState& state) {
    if (!state.files.asset_watcher.due()) return false;
    const NamedFiles files = named_files(state.doc.scene);
    std::vector<std::filesystem::path> watched = files.models;
    watched.insert(watched.end(), files.images.begin(), files.images.end());
    state.files.asset_watcher.watch(watched);
    const std::vector<std::filesystem::path> changed = state.files.asset_watcher.poll();
    if (changed.empty()) return false;
    bool models = false;
    for (const std::filesystem::path& file : changed)
        if (std::find(files.models.begin(), files.models.end(), file) != files.models.end()) {
            forget_model(file);
            models = true;
        }
    files_changed(state, models);
    state.message = changed.front().filename().string() +
                    (changed.size() > 1 ? " and other files" : "") +
                    " changed on disk: rendering again";
    return true;
}

}  // namespace

bool reload_if_changed(AppState& state) {
    const bool assets = state.doc.loaded && assets_changed(state);
    if (!state.files.watcher.poll()) return assets;
    reload_scene(state);
    return true;
}

void reload_model(AppState& state, std::size_t primitive) {
    const auto& primitives = state.doc.scene.primitives;
    const Mesh* mesh =
        primitive < primitives.size() ? std::get_if<Mesh>(&primitives[primitive].shape) : nullptr;
    if (!mesh) return;
    forget_model(asset_path(state.doc.scene, mesh->file));
    files_changed(state, true);
    state.message = "Reading " + mesh->file + " again";
}

bool take_finished_load(AppState& state) {
    std::optional<FinishedLoad> done = state.files.loader.take();
    if (!done) return false;
    state.files.last_load_times = done->attempt.times;
    // A reload of a file that is no longer the open one is stale.
    if (done->purpose == LoadPurpose::reload && done->path != state.doc.path) return true;
    if (done->purpose == LoadPurpose::open)
        finish_open(state, done->path, std::move(done->attempt));
    else
        finish_reload(state, std::move(done->attempt));
    return true;
}

void resolve_reload(AppState& state, ReloadChoice choice) {
    if (!state.files.pending_reload) return;
    const std::string name = state.doc.path.filename().string();
    if (choice == ReloadChoice::keep_edits) {
        state.files.pending_reload.reset();
        state.message = "Kept your edits; " + name +
                        " on disk differs, so Save scene will ask before overwriting it";
        return;
    }
    std::optional<Scene> edited;
    if (choice == ReloadChoice::reapply_edits) {
        Expected<Scene> reapplied = reapply_edits(state.doc, *state.files.pending_reload);
        if (!reapplied) {
            state.message = "Edits not re-applied: " + reapplied.error().message;
            return;
        }
        edited = std::move(*reapplied);
    }
    LoadAttempt newer = std::move(*state.files.pending_reload);
    if (!newer.ok) {
        show_broken_file(state, std::move(newer));
        state.message = "Reloaded " + name + " (it has errors); your edits were dropped";
        return;
    }
    const Scene before = state.doc.scene;
    accept_load(state.doc, state.doc.path, std::move(newer));
    after_scene_replaced(state, before);
    if (edited) {
        state.doc.scene = std::move(*edited);
        note_command_edit(state.history, state.doc);
        keep_camera_selection(state.view, state.doc.scene, before);
        // One undo shows the file as it is.
        state.history.undo.record({state.doc.text, state.doc.original, std::nullopt});
        state.message = "Reloaded " + name + " and re-applied your edits (not saved yet)";
    } else {
        state.message = "Reloaded " + name + "; your edits were dropped";
    }
}

namespace {

bool save_now(AppState& state) {
    if (const Expected<void> saved = save_scene_in_place(state.doc); !saved) {
        state.message = "Scene not saved: " + saved.error().message;
        return false;
    }
    state.files.watcher.acknowledge();     // our own write is not an outside change
    state.check.checked_revision.reset();  // the diagnostics now describe the new text
    state.files.save_conflict.clear();
    state.files.pending_reload.reset();
    state.message = "Saved " + state.doc.path.string();
    return true;
}

}  // namespace

bool save_scene(AppState& state) {
    std::string what;
    if (state.doc.loaded && file_changed_on_disk(state.doc, what)) {
        state.files.save_conflict = state.doc.path.filename().string() + " " + what +
                                    " since it was loaded; saving would replace that";
        state.message = "Scene not saved: " + state.files.save_conflict;
        return false;
    }
    return save_now(state);
}

bool save_scene_anyway(AppState& state) {
    return save_now(state);
}

bool save_image(AppState& state, const std::filesystem::path& path) {
    const Expected<std::filesystem::path> written =
        jt::view::save_image_numbered(path, state.render.display);
    if (!written) {
        state.message = "Image not saved: " + written.error().message;
        return false;
    }
    state.message = "Saved image " + written->string();
    if (*written != path) state.message += " (" + path.filename().string() + " exists)";
    return true;
}

bool save_image_numbered(AppState& state) {
    return save_image(state, state.fields.save_image_path);
}

bool save_scene_as(AppState& state, const std::filesystem::path& path, bool replace) {
    state.files.save_as_conflict.clear();
    if (!state.doc.loaded) {
        state.message = "Scene not saved: no scene is open";
        return false;
    }
    std::error_code ec;
    if (!replace && std::filesystem::exists(path, ec)) {
        state.files.save_as_conflict = path.string();
        state.message = "Scene not saved: " + path.string() + " exists";
        return false;
    }
    if (const Expected<void> saved = save_scene_copy(state.doc, path); !saved) {
        state.message = "Scene not saved: " + saved.error().message;
        return false;
    }
    state.files.watcher = FileWatcher(state.config.watch_interval);
    state.files.watcher.watch(path);
    state.check.checked_revision.reset();
    state.files.save_conflict.clear();
    state.files.pending_reload.reset();
    state.files.recent.add(path);
    state.fields.open_path_input = path.string();
    state.message = "Saved " + path.string();
    return true;
}

void check_edits(CheckState& check, SceneDocument& doc, const FileState& files) {
    // A failed load's diagnostics describe the file, and a pending reload's the
    // newer text: both stay until the file is fixed or the user chooses.
    if (!doc.loaded || doc.load_failed ||
        (files.pending_reload && files.pending_reload->text != doc.disk_text) || doc.draft) {
        check.checked_revision.reset();
        return;
    }
    if (check.checked_revision == doc.revision) return;
    doc.diagnostics = doc.parse_diagnostics;
    std::vector<Diagnostic> more = validate_scene(doc.scene, doc.source);
    doc.diagnostics.insert(doc.diagnostics.end(), more.begin(), more.end());
    doc.diagnostics_source = doc.text;
    doc.diagnostics_path = doc.path;
    check.checked_revision = doc.revision;
}

void edit_scene(AppState& state, const std::function<void(Scene&)>& change) {
    const Scene before = state.doc.scene;
    const DocumentVersion version = version_of(state.doc);
    change(state.doc.scene);
    keep_camera_selection(state.view, state.doc.scene, before);
    state.history.undo.record(version);
    note_command_edit(state.history, state.doc);
}

namespace {

// After undo or redo: a draft brought back is checked again (for its
// diagnostics); any other text ends the typing burst and its pending check.
void recheck_draft(AppState& state) {
    state.history.typing = false;
    if (state.doc.draft)
        state.check.checker.check(++state.check.draft_id, *state.doc.draft, state.doc.path,
                                  std::chrono::milliseconds(0));
    else
        state.check.checker.cancel();
}

}  // namespace

namespace {

// Moves one step through the undo history; `step` is the stack's undo or redo.
// Undo or redo during a drag that moves an object gives back the document as
// the drag found it, and nothing more: the drag is the step being undone.
template <class Step>
void step_history(AppState& state, Step step, const char* done) {
    if (state.drags.object) {
        cancel_object_drag(state);
        return;
    }
    if (auto version = step(version_of(state.doc))) {
        const Scene before = state.doc.scene;
        restore_version(state.doc, *version);
        keep_camera_selection(state.view, state.doc.scene, before);
        state.message = done;
    }
    recheck_draft(state);
    state.history.edit_base.reset();
    note_command_edit(state.history, state.doc);
}

}  // namespace

void undo(AppState& state) {
    step_history(
        state, [&](auto current) { return state.history.undo.undo(std::move(current)); }, "Undone");
}

void redo(AppState& state) {
    step_history(
        state, [&](auto current) { return state.history.undo.redo(std::move(current)); }, "Redone");
}

void note_command_edit(EditHistory& history, SceneDocument& doc) {
    ++history.scene_generation;
    note_scene_changed(doc);
}

EditMark begin_edit_tracking(EditHistory& history, const SceneDocument& doc) {
    if (!history.edit_base && history.settled_revision != doc.revision) {
        history.settled_scene = doc.scene;
        history.settled_revision = doc.revision;
    }
    return {doc.revision, history.scene_generation};
}

void track_edits(EditHistory& history, const SceneDocument& doc, EditMark before,
                 bool widget_active) {
    if (history.scene_generation != before.generation) {
        history.edit_base.reset();
        return;
    }
    if (doc.revision != before.revision && !history.edit_base &&
        history.settled_revision == before.revision) {
        history.edit_base = std::move(history.settled_scene);
        history.settled_revision.reset();
    }
    if (!widget_active && history.edit_base) {
        // A field touched and put back leaves no step to undo.
        if (*history.edit_base != doc.scene)
            history.undo.record({doc.text, *history.edit_base, doc.draft});
        history.edit_base.reset();
    }
}

int selected_camera(const ViewState& view, const Scene& scene) {
    const int count = static_cast<int>(scene.cameras.size());
    if (count == 0) return -1;
    return std::clamp(view.camera_index, 0, count - 1);
}

void select_camera(AppState& state, int index) {
    const int count = static_cast<int>(state.doc.scene.cameras.size());
    if (count == 0) return;
    state.view.camera_index = std::clamp(index, 0, count - 1);
    state.view.free_camera_active = false;
    state.message = "Camera: " + camera_label(state.doc.scene.cameras[state.view.camera_index],
                                              state.view.camera_index);
}

void next_camera(AppState& state) {
    const int count = static_cast<int>(state.doc.scene.cameras.size());
    if (count == 0) return;
    select_camera(state, state.view.free_camera_active ? state.view.camera_index
                                                       : (state.view.camera_index + 1) % count);
}

void use_free_camera(ViewState& view, const Scene& scene) {
    if (view.free_camera_active || scene.cameras.empty()) return;
    reset_free_camera(view, scene);
    view.free_camera_active = true;
}

void reset_free_camera(ViewState& view, const Scene& scene) {
    const auto& cameras = scene.cameras;
    if (cameras.empty()) return;
    view.free_camera = free_camera_from(cameras[selected_camera(view, scene)]);
}

bool copy_free_camera_to_scene(AppState& state, const std::string& name) {
    if (!state.doc.loaded || state.doc.scene.cameras.empty()) return false;
    if (find_camera(state.doc.scene, name) >= 0) {
        state.message = "A camera is already called \"" + name + "\": choose another name";
        return false;
    }
    const Scene before = state.doc.scene;
    const FreeCamera from =
        state.view.free_camera_active
            ? state.view.free_camera
            : free_camera_from(
                  state.doc.scene.cameras[selected_camera(state.view, state.doc.scene)]);
    Camera camera = camera_from(from, name);
    if (state.view.free_camera_active) {  // moved with the mouse: short numbers in the file
        camera.position = ui_rounded(camera.position);
        camera.look_at = ui_rounded(camera.look_at);
    }
    const DocumentVersion version = version_of(state.doc);
    state.doc.scene.cameras.push_back(std::move(camera));
    state.history.undo.record(version);
    note_command_edit(state.history, state.doc);
    state.view.camera_index = static_cast<int>(state.doc.scene.cameras.size()) - 1;
    state.view.free_camera_active = false;
    state.message = "Added camera \"" + name + "\" (Save scene to keep it)";
    return true;
}

namespace {

void run_guarded(AppState& state, const GuardedCommand& command) {
    if (command.kind == GuardedCommand::Kind::quit)
        state.quit = true;
    else
        request_open(state, command.path);
}

void guard(AppState& state, GuardedCommand command) {
    if (!has_unsaved_edits(state.doc)) {
        run_guarded(state, command);
        return;
    }
    state.files.unsaved_prompt = std::move(command);
    state.message = "Unsaved edits: save them, discard them or cancel";
}

}  // namespace

void request_quit(AppState& state) {
    guard(state, {GuardedCommand::Kind::quit, {}});
}

void request_open_guarded(AppState& state, const std::filesystem::path& path) {
    guard(state, {GuardedCommand::Kind::open, path});
}

void resolve_unsaved(AppState& state, UnsavedChoice choice) {
    if (!state.files.unsaved_prompt) return;
    const GuardedCommand command = std::move(*state.files.unsaved_prompt);
    state.files.unsaved_prompt.reset();
    if (choice == UnsavedChoice::cancel) {
        state.message = "Cancelled: your edits are still here";
        return;
    }
    if (choice == UnsavedChoice::save && !save_scene(state)) return;  // the message says why
    run_guarded(state, command);
}

void remember_settings(ViewState& view, const ViewerConfig& config) {
    ViewerSettings now = view.saved_settings;
    now.panel_width = std::clamp(view.sidebar_width, kLeastPanelWidth, kMostPanelWidth);
    if (now == view.saved_settings || config.settings_file.empty()) return;
    view.saved_settings = now;
    static_cast<void>(write_viewer_settings(config.settings_file, now));
}

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
// edit can make the scene invalid (a zero plane normal, say).
std::string validation_error(const Scene& scene) {
    for (const Diagnostic& d : validate_scene(scene, SceneSource{}))
        if (d.severity == Severity::error) return d.message;
    return {};
}

// Waits, at most config.first_pass_wait, for the render just started to finish
// its first pass (the render's wakeup ends the wait at once).
void wait_for_first_pass(AppState& state) {
    const auto deadline = std::chrono::steady_clock::now() + state.config.first_pass_wait;
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
            const Scene scene = scene_to_render(state.doc, *request);
            if (const std::string error = validation_error(scene); !error.empty()) {
                // Keep the last image rather than render nonsense; say why.
                state.render.rejected = std::move(request);
                state.render.rejected_reason = "Not rendered: " + error;
                state.render.render_note = state.render.rejected_reason;
            } else {
                state.render.rejected.reset();
                state.render.renderer.start(scene, request->options);
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

std::optional<PixelRect> take_display_changes(RenderState& render) {
    return std::exchange(render.display_changed, std::nullopt);
}

std::string pass_label(const RenderProgress& p, int target_samples) {
    if (p.pass_name.rfind("preview", 0) == 0) return p.pass_name;
    // The core names its full-resolution passes by the samples they reach.
    const int reached = std::atoi(p.pass_name.c_str());
    if (target_samples <= 1 || reached <= 1) return "full resolution";
    return "sample " + std::to_string(reached) + " of " + std::to_string(target_samples);
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
                  pass_label(p, render.started->options.samples).c_str(),
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

}  // namespace jt::view
