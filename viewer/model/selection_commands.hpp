#pragma once
// What the keyboard does to the selected object or light (Delete/X, Ctrl+D or
// Shift+D, frame it), and where it is in the text, so that the text editor
// scrolls to the block picked in the image and a click in a block selects it.

#include "model/app_state.hpp"

#include <optional>

namespace jt::view {

// Deletes the selection's block (one undo step); false when nothing is selected.
bool delete_selection(AppState& state);
// Duplicates it right after itself and selects the copy.
bool duplicate_selection(AppState& state);
// Turns the free camera, keeping its direction, to look at the selection's
// centre from where its bounds fill about half of the view. A plane or mesh
// (no bounds known) and a light are looked at from where the camera is.
bool frame_selection(AppState& state);

// The line (from 1) of the selection's block keyword in the document's base
// text (state.doc.text), or nothing (also for a block of an included file).
std::optional<int> selection_line(const AppState& state);
// The object or light whose block holds byte `offset` of state.doc.text
// (never one of an included file).
Selection selection_at_offset(const AppState& state, std::size_t offset);

}  // namespace jt::view
