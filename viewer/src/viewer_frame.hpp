#pragma once
// One frame of the viewer: input, panels, render progress, the image. Runs in
// whatever GL context is current, between ImGuiLayer::begin_frame and
// end_frame, so a GLFW window and an OSMesa buffer show the same thing.

#include "app_state.hpp"

#include <string>

namespace jt::view {

struct FrameInfo {
    float framebuffer_scale = 1.0f;  // framebuffer pixels per window unit (HiDPI)
};

void viewer_frame(AppState& state, const FrameInfo& info);

// The window title: file name, unsaved mark, render progress.
std::string window_title(const AppState& state);

}  // namespace jt::view
