#include "app/panels/panels.hpp"
#include "app/panels/property_fields.hpp"

#include <imgui.h>

namespace jt::view {

void settings_panel(AppState& state) {
    if (!panel_header("Render settings", "Render settings", true)) return;
    ImGui::BeginDisabled(!state.doc.loaded);
    RenderSettings& s = state.doc.scene.settings;
    if (edit_properties(s)) note_scene_changed(state.doc);
    ImGui::EndDisabled();
}

}  // namespace jt::view
