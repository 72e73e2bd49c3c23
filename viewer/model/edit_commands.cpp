#include "model/edit_commands.hpp"

#include "model/app_actions.hpp"

#include "jtracer/check.hpp"
#include "jtracer/validate.hpp"
#include "model/object_drag.hpp"

#include <chrono>
#include <type_traits>
#include <variant>

namespace jt::view {

void check_edits(CheckState& check, SceneDocument& doc, const FileState& files) {
    // A failed load's diagnostics describe the file, and a pending reload's the
    // newer text: both stay until the file is fixed or the user chooses.
    if (!doc.loaded || doc.load_failed ||
        (files.pending_reload && !files.changed_on_disk.empty()) || doc.draft) {
        check.checked_revision.reset();
        return;
    }
    if (check.checked_revision == doc.revision) return;
    doc.diagnostics = doc.parse_diagnostics;
    std::vector<Diagnostic> more = validate_scene(doc.scene, doc.source);
    check.error_free_revision =
        has_errors(more) ? std::nullopt : std::optional<std::uint64_t>(doc.revision);
    doc.diagnostics.insert(doc.diagnostics.end(), more.begin(), more.end());
    doc.diagnostics_source = doc.text;
    doc.diagnostics_path = doc.path;
    doc.diagnostics_files = doc.source.files;
    note_diagnostics_changed(doc);
    check.checked_revision = doc.revision;
}

void edit_scene(AppState& state, const std::function<void(Scene&)>& change) {
    // Not a copy of the whole scene: for 100,000 objects each copy is a
    // noticeable part of the wait for the edit's first preview.
    const std::vector<Camera> cameras_before = state.doc.scene.cameras;
    const DocumentVersion version = version_of(state.doc);
    change(state.doc.scene);
    keep_camera_selection(state.view, state.doc.scene, cameras_before);
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
                                  std::chrono::milliseconds(0), state.doc.options);
    else
        state.check.checker.cancel();
}

}  // namespace

namespace {

// Moves one step through the undo history; `step` is the stack's undo or redo.
// Undo or redo during a drag that moves an object gives back the document as
// the drag found it, and nothing more: the drag is the step being undone.
template <class Step>
void step_history(AppState& state, Step step, const char* done, const char* nothing) {
    if (state.drags.object) {
        cancel_object_drag(state);
        return;
    }
    std::optional<DocumentVersion> version = step(version_of(state.doc));
    // Nothing to step to: the document stays as it is, and so does its
    // render (a change noted here would start it again).
    if (!version) {
        state.message = nothing;
        return;
    }
    const std::uint64_t revision_before = state.doc.revision;
    const Scene before = state.doc.scene;
    restore_version(state.doc, *version);
    keep_camera_selection(state.view, state.doc.scene, before);
    state.message = done;
    recheck_draft(state);
    state.history.edit_base.reset();
    note_command_edit(state.history, state.doc);
    // Typing with errors undone (or redone): the image shown is of this very scene.
    if (state.doc.scene == before)
        keep_render_for(state.render, revision_before, state.doc.revision);
}

}  // namespace

void undo(AppState& state) {
    step_history(
        state, [&](auto current) { return state.history.undo.undo(std::move(current)); }, "Undone",
        "Nothing to undo");
}

void redo(AppState& state) {
    step_history(
        state, [&](auto current) { return state.history.undo.redo(std::move(current)); }, "Redone",
        "Nothing to redo");
}

void note_command_edit(EditHistory& history, SceneDocument& doc) {
    ++history.scene_generation;
    note_scene_changed(doc);
}

namespace {

BlockCopy copy_of(const Scene& scene, EditedBlock block) {
    switch (block.kind) {
        case EditedBlock::Kind::settings:
            return {block, scene.settings};
        case EditedBlock::Kind::camera:
            return {block, scene.cameras[block.index]};
        case EditedBlock::Kind::primitive:
            return {block, scene.primitives[block.index]};
        case EditedBlock::Kind::light:
            return {block, scene.lights[block.index]};
    }
    return {block, scene.settings};
}

// The place of `copy`'s block in `scene`, as its value's type, or null when
// the scene has no such block.
template <class T>
T* place_of(Scene& scene, const BlockCopy& copy) {
    const std::size_t i = copy.block.index;
    if constexpr (std::is_same_v<T, RenderSettings>)
        return &scene.settings;
    else if constexpr (std::is_same_v<T, Camera>)
        return i < scene.cameras.size() ? &scene.cameras[i] : nullptr;
    else if constexpr (std::is_same_v<T, Primitive>)
        return i < scene.primitives.size() ? &scene.primitives[i] : nullptr;
    else
        return i < scene.lights.size() ? &scene.lights[i] : nullptr;
}

bool holds(const Scene& scene, const BlockCopy& copy) {
    return std::visit(
        [&](const auto& value) {
            using T = std::decay_t<decltype(value)>;
            const T* place = place_of<T>(const_cast<Scene&>(scene), copy);
            return place && *place == value;
        },
        copy.value);
}

void put_back(Scene& scene, const BlockCopy& copy) {
    std::visit(
        [&](const auto& value) {
            using T = std::decay_t<decltype(value)>;
            if (T* place = place_of<T>(scene, copy)) *place = value;
        },
        copy.value);
}

}  // namespace

EditMark begin_edit_tracking(const EditHistory& history, const SceneDocument& doc) {
    return {doc.revision, history.scene_generation};
}

void settle_block(EditHistory& history, const SceneDocument& doc, EditedBlock block) {
    if (history.edit_base) return;  // its base is taken; the rest waits for the step
    if (history.settled_revision != doc.revision) {
        history.settled.clear();
        history.settled_revision = doc.revision;
    }
    for (const BlockCopy& copy : history.settled)
        if (copy.block == block) return;
    history.settled.push_back(copy_of(doc.scene, block));
}

void note_block_edited(EditHistory& history, SceneDocument& doc, EditedBlock block) {
    if (!history.edit_base && history.settled_revision == doc.revision) {
        for (BlockCopy& copy : history.settled)
            if (copy.block == block) {
                history.edit_base = std::move(copy);
                break;
            }
        JT_DCHECK(history.edit_base, "a panel settles a block before drawing its fields");
        history.settled.clear();
        history.settled_revision.reset();
    }
    note_scene_changed(doc);
}

void track_edits(EditHistory& history, const SceneDocument& doc, EditMark before,
                 bool widget_active) {
    if (history.scene_generation != before.generation) {
        history.edit_base.reset();
        return;
    }
    if (widget_active || !history.edit_base) return;
    // A field touched and put back leaves no step to undo.
    if (!holds(doc.scene, *history.edit_base)) {
        Scene was = doc.scene;  // the undo stack keeps whole versions
        put_back(was, *history.edit_base);
        history.undo.record({doc.text, std::move(was), doc.draft});
    }
    history.edit_base.reset();
}

}  // namespace jt::view
