#pragma once
// Where the text editor's cursor goes when the app replaces the text under it
// (an undo, a redo, a panel edit): beside the change, not at its old byte
// offset, which in the new text may be inside another line or a number.

#include <string_view>

namespace jt::view {

// The cursor `cursor` (a byte offset into `before`) in `after`: kept when it
// is before the changed span, moved with the text after it, and put at the
// end of the new span when it was inside the old one, or when the change
// inserts text where it stands.
int cursor_after_replace(std::string_view before, std::string_view after, int cursor);

}  // namespace jt::view
