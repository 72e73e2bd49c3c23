#include "app/ui_items.hpp"

#include <imgui.h>
#include <imgui_internal.h>

namespace jt::view {

namespace {
std::vector<UiItem>* collecting = nullptr;  // like ImGui's own context: one per frame loop
}

void collect_ui_items(std::vector<UiItem>* items) {
    collecting = items;
    if (collecting) collecting->clear();
}

void note_window(const char* label) {
    if (!collecting) return;
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    UiItem item;
    item.label = label;
    item.rect = {pos.x, pos.y, pos.x + size.x, pos.y + size.y};
    collecting->push_back(std::move(item));
}

void note_item(const char* label, bool has_tooltip) {
    if (!collecting) return;
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    UiItem item;
    item.label = label;
    item.rect = {min.x, min.y, max.x, max.y};
    item.enabled = (GImGui->CurrentItemFlags & ImGuiItemFlags_Disabled) == 0;
    item.has_tooltip = has_tooltip;
    // What ImGui clips the window's contents to.
    item.clipped = max.x > GImGui->CurrentWindow->InnerClipRect.Max.x + 0.5f;
    collecting->push_back(std::move(item));
}

const UiItem* find_item(const std::vector<UiItem>& items, const std::string& label) {
    for (const UiItem& item : items)
        if (item.label == label) return &item;
    return nullptr;
}

}  // namespace jt::view
