#include "panels/panels.hpp"
#include "panels/widgets.hpp"

#include <imgui.h>

namespace jt::view {

void settings_panel(AppState& state) {
    if (!ImGui::CollapsingHeader("Render settings", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::BeginDisabled(!state.doc.loaded);
    RenderSettings& s = state.doc.scene.settings;
    edit_int("width", s.width, 1, 8192);
    edit_int("height", s.height, 1, 8192);
    edit_int("recurse_depth", s.recurse_depth, 0, 256);
    edit_int("samples", s.samples, 1, 1024);
    edit_colour("background", s.background);
    edit_colour("ambient_light", s.ambient_light);
    ImGui::EndDisabled();
}

}  // namespace jt::view
