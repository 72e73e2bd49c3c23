#include "app/ui_items.hpp"

#include <imgui.h>
#include <imgui_internal.h>

namespace jt::view {

namespace {
UiItems* collecting = nullptr;  // like ImGui's own context: one per frame loop

// The next slot, its label `label` (assign keeps the string's storage).
UiItem& next_item(const char* label) {
    if (collecting->count == collecting->slots.size()) collecting->slots.emplace_back();
    UiItem& item = collecting->slots[collecting->count++];
    item.label.assign(label);
    return item;
}

}  // namespace

void collect_ui_items(UiItems* items) {
    collecting = items;
    if (collecting) collecting->count = 0;
}

void note_window(const char* label) {
    if (!collecting) return;
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    UiItem& item = next_item(label);
    item.rect = {pos.x, pos.y, pos.x + size.x, pos.y + size.y};
    item.enabled = true;
    item.has_tooltip = false;
    item.clipped = false;
}

void note_item(const char* label, bool has_tooltip) {
    if (!collecting) return;
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    UiItem& item = next_item(label);
    item.rect = {min.x, min.y, max.x, max.y};
    // The item's own flags too: a control disabled alone (button()) is noted
    // after its EndDisabled, when the flags in force no longer say so.
    item.enabled =
        ((GImGui->CurrentItemFlags | GImGui->LastItemData.InFlags) & ImGuiItemFlags_Disabled) == 0;
    item.has_tooltip = has_tooltip;
    // What ImGui clips the window's contents to.
    item.clipped = max.x > GImGui->CurrentWindow->InnerClipRect.Max.x + 0.5f;
    item.drawn = !GImGui->CurrentWindow->Hidden;
}

const UiItem* find_item(const UiItems& items, std::string_view label) {
    for (const UiItem& item : items)
        if (item.label == label) return &item;
    return nullptr;
}

}  // namespace jt::view
