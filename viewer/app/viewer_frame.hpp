#pragma once
// One frame of the viewer: input, panels, render progress, the image. Runs in
// whatever GL context is current, between ImGuiLayer::begin_frame and
// end_frame, so a GLFW window and an OSMesa buffer show the same thing.

#include "app/panels/panels.hpp"
#include "app/presenter.hpp"
#include "app/reload_bar.hpp"
#include "app/selection_overlay.hpp"
#include "app/text_editor.hpp"
#include "app/ui_items.hpp"
#include "model/app_state.hpp"

#include <string>
#include <vector>

namespace jt::view {

struct FrameInfo {
    float framebuffer_scale = 1.0f;  // framebuffer pixels per window unit (HiDPI)
};

// What the frame code keeps between frames beside the model: the texture that
// shows state.render.display, and what the last frame drew where. Lives with the GL
// context (its texture must go before the context does).
struct FrameState {
    Presenter presenter;
    // A (split and A views) or the difference image, whichever the view shows.
    Presenter compare;
    std::uint64_t compare_holds_version = ~std::uint64_t{0};  // of state.view.compare.a
    bool compare_holds_difference = false;
    std::string compare_summary;  // of the difference shown
    SelectionOverlay overlay;
    UiItems ui_items;
    TextEditorState text_editor;
    ReloadBarState reload_bar;
    DiagnosticsText diagnostics;
    ScreenRect image_area;  // where the last frame could show the image
    ScreenRect image_rect;  // where it put it (place_image; may reach past image_area)
    // Ctrl+Q or Ctrl+S pressed while a value was being typed into a field:
    // that frame ends the typing and the panels take the value; the key acts
    // on the next frame, on the value taken. The key's code, or 0.
    int key_after_typing = 0;
};

void viewer_frame(AppState& state, FrameState& frame, const FrameInfo& info);

// The window title: file name, unsaved mark, render progress.
std::string window_title(const AppState& state);

}  // namespace jt::view
