#pragma once
// Keeps a quick key tap visible for one frame. ImGui 1.86 reads a key as
// "down at the start of the frame": a key pressed and released between two
// frames (a tap while a frame renders, or two events in one batch) was never
// seen down, and its shortcut (Ctrl+Z, Esc, Space) was lost. A release of a
// key pressed since the last frame is held back until that frame has run.

#include <functional>
#include <vector>

namespace jt::view {

struct KeyEvent {
    int key = 0, scancode = 0, action = 0, mods = 0;  // as GLFW passes them
};

class KeyTaps {
  public:
    using Sink = std::function<void(const KeyEvent&)>;
    // `press` and `release`: the platform's action codes (GLFW_PRESS, GLFW_RELEASE).
    KeyTaps(int press, int release) : press_(press), release_(release) {}

    // Passes `event` on to `sink` now, or holds it back (a release of a key
    // pressed since the last frame).
    void event(const KeyEvent& event, const Sink& sink);
    // After each frame: passes the held-back releases on.
    void frame_done(const Sink& sink);

  private:
    int press_, release_;
    std::vector<int> pressed_;  // keys pressed since the last frame
    std::vector<KeyEvent> held_;
};

}  // namespace jt::view
