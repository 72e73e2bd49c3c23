#pragma once
// The viewer's commands, each a free function on AppState, shared by the
// panels, the keyboard shortcuts and the tests. Each leaves a one-line
// outcome in state.message.

#include "model/app_state.hpp"

#include <filesystem>
#include <functional>

namespace jt::view {

// Opens `path` and waits for it (start-up, scripts, tests). When it does not
// load, a scene already open stays open and the diagnostics show what is wrong.
void open_scene(AppState& state, const std::filesystem::path& path);
// The same without waiting: the file is read and parsed on the loader's
// thread and taken in by a later frame (take_finished_load).
void request_open(AppState& state, const std::filesystem::path& path);
// Reads the open file again, off the UI thread (also done by the watcher when
// it changes). A file with errors keeps the last good scene. With unsaved
// edits nothing is replaced: the newer text waits in `pending_reload` for the
// user's choice.
void reload_scene(AppState& state);
// Starts a reload when the watcher saw the file change, and renders again
// when a model or image file the scene names changed; true when either did.
// A changed model or image never touches the scene or its unsaved edits.
bool reload_if_changed(AppState& state);
// Reads the model file of mesh `primitive` again even when it looks
// unchanged on disk, and renders again. A file that no longer loads keeps the
// last image; the diagnostics say where and why.
void reload_model(AppState& state, std::size_t primitive);
// Takes in a finished open or reload, if any; true when there was one.
bool take_finished_load(AppState& state);

enum class ReloadChoice {
    drop_edits,     // take the file as it is now
    reapply_edits,  // take the file and apply the unsaved edits to it again
    keep_edits,     // ignore the file's new text (saving will then ask)
};
void resolve_reload(AppState& state, ReloadChoice choice);

// Saves the edits into the file, unless the file changed on disk since it was
// loaded: then nothing is written and `save_conflict` says so.
bool save_scene(AppState& state);
// Saves even though the file changed on disk, replacing what is there.
bool save_scene_anyway(AppState& state);
// Writes the current image to `path`; never replaces a file (see
// save_image_numbered in image_files.hpp): when `path` exists the first free
// numbered name beside it is used, and the message says which.
bool save_image(AppState& state, const std::filesystem::path& path);
// The same to state.save_image_path (the S key).
bool save_image_numbered(AppState& state);
// Writes the edited scene to `path` and makes that the open file. A file
// already there is replaced only with `replace`; otherwise nothing is written
// and state.files.save_as_conflict names it.
bool save_scene_as(AppState& state, const std::filesystem::path& path, bool replace);

// Checks the edited scene as `jtracer-cli --check` checks a file (the load's
// parse diagnostics, then validate_scene), once after each change, so that the
// Diagnostics panel always describes the scene as it is now.
void check_edits(CheckState& check, SceneDocument& doc, const FileState& files);

// Applies `change` to the scene as one undoable step (for edits made outside
// the panels, e.g. by scripts and tests).
void edit_scene(AppState& state, const std::function<void(Scene&)>& change);

void undo(AppState& state);
void redo(AppState& state);

// Every command that changes the scene and keeps the undo stack itself (open,
// reload, undo, structure edits, drags) announces it with this: the change is
// then not taken for a panel edit (AppState::scene_generation).
void note_command_edit(EditHistory& history, SceneDocument& doc);

// Where the document stood before a frame's widgets ran.
struct EditMark {
    std::uint64_t revision = 0;    // SceneDocument::revision
    std::uint64_t generation = 0;  // AppState::scene_generation
};
// Called before the frame's widgets run; keeps state.history.settled_scene current
// (a copy once per change, none on a frame with nothing to do).
EditMark begin_edit_tracking(EditHistory& history, const SceneDocument& doc);
// Called after them, with begin_edit_tracking's mark: records one undo step
// per continuous panel edit (a whole drag is one step). A panel field that
// changes the scene says so with note_scene_changed(state.doc).
void track_edits(EditHistory& history, const SceneDocument& doc, EditMark before,
                 bool widget_active);

// The index of the scene camera the view shows (or the free camera started
// from): always one of the scene's cameras, -1 when it has none. Every command
// that replaces the scene keeps state.view.camera_index valid; readers still go
// through this so that no stale index can reach past the cameras.
int selected_camera(const ViewState& view, const Scene& scene);
// After the scene was replaced by another (undo, redo, reload, an edit of the
// text), the selected camera index may name no camera or another one: keeps
// the same camera by name when it is still there, else the scene's active one.
void keep_camera_selection(ViewState& view, const Scene& scene, const Scene& before);
void select_camera(AppState& state, int index);
void next_camera(AppState& state);
// Starts moving freely from the selected scene camera (or keeps moving).
void use_free_camera(ViewState& view, const Scene& scene);
void reset_free_camera(ViewState& view, const Scene& scene);
// Appends the free camera to the scene as a new camera named `name` and
// selects it; refused when a camera already has that name.
bool copy_free_camera_to_scene(AppState& state, const std::string& name);

// Quitting and opening another file go through these: with unsaved edits
// nothing happens until the user answers the prompt (state.files.unsaved_prompt).
void request_quit(AppState& state);
void request_open_guarded(AppState& state, const std::filesystem::path& path);
enum class UnsavedChoice { save, discard, cancel };
// Save runs the command only when the save succeeded (a refused save shows
// why and keeps the edits).
void resolve_unsaved(AppState& state, UnsavedChoice choice);

// Writes the panel width to config.settings_file when it changed since the
// last write. A file that cannot be written is no reason to fail: it is not
// tried again until the width changes.
void remember_settings(ViewState& view, const ViewerConfig& config);

// Pauses the render, or continues it from where it paused.
void toggle_pause(AppState& state);

// Starts a render when what should be shown changed (and gives its first pass
// up to config.first_pass_wait to be done), then moves the finished pixels
// into state.render.display and notes where (state.render.display_changed).
void update_render(AppState& state);
// The rectangle of state.render.display changed since the last call, or nothing:
// what the frame code sends to the texture.
std::optional<PixelRect> take_display_changes(RenderState& render);
// The render that update_render would start now, or nothing (with the reason
// in `note`) when there is nothing to render.
std::optional<RenderRequest> render_request(const AppState& state, std::string& note);
// The scene a request renders: the document's, with the free camera added
// when it renders.
Scene scene_to_render(const SceneDocument& doc, const RenderRequest& request);

// A pass as a user reads it: "preview 1/8", "full resolution", "sample 4 of 16".
std::string pass_label(const RenderProgress& progress, int target_samples);

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

}  // namespace jt::view
