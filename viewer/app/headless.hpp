#pragma once
// The viewer without a window: an OSMesa context, ImGui, and a frame loop that
// stops when the render is complete. Used by --screenshot and by the tests.

#include "app/gl/gl_context_osmesa.hpp"
#include "app/imgui_layer.hpp"
#include "app/key_taps.hpp"
#include "app/viewer_frame.hpp"
#include "model/app_state.hpp"

#include <chrono>
#include <string>

namespace jt::view {

// Keys held through a drag (flags).
enum DragModifier { kNoModifier = 0, kCtrl = 1, kShift = 2, kAlt = 4 };

class HeadlessViewer {
  public:
    HeadlessViewer(int width, int height);
    bool ok() const { return context_.ok() && layer_.ok(); }
    std::string error() const;

    // Draws one frame of `state` into the offscreen buffer.
    void frame(AppState& state);
    // Holds `key` down for one frame (with the modifiers), then releases it.
    void press_key(AppState& state, int key, bool ctrl = false, bool shift = false);
    // Key events, typed characters, mouse buttons (mouse_button_event) and
    // wheel turns (wheel_event) as the window's callbacks get them,
    // one every `event_ms`, while frames are drawn one every `frame_ms`
    // (simulated time: events that come during a frame reach the next one),
    // through the window's KeyTaps; then frames until none waits.
    void key_events(AppState& state, const std::vector<KeyEvent>& events, double event_ms,
                    double frame_ms);
    // Drags the mouse with `button` (0 left, 1 right, 2 middle) from one point
    // to another (window units, y down) over a few frames, as a user would:
    // pressed at the first point, moved, released at the second; `modifiers`
    // (DragModifier flags) held throughout.
    void drag(AppState& state, int button, float x0, float y0, float x1, float y1,
              int modifiers = kNoModifier);
    // The same in steps: the button pressed at (x, y) with `modifiers` held
    // (a frame before and one after the press), then moves (move_mouse), then
    // let go (a frame) and the modifiers with it.
    void press_mouse(AppState& state, int button, float x, float y, int modifiers = kNoModifier);
    void release_mouse(AppState& state, int button);
    // Clicks the control drawn under `label` in the last frame (see
    // ui_items.hpp) with the left button; false when there is none. A
    // control of a window not yet drawn (measuring itself) is clicked where
    // the next frame draws it.
    bool click(AppState& state, const std::string& label);
    // Moves the mouse to (x, y) for one frame.
    void move_mouse(AppState& state, float x, float y);
    // Turns the wheel by `steps` with the mouse at (x, y) (Ctrl held: zooms the image).
    void scroll(AppState& state, float x, float y, float steps, bool ctrl = false);
    // The reload choice's bar (the differences it shows).
    const ReloadBarState& reload_bar() const { return frame_state_.reload_bar; }
    // The text editor's state (what the editor shows, where its cursor is).
    TextEditorState& text_editor() { return frame_state_.text_editor; }
    // Runs frames until the render of the current scene is complete and shown,
    // then `settle_frames` more so the UI shows the final state. False on timeout
    // or when there is nothing to render.
    bool run_until_complete(AppState& state,
                            std::chrono::milliseconds timeout = std::chrono::minutes(10),
                            int settle_frames = 2);
    // Runs frames until no open or reload is in flight (and one more, which
    // takes the result in). False on timeout.
    bool run_until_loaded(AppState& state,
                          std::chrono::milliseconds timeout = std::chrono::minutes(2));
    // Simulates a HiDPI screen: `scale` framebuffer pixels per window unit.
    void set_framebuffer_scale(float scale) { scale_ = scale > 0 ? scale : 1.0f; }
    // Simulates the monitor's content scale (Xft.dpi 192: 2), as
    // glfwGetWindowContentScale reports it.
    void set_content_scale(float scale) { content_scale_ = scale > 0 ? scale : 1.0f; }
    // Every frame() checks that a change of the scene bumped the document's
    // revision (what the frames compare), aborting when not; off for benchmarks.
    void set_check_revisions(bool on) { check_revisions_ = on; }
    // The longest frame() so far, in seconds.
    double slowest_frame() const { return slowest_frame_; }
    // The same less the time the thread waited for a core while runnable: on a
    // machine busy with other work, this is what the viewer itself spent
    // computing or blocked waiting (the monkey test's no-hang check).
    double slowest_unqueued_frame() const { return slowest_unqueued_frame_; }
    // The last frame as drawn (rows bottom-up).
    Image8 screenshot() const;
    int width() const { return context_.width(); }
    int height() const { return context_.height(); }
    // The texture the frames draw the image from.
    const Presenter& presenter() const { return frame_state_.presenter; }
    // The texture the compare views draw A or the difference from.
    const Presenter& compare_texture() const { return frame_state_.compare; }
    // The selection as the last frame drew it over the image.
    const SelectionOverlay& overlay() const { return frame_state_.overlay; }
    // Where the last frame drew the image (zoomed and panned), and the part of
    // the window it may show in.
    ScreenRect image_rect() const { return frame_state_.image_rect; }
    ScreenRect image_area() const { return frame_state_.image_area; }
    // What the last frame drew where (ui_items.hpp).
    const UiItems& ui_items() const { return frame_state_.ui_items; }

  private:
    OsMesaContext context_;
    ImGuiLayer layer_;
    FrameState frame_state_;  // after the context: its texture goes first
    KeyTaps key_taps_;
    static constexpr float kFrameSeconds = 1.0f / 30.0f;  // ImGui's time between frames
    float frame_seconds_ = kFrameSeconds;
    float scale_ = 1.0f;
    float content_scale_ = 1.0f;
    bool check_revisions_ = true;
    double slowest_frame_ = 0.0;
    double slowest_unqueued_frame_ = 0.0;
};

}  // namespace jt::view
