#pragma once
// Edits and their history: checking the edited scene, scripted edits, undo
// and redo, and how a frame tells a panel edit (one undo step per continuous
// edit) from a command's.

#include "model/app_state.hpp"

#include <cstdint>
#include <functional>

namespace jt::view {

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
// then not taken for a panel edit (EditHistory::scene_generation).
void note_command_edit(EditHistory& history, SceneDocument& doc);

// Where the document stood before a frame's widgets ran.
struct EditMark {
    std::uint64_t revision = 0;    // SceneDocument::revision
    std::uint64_t generation = 0;  // EditHistory::scene_generation
};
// Called before the frame's widgets run.
EditMark begin_edit_tracking(const EditHistory& history, const SceneDocument& doc);
// A panel calls this before it draws the fields of `block`: it keeps a copy of
// the block as it is (once per change of the scene, none on a frame with
// nothing to do), the value an edit of those fields goes back to on undo.
void settle_block(EditHistory& history, const SceneDocument& doc, EditedBlock block);
// And this when a field changed `block`: the scene changed
// (note_scene_changed), and the block's settled copy becomes the base of the
// edit in progress.
void note_block_edited(EditHistory& history, SceneDocument& doc, EditedBlock block);
// Called after the widgets, with begin_edit_tracking's mark: records one undo
// step per continuous panel edit (a whole drag is one step), when the widget
// is let go.
void track_edits(EditHistory& history, const SceneDocument& doc, EditMark before,
                 bool widget_active);

}  // namespace jt::view
