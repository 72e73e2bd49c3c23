#include "model/edit_commands.hpp"

#include "model/app_actions.hpp"

#include "jtracer/validate.hpp"
#include "model/object_drag.hpp"

#include <chrono>

namespace jt::view {

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

}  // namespace jt::view
