#pragma once
// The keys that act on the selected object or light, as in Blender and most
// editors: Delete or X deletes it, Ctrl+D or Shift+D duplicates it, the
// period key (or the keypad's) frames it (selection_commands.hpp).

#include "model/app_state.hpp"

namespace jt::view {

// Once a frame, when no text field has the keyboard.
void selection_keys(AppState& state);

}  // namespace jt::view
