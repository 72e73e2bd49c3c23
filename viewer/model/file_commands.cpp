#include "model/file_commands.hpp"

#include "model/app_actions.hpp"

#include "jtracer/model_cache.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/validate.hpp"
#include "model/image_files.hpp"

#include <algorithm>
#include <chrono>

namespace jt::view {

namespace {

void after_scene_replaced(AppState& state, const std::vector<Camera>& cameras_before) {
    keep_camera_selection(state.view, state.doc.scene, cameras_before);
    state.history.undo.clear();
    // A burst of typing under way ends with the text it typed in: the next
    // keystroke records the undo step the cleared history no longer holds.
    state.history.typing = false;
    state.history.edit_base.reset();
    state.files.pending_reload.reset();
    state.files.save_conflict.clear();
    note_command_edit(state.history, state.doc);
    // The loader validated this very scene (attempt_load's check_scene) and
    // found no errors: for 100,000 objects each validation again is a
    // noticeable part of the wait for the first preview.
    state.check.checked_revision = state.doc.revision;
    state.check.error_free_revision = state.doc.revision;
    // The scene is its text's own, just taken in: the title's "*" need not
    // compare 100,000 objects to find that out.
    state.doc.edited_at = {state.doc.revision, false};
}

bool has_located(const std::vector<Diagnostic>& diagnostics) {
    for (const Diagnostic& d : diagnostics)
        if (d.pos.line > 0) return true;
    return false;
}

}  // namespace

namespace {

void finish_open(AppState& state, const std::filesystem::path& path, LoadAttempt attempt) {
    const bool ok = attempt.ok;
    const bool first = !state.doc.loaded;
    // A file read with errors as the first scene is the document all the
    // same (the title's, the text editor's to mend): listed as opened.
    const bool listed = ok || (first && attempt.read);
    // Only the cameras are compared: copying the whole scene would cost as
    // much as the load's own copies.
    const std::vector<Camera> before = state.doc.scene.cameras;
    const std::filesystem::path was = state.doc.path;
    accept_load(state.doc, path, std::move(attempt));
    // An open was asked before dropping text typed in included files (guard):
    // none carries over to another scene. A failed open keeps the scene shown
    // with its edits (accept_load), and so with the text typed in its files.
    if (ok || first) forget_included_drafts(state.editor);
    if (state.doc.path != was) state.editor.shown.clear();
    if (ok || first) {
        state.files.watcher = FileWatcher(state.config.watch_interval);
        state.files.watcher.watch(path);
    }
    if (listed) {
        state.files.recent.add(path);
        // Absolute: the Open field reads a relative path beside the scene
        // (open_typed_path), and Open pressed again opens this same file.
        std::error_code ec;
        const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
        state.fields.open_path_input = (ec ? path : absolute).string();
    }
    if (ok) {
        state.view.camera_index = std::max(active_camera_index(state.doc.scene), 0);
        state.view.free_camera_active = false;
        // A selection is an index into the scene: in another file's it would
        // be an object the user never picked.
        // So is a Save as path typed for the file before: a Save as of
        // this one would otherwise write under a name meant for that one.
        if (state.doc.path != was) {
            state.view.selection = {};
            state.fields.save_scene_path.clear();
        }
        after_scene_replaced(state, before);
        state.message.claim_read("Opened " + path.string(), "opening", path.filename().string());
    } else if (!first && state.doc.path != path) {
        state.message = "Could not open " + path.filename().string() +
                        (has_located(state.doc.diagnostics) ? ": it has errors" : "") +
                        " (see Diagnostics); still showing " + state.doc.path.filename().string();
    } else if (document_is_blank(state.doc)) {
        state.message = path.filename().string() +
                        " is empty: Start a scene in the File panel, or type one in the Text "
                        "editor (T)";
    } else if (state.doc.diagnostics_source.empty() && !has_located(state.doc.diagnostics)) {
        state.message = "Could not open " + path.string() + ": see Diagnostics";
    } else {
        // The file shown, read again: its last good scene stays.
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
        const std::vector<Camera> before = state.doc.scene.cameras;
        // The scene shown (no edit: its text's own), shared, not copied.
        const std::shared_ptr<const Scene> shown = state.doc.original;
        const std::uint64_t revision = state.doc.revision;
        accept_load(state.doc, state.doc.path, std::move(attempt));
        after_scene_replaced(state, before);
        // An error made and mended in another editor, or a file saved
        // unchanged: the image shown is of this very scene.
        if (*state.doc.original == *shown)
            keep_render_for(state.render, revision, state.doc.revision);
        state.message.claim_read("Reloaded " + name, "reloading", name);
        // The scene now reads the file, the editor still shows the text typed
        // in it before: said now, not first when Save refuses.
        std::vector<std::string> under;
        for (const std::string& canonical : conflicting_drafts(state.doc, state.editor))
            under.push_back(draft_of(state.editor, canonical)->name);
        if (!under.empty())
            state.message = listed_names(under) +
                            " changed on disk while you were typing in it: the image shows the "
                            "file; Revert drops your text, Save scene asks before replacing it";
        return;
    }
    // Replacing the scene now would throw the edits away: ask first.
    // The same text again: the only choice is whether to drop the edits, and
    // the diagnostics stay those of the edited scene. So do those of typed
    // text (a draft): the text editor shows that text with them, and its
    // next keystroke would check it again anyway; the bar and the message
    // say whether the file on disk has errors.
    // An included file changed is a change too: its objects are new.
    state.files.changed_on_disk = changed_on_disk(state.doc, attempt);
    const std::string& changed = state.files.changed_on_disk;
    const bool unchanged = changed.empty();
    state.files.reapply_problem.clear();
    if (!unchanged) {
        if (const Expected<Scene> reapplied = reapply_edits(state.doc, attempt); !reapplied)
            state.files.reapply_problem = reapplied.error().message;
    }
    if (!unchanged && !state.doc.draft) {
        state.doc.load_failed = !attempt.ok;
        state.doc.diagnostics = attempt.diagnostics;
        state.doc.diagnostics_source = attempt.text;
        note_diagnostics_changed(state.doc);
    }
    const bool broken = !attempt.ok;
    state.files.pending_reload = std::move(attempt);
    state.message = unchanged
                        ? name +
                              " is unchanged on disk; reloading it would drop your "
                              "unsaved edits: choose in the bar above the image"
                        : changed + " changed on disk" + (broken ? " (it has errors)" : "") +
                              " while you have unsaved edits: choose in the bar above the image";
}

}  // namespace

void open_scene(AppState& state, const std::filesystem::path& path) {
    request_open(state, path);
    state.files.loader.wait();
    take_finished_load(state);
}

namespace {

FileState::UnsavedStamp unsaved_stamp(const AppState& state) {
    FileState::UnsavedStamp stamp{
        state.history.undo.changes(), state.doc.draft.value_or(state.doc.text), {}};
    for (const IncludedDraft& d : state.editor.drafts) stamp.included.push_back(d.text);
    return stamp;
}

}  // namespace

void request_open(AppState& state, const std::filesystem::path& path) {
    state.files.open_requested_over = unsaved_stamp(state);
    state.files.loader.request(path, LoadPurpose::open, state.doc.options);
    state.message = "Opening " + path.string();
}

void reload_scene(AppState& state) {
    if (state.doc.path.empty()) return;
    // An open under way replaces the document anyway; a reload of the file
    // it replaces would overtake it (the loader keeps only the newest
    // request) and the open would be lost.
    if (state.files.loader.opening()) return;
    state.files.loader.request(state.doc.path, LoadPurpose::reload, state.doc.options);
}

namespace {

// After a model or image file changed (or is to be read again): the scene's
// diagnostics are checked and its render started again, so that a file that
// no longer loads is reported where the scene names it and keeps the last
// image (update_render), and one that loads is shown.
void files_changed(AppState& state, bool models) {
    state.render.renderer.files_changed();
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

namespace {

// A file that the document's text includes changed, and that text is not the
// file's (an `include` typed, not saved yet): reading the file again would not
// read the changed one. The text, with the panels' edits written in, is
// checked again as a draft is (take_checked_text), and taken in once it
// parses; with errors it shows them and keeps the last good scene.
void read_typed_includes_again(AppState& state) {
    SceneDocument& doc = state.doc;
    if (!doc.draft) doc.draft = document_text(doc);
    state.check.checker.check(++state.check.draft_id, *doc.draft, doc.path,
                              std::chrono::milliseconds(0), doc.options);
    state.message = "A file the text includes changed on disk: reading the text again";
}

}  // namespace

bool reload_if_changed(AppState& state) {
    // A file the draft's check could not read, or read, changed (it was
    // created, say, after `include "new.jts";` was typed): the draft is
    // checked again; the file on disk is not read again for it.
    if (state.doc.draft && !state.check.draft_reads.empty() && state.files.draft_watcher.due()) {
        state.files.draft_watcher.watch(state.check.draft_reads);
        if (!state.files.draft_watcher.poll().empty())
            state.check.checker.check(++state.check.draft_id, *state.doc.draft, state.doc.path,
                                      std::chrono::milliseconds(0), state.doc.options);
    }
    const bool assets = state.doc.loaded && assets_changed(state);
    bool included = false;
    if (state.files.include_watcher.due()) {
        state.files.include_watcher.watch(state.doc.included_files);
        included = !state.files.include_watcher.poll().empty();
    }
    const bool file_changed = state.files.watcher.poll();
    if (included && !file_changed && state.doc.loaded && state.doc.text != state.doc.disk_text) {
        read_typed_includes_again(state);
        return true;
    }
    if (!file_changed && !included) return assets;
    reload_scene(state);
    return true;
}

void reload_model(AppState& state, std::size_t primitive) {
    const auto& primitives = state.doc.scene.primitives;
    const Mesh* mesh =
        primitive < primitives.size() ? shape_if<Mesh>(&primitives[primitive].shape) : nullptr;
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
    // Edited while the file loaded (the panels and the text stay editable):
    // asked about now, as the open would have asked when it was requested.
    // Save or Discard opens it again.
    if (done->purpose == LoadPurpose::open && has_unsaved_work(state) &&
        state.files.open_requested_over != unsaved_stamp(state)) {
        state.files.unsaved_prompt = GuardedCommand{GuardedCommand::Kind::open, done->path};
        state.message = "You edited while " + done->path.filename().string() +
                        " was opening: save your edits, discard them or cancel the open";
        return true;
    }
    if (done->purpose == LoadPurpose::open)
        finish_open(state, done->path, std::move(done->attempt));
    else
        finish_reload(state, std::move(done->attempt));
    // Only an open without errors comes with a preparation, and such an
    // open always makes its scene the document's original.
    if (done->ahead) state.render.renderer.adopt_prepared(std::move(*done->ahead));
    return true;
}

void resolve_reload(AppState& state, ReloadChoice choice) {
    if (!state.files.pending_reload) return;
    const std::string name = state.doc.path.filename().string();
    if (choice == ReloadChoice::keep_edits) {
        state.files.pending_reload.reset();
        // While the bar asked, the diagnostics were the newer file's; the
        // edits kept are described by their own again: the edited scene's
        // (check_edits), or the draft's, checked again now.
        state.doc.load_failed = false;
        state.check.checked_revision.reset();
        if (state.doc.draft)
            state.check.checker.check(++state.check.draft_id, *state.doc.draft, state.doc.path,
                                      std::chrono::milliseconds(0), state.doc.options);
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
        // The image stays of the last good scene: the file's, not the edits
        // just dropped, which no text holds any more.
        if (scene_edited(state.doc)) {
            state.doc.scene = *state.doc.original;
            note_scene_changed(state.doc);
        }
        show_broken_file(state, std::move(newer));
        state.message = "Reloaded " + name + " (it has errors); your edits were dropped";
        return;
    }
    const std::vector<Camera> before = state.doc.scene.cameras;
    accept_load(state.doc, state.doc.path, std::move(newer));
    after_scene_replaced(state, before);
    if (edited) {
        state.doc.scene = std::move(*edited);
        note_command_edit(state.history, state.doc);
        keep_camera_selection(state.view, state.doc.scene, before);
        // One undo shows the file as it is.
        state.history.undo.record({state.doc.text, *state.doc.original, std::nullopt});
        state.message = "Reloaded " + name + " and re-applied your edits (not saved yet)";
    } else {
        state.message.claim_read("Reloaded " + name + "; your edits were dropped", "reloading",
                                 name);
    }
}

namespace {

// Reads the scene again now, after the viewer wrote a file it includes: the
// image and the panels follow at once, and the status line says what was
// written rather than "Reloaded".
void reload_now(AppState& state) {
    if (state.doc.loaded)
        reload_scene(state);
    else
        request_open(state, state.doc.path);  // the first good load: as opening it
    state.files.loader.wait();
    take_finished_load(state);
}

bool save_now(AppState& state) {
    SceneDocument& doc = state.doc;
    const bool drafts = has_included_drafts(state.editor);
    if (const Expected<void> checked = check_included_drafts(doc, state.editor); !checked) {
        state.message = "Not saved: " + checked.error().message;
        return false;
    }
    // A read-only file typed in is found before the scene file is written.
    for (const IncludedDraft& d : state.editor.drafts)
        if (const Expected<void> ok = check_writable(d.path); !ok) {
            state.message = "Not saved: " + ok.error().message;
            return false;
        }
    std::vector<std::string> written;
    // With only included files typed in, the scene file is left as it is.
    if (!drafts || has_unsaved_edits(doc)) {
        Expected<std::vector<std::string>> saved = save_scene_in_place(doc);
        if (!saved) {
            state.message = "Scene not saved: " + saved.error().message;
            return false;
        }
        state.files.watcher.acknowledge();  // our own write is not an outside change
        written = std::move(*saved);
    }
    if (drafts) {
        Expected<std::vector<std::string>> saved = write_included_drafts(state.editor);
        if (!saved) {
            state.message = "Not saved: " + saved.error().message +
                            (written.empty() ? "" : " (" + listed_names(written) + " saved)");
            return false;
        }
        for (std::string& name : *saved)
            if (std::find(written.begin(), written.end(), name) == written.end())
                written.push_back(std::move(name));
    }
    state.files.include_watcher.acknowledge();
    state.check.checked_revision.reset();  // the diagnostics now describe the new text
    state.files.save_conflict.clear();
    state.files.pending_reload.reset();
    if (drafts) reload_now(state);
    state.message.claim_saved(written.empty() ? "Nothing to save: the files hold this scene"
                                              : "Saved " + listed_names(written));
    return true;
}

}  // namespace

bool has_unsaved_work(const AppState& state) {
    return has_unsaved_edits(state.doc) || has_included_drafts(state.editor);
}

const std::string& shown_message(const AppState& state) {
    if (state.message.claims() && has_unsaved_work(state)) return state.message.when_edited;
    return state.message;
}

std::vector<std::string> unsaved_file_names(const AppState& state) {
    std::vector<std::string> names;
    if (has_unsaved_edits(state.doc)) names.push_back(state.doc.path.filename().string());
    for (const IncludedDraft& d : state.editor.drafts) names.push_back(d.name);
    return names;
}

bool save_scene(AppState& state) {
    std::string what;
    // The scene file is written unless only included files were typed in.
    const bool writes_scene = !has_included_drafts(state.editor) || has_unsaved_edits(state.doc);
    if (state.doc.loaded && writes_scene && file_changed_on_disk(state.doc, what)) {
        state.files.save_conflict = state.doc.path.filename().string() + " " + what +
                                    " since it was loaded; saving would replace that";
        state.files.save_conflict_drafts.clear();
        state.message = "Scene not saved: " + state.files.save_conflict;
        return false;
    }
    if (const std::string conflict = included_draft_conflict(state.doc, state.editor);
        !conflict.empty()) {
        state.files.save_conflict = conflict + "; saving would replace that";
        state.files.save_conflict_drafts = conflicting_drafts(state.doc, state.editor);
        state.message = "Not saved: " + state.files.save_conflict;
        return false;
    }
    return save_now(state);
}

bool save_scene_anyway(AppState& state) {
    return save_now(state);
}

void revert_conflicting_drafts(AppState& state) {
    std::vector<std::string> names;
    for (const std::string& canonical : state.files.save_conflict_drafts) {
        if (const IncludedDraft* d = draft_of(state.editor, canonical)) names.push_back(d->name);
        revert_included_draft(state.editor, canonical);
    }
    state.files.save_conflict.clear();
    state.files.save_conflict_drafts.clear();
    // The scene already reads those files as they are on disk (the watcher
    // reloaded it): a draft is taken in only by a save.
    if (!names.empty())
        state.message = "Dropped what you typed in " + listed_names(names) +
                        ": the scene reads it as it is on disk";
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

std::filesystem::path beside_scene(const SceneDocument& doc, const std::filesystem::path& typed) {
    // A name typed beside the scene's own path means a file beside the scene
    // (where its includes and images are found), not one in whatever folder
    // the viewer was started from.
    if (!typed.is_relative()) return typed;
    std::error_code ec;
    const std::filesystem::path path =
        std::filesystem::absolute(doc.path.parent_path() / typed, ec);
    return ec ? doc.path.parent_path() / typed : path;
}

bool save_scene_as(AppState& state, const std::filesystem::path& asked, bool replace) {
    state.files.save_as_conflict.clear();
    if (!state.doc.loaded) {
        state.message = "Scene not saved: no scene is open";
        return false;
    }
    // Made absolute, so that the name kept for "Replace it" is not read
    // against the folder a second time.
    const std::filesystem::path path = beside_scene(state.doc, asked);
    std::error_code ec;
    if (!replace && std::filesystem::exists(path, ec)) {
        state.files.save_as_conflict = path.string();
        state.message = "Scene not saved: " + path.string() + " exists";
        return false;
    }
    const Expected<std::vector<std::string>> saved = save_scene_copy(state.doc, path);
    if (!saved) {
        state.message = "Scene not saved: " + saved.error().message;
        return false;
    }
    state.files.watcher = FileWatcher(state.config.watch_interval);
    state.files.watcher.watch(path);
    state.files.include_watcher.acknowledge();  // values edited in included files were written
    state.check.checked_revision.reset();
    state.files.save_conflict.clear();
    state.files.pending_reload.reset();
    state.files.recent.add(path);
    state.fields.open_path_input = path.string();
    state.message.claim_saved("Saved " + (saved->empty() ? path.string() : listed_names(*saved)));
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
    if (!has_unsaved_work(state)) {
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

void open_typed_path(AppState& state) {
    if (state.fields.open_path_input.empty()) return;
    request_open_guarded(state, beside_scene(state.doc, state.fields.open_path_input));
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

}  // namespace jt::view
