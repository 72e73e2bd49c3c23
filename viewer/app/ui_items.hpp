#pragma once
// What the last frame drew where: every labelled control with its rectangle,
// whether it was enabled, whether it had a tooltip and whether it ran past
// its window's edge. The tests and the monkey click controls by label, and
// check that nothing is clipped and every disabled control says why.

#include "model/image_layout.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace jt::view {

struct UiItem {
    std::string label;
    ScreenRect rect;
    bool enabled = true;
    bool has_tooltip = false;
    bool clipped = false;  // its right edge is past the visible part of its window
    // Its window was drawn: a window that sizes itself to its contents is
    // hidden in the frame that measures them, its items not yet in place.
    bool drawn = true;
};

// A frame's items. Their storage stays from one frame to the next and a label
// is copied into the string that held the same item last frame, so a frame
// like the last one records its items without allocating.
struct UiItems {
    std::vector<UiItem> slots;  // slots[count...] are kept for the next frame
    std::size_t count = 0;
    const UiItem* begin() const { return slots.data(); }
    const UiItem* end() const { return slots.data() + count; }
    std::size_t size() const { return count; }
    bool empty() const { return count == 0; }
    const UiItem& operator[](std::size_t i) const { return slots[i]; }
};

// Items are collected into `items` until the next call (nullptr: collect none).
// viewer_frame starts each frame with the frame's list.
void collect_ui_items(UiItems* items);

// Records the last ImGui item under `label`.
void note_item(const char* label, bool has_tooltip);

// Records the current ImGui window (its whole rectangle) under `label`.
void note_window(const char* label);

// The item of `items` called `label`, or nullptr.
const UiItem* find_item(const UiItems& items, std::string_view label);

}  // namespace jt::view
