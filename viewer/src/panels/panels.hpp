#pragma once
// The viewer's panels. Each draws its part of the sidebar (or the status line)
// for one frame and edits AppState through app_actions.hpp.

#include "app_state.hpp"

namespace jt::view {

void file_panel(AppState& state);
void camera_panel(AppState& state);
void settings_panel(AppState& state);
void objects_panel(AppState& state);  // every primitive: shape, material, transform
void lights_panel(AppState& state);
void diagnostics_panel(AppState& state);
void help_panel();
void status_line(AppState& state);

// Parts of objects_panel, one primitive at a time.
void material_editor(Material& material);
void transform_editor(std::vector<TransformOp>& transforms);

// "pass 3/7 (1 sample) | 4/16 samples | 1.2 s | 3.4 Mrays/s"
std::string render_status(const AppState& state);

}  // namespace jt::view
