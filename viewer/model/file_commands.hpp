#pragma once
// The commands on the scene's file: open, reload (also when it or a file it
// names changes on disk), save, save as, the image's save, and the prompts
// that guard unsaved edits (quit, open another).

#include "model/app_state.hpp"

#include <filesystem>
#include <string>
#include <vector>

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

// Unsaved edits of the scene, or text typed in an included file (editor_files.hpp).
bool has_unsaved_work(const AppState& state);
// The files that hold it, as the editor names them: the scene file's name
// first when its edits are unsaved, then each included file typed in.
std::vector<std::string> unsaved_file_names(const AppState& state);

// The status line's message (state.message), unless it says the files hold
// the work shown and there is unsaved work since: then that there is.
const std::string& shown_message(const AppState& state);

// Saves the edits into the file, and the text typed in included files into
// theirs (then reloads the scene), unless a file changed on disk since it was
// loaded: then nothing is written and `save_conflict` says so. The status
// line names the files written ("Saved /home/me/scene.jts and parts/ball.jts").
bool save_scene(AppState& state);
// Saves even though a file changed on disk, replacing what is there.
bool save_scene_anyway(AppState& state);
// After a save refused for included files changed under the text typed in
// them (save_conflict_drafts): drops that text, keeping the files on disk.
void revert_conflicting_drafts(AppState& state);
// Writes the current image to `path`; never replaces a file (see
// save_image_numbered in image_files.hpp): when `path` exists the first free
// numbered name beside it is used, and the message says which.
bool save_image(AppState& state, const std::filesystem::path& path);
// The same to state.save_image_path (the S key).
bool save_image_numbered(AppState& state);
// A path the user typed (Open, Save scene as): a relative one is read against
// the scene file's folder, as its includes and images are, and made absolute;
// with no scene file, against the working folder.
std::filesystem::path beside_scene(const SceneDocument& doc, const std::filesystem::path& typed);
// Writes the edited scene to `path` and makes that the open file. A relative
// `path` is read against the scene file's folder (beside_scene). A file already there is
// replaced only with `replace`; otherwise nothing is written and
// state.files.save_as_conflict names it.
bool save_scene_as(AppState& state, const std::filesystem::path& path, bool replace);

// Quitting and opening another file go through these: with unsaved edits
// nothing happens until the user answers the prompt (state.files.unsaved_prompt).
void request_quit(AppState& state);
void request_open_guarded(AppState& state, const std::filesystem::path& path);
// Opens the file named in the Open field (state.fields.open_path_input), a
// relative path read against the scene file's folder (beside_scene); guarded
// as request_open_guarded.
void open_typed_path(AppState& state);
enum class UnsavedChoice { save, discard, cancel };
// Save runs the command only when the save succeeded (a refused save shows
// why and keeps the edits).
void resolve_unsaved(AppState& state, UnsavedChoice choice);

// Writes the panel width to config.settings_file when it changed since the
// last write. A file that cannot be written is no reason to fail: it is not
// tried again until the width changes.
void remember_settings(ViewState& view, const ViewerConfig& config);

}  // namespace jt::view
