#include "app/headless.hpp"

#include "app/gl/gl.hpp"

#include "app/keys.hpp"
#include "app/viewer_frame.hpp"
#include "model/app_actions.hpp"
#include "model/model_frame.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace jt::view {

namespace {

// What the current GL context drew, rows bottom-up as in Image8.
Image8 read_framebuffer(int width, int height) {
    Image8 image(width, height);
    if (width <= 0 || height <= 0) return image;
    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // glReadPixels returns the bottom row first, which is Image8's order.
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return image;
}

}  // namespace

HeadlessViewer::HeadlessViewer(int width, int height)
    : context_(width, height),
      layer_(OsMesaContext::proc_loader()),
      key_taps_(kKeyPress, kKeyRelease) {
    // As the GLFW backend reports: the panel edge can be dragged.
    if (layer_.ok()) ImGui::GetIO().BackendFlags |= ImGuiBackendFlags_HasMouseCursors;
}

std::string HeadlessViewer::error() const {
    if (!context_.ok()) return context_.error();
    return layer_.error();
}

namespace {

// Nanoseconds this thread has waited for a core while runnable
// (/proc/thread-self/schedstat, second field); 0 when unknown.
long long run_queue_wait_ns() {
    std::FILE* f = std::fopen("/proc/thread-self/schedstat", "r");
    if (!f) return 0;
    long long running = 0, waiting = 0;
    const int n = std::fscanf(f, "%lld %lld", &running, &waiting);
    std::fclose(f);
    return n == 2 ? waiting : 0;
}

// What the GLFW backend does with a key event, a character or a wheel turn,
// and the window's loop with a mouse button (main.cpp: the mouse where it
// changed or turned).
void key_to_imgui(const KeyEvent& e) {
    ImGuiIO& io = ImGui::GetIO();
    if (e.wheel) {
        io.MouseWheelH += e.scroll_x;
        io.MouseWheel += e.scroll_y;
        io.MousePos = ImVec2(e.x, e.y);
        return;
    }
    if (e.mouse_button >= 0) {
        if (e.mouse_button >= ImGuiMouseButton_COUNT) return;
        io.MouseDown[e.mouse_button] = e.action == kKeyPress;
        io.MousePos = ImVec2(e.x, e.y);
        return;
    }
    if (e.codepoint != 0) {
        io.AddInputCharacter(e.codepoint);
        return;
    }
    if (e.key < 0 || e.key >= static_cast<int>(IM_ARRAYSIZE(io.KeysDown))) return;
    if (e.action == kKeyPress) io.KeysDown[e.key] = true;
    if (e.action == kKeyRelease) io.KeysDown[e.key] = false;
    io.KeyShift = io.KeysDown[keys::left_shift] || io.KeysDown[keys::right_shift];
    io.KeyCtrl = io.KeysDown[keys::left_ctrl] || io.KeysDown[keys::right_ctrl];
    io.KeyAlt = io.KeysDown[keys::left_alt] || io.KeysDown[keys::right_alt];
}

}  // namespace

void HeadlessViewer::key_events(AppState& state, const std::vector<KeyEvent>& events,
                                double event_ms, double frame_ms) {
    // ImGui's clock as the frames' (a key held over frames repeats after its delay).
    frame_seconds_ = static_cast<float>(frame_ms / 1000.0);
    std::size_t next = 0;
    for (double now = 0.0; next < events.size() || key_taps_.holding(); now += frame_ms) {
        for (; next < events.size() && static_cast<double>(next) * event_ms <= now; ++next)
            key_taps_.event(events[next], key_to_imgui);
        frame(state);
        key_taps_.frame_done(key_to_imgui);
    }
    frame(state);
    frame_seconds_ = kFrameSeconds;
}

void HeadlessViewer::frame(AppState& state) {
    const auto start = std::chrono::steady_clock::now();
    const long long waited_before = run_queue_wait_ns();
    // Window units = framebuffer pixels / scale, as GLFW reports on a HiDPI screen.
    ImGuiLayer::set_display(static_cast<int>(context_.width() / scale_),
                            static_cast<int>(context_.height() / scale_), scale_, frame_seconds_);
    layer_.set_scale(content_scale_, scale_);
    layer_.begin_frame();
    // The frames compare the document's revision, not its scenes: a change
    // made without announcing it would never be rendered nor undone.
    std::optional<Scene> scene_before;
    if (check_revisions_) scene_before = state.doc.scene;
    const std::uint64_t revision_before = state.doc.revision;
    viewer_frame(state, frame_state_, FrameInfo{scale_});
    if (scene_before && state.doc.revision == revision_before && *scene_before != state.doc.scene) {
        std::fprintf(stderr,
                     "HeadlessViewer: a frame changed the scene without note_scene_changed: "
                     "the change would be neither rendered nor undoable\n");
        std::abort();
    }
    layer_.end_frame(context_.width(), context_.height());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    slowest_frame_ = std::max(slowest_frame_, seconds);
    const double queued = static_cast<double>(run_queue_wait_ns() - waited_before) * 1e-9;
    slowest_unqueued_frame_ = std::max(slowest_unqueued_frame_, seconds - queued);
}

void HeadlessViewer::press_key(AppState& state, int key, bool ctrl, bool shift) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    io.KeyShift = shift;
    io.KeysDown[key] = true;
    frame(state);
    io.KeysDown[key] = false;
    io.KeyCtrl = false;
    io.KeyShift = false;
    frame(state);
}

void HeadlessViewer::drag(AppState& state, int button, float x0, float y0, float x1, float y1,
                          int modifiers) {
    press_mouse(state, button, x0, y0, modifiers);
    constexpr int steps = 4;
    for (int i = 1; i <= steps; ++i) {
        const float t = static_cast<float>(i) / steps;
        move_mouse(state, x0 + (x1 - x0) * t, y0 + (y1 - y0) * t);
    }
    release_mouse(state, button);
}

void HeadlessViewer::press_mouse(AppState& state, int button, float x, float y, int modifiers) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = (modifiers & kCtrl) != 0;
    io.KeyShift = (modifiers & kShift) != 0;
    io.KeyAlt = (modifiers & kAlt) != 0;
    io.MousePos = ImVec2(x, y);
    frame(state);
    io.MouseDown[button] = true;
    frame(state);  // pressed where it is, then moved
}

void HeadlessViewer::release_mouse(AppState& state, int button) {
    ImGuiIO& io = ImGui::GetIO();
    io.MouseDown[button] = false;
    frame(state);
    io.KeyCtrl = io.KeyShift = io.KeyAlt = false;
}

bool HeadlessViewer::click(AppState& state, const std::string& label) {
    const UiItem* item = find_item(frame_state_.ui_items, label);
    // A user clicks what a frame showed: a window still measuring itself
    // shows in the next frame.
    if (item && !item->drawn) {
        frame(state);
        item = find_item(frame_state_.ui_items, label);
    }
    if (!item || !item->drawn) return false;
    const ScreenRect r = item->rect;
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2((r.x0 + r.x1) * 0.5f, (r.y0 + r.y1) * 0.5f);
    frame(state);
    io.MouseDown[0] = true;
    frame(state);
    io.MouseDown[0] = false;
    frame(state);
    return true;
}

void HeadlessViewer::move_mouse(AppState& state, float x, float y) {
    ImGui::GetIO().MousePos = ImVec2(x, y);
    frame(state);
}

void HeadlessViewer::scroll(AppState& state, float x, float y, float steps, bool ctrl) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(x, y);
    io.MouseWheel = steps;
    io.KeyCtrl = ctrl;
    frame(state);
    io.MouseWheel = 0.0f;
    io.KeyCtrl = false;
    frame(state);
}

bool HeadlessViewer::run_until_complete(AppState& state, std::chrono::milliseconds timeout,
                                        int settle_frames) {
    return run_frames_until_complete(
        state, [&] { frame(state); }, timeout, settle_frames);
}

bool HeadlessViewer::run_until_loaded(AppState& state, std::chrono::milliseconds timeout) {
    return run_frames_until_loaded(
        state, [&] { frame(state); }, timeout);
}

Image8 HeadlessViewer::screenshot() const {
    return read_framebuffer(context_.width(), context_.height());
}

}  // namespace jt::view
