#pragma once
// What the last frame drew where: every labelled control with its rectangle,
// whether it was enabled, whether it had a tooltip and whether it ran past
// its window's edge. The tests and the monkey click controls by label, and
// check that nothing is clipped and every disabled control says why.

#include "model/image_layout.hpp"

#include <string>
#include <vector>

namespace jt::view {

struct UiItem {
    std::string label;
    ScreenRect rect;
    bool enabled = true;
    bool has_tooltip = false;
    bool clipped = false;  // its right edge is past the visible part of its window
};

// Items are collected into `items` until the next call (nullptr: collect none).
// viewer_frame starts each frame with the frame's list.
void collect_ui_items(std::vector<UiItem>* items);

// Records the last ImGui item under `label`.
void note_item(const char* label, bool has_tooltip);

// Records the current ImGui window (its whole rectangle) under `label`.
void note_window(const char* label);

// The item of `items` called `label`, or nullptr.
const UiItem* find_item(const std::vector<UiItem>& items, const std::string& label);

}  // namespace jt::view
