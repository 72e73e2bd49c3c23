#include "ui_items.hpp"

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

void note_item(const char* label, bool has_tooltip) {
    if (!collecting) return;
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    UiItem item;
    item.label = label;
    item.rect = {min.x, min.y, max.x, max.y};
    item.enabled = (GImGui->CurrentItemFlags & ImGuiItemFlags_Disabled) == 0;
    item.has_tooltip = has_tooltip;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    item.clipped = max.x > right + 0.5f;
    collecting->push_back(std::move(item));
}

const UiItem* find_item(const std::vector<UiItem>& items, const std::string& label) {
    for (const UiItem& item : items)
        if (item.label == label) return &item;
    return nullptr;
}

}  // namespace jt::view
