#pragma once
// Lets ImGui 1.86 see every key tap. It reads a key as "down at the start of
// the frame": a key pressed and released between two frames (a tap while a
// frame renders, or two events in one batch) was never seen down, and its
// shortcut (Ctrl+Z, Esc, Space) was lost; three Backspaces typed within one
// slow frame deleted one character. So each key changes at most once a frame:
// an event that would change a key already changed since the last frame waits,
// in order, for the frames after.

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

    // Passes `event` on to `sink` now, or holds it back (its key has changed
    // since the last frame, or an earlier event of its key is held).
    void event(const KeyEvent& event, const Sink& sink);
    // After each frame: passes on, in order, the held-back events whose key
    // has not changed yet in the frame to come.
    void frame_done(const Sink& sink);

  private:
    bool changes_key(const KeyEvent& event) const;
    void pass(const KeyEvent& event, const Sink& sink);

    int press_, release_;
    std::vector<int> changed_;  // keys pressed or released since the last frame
    std::vector<KeyEvent> held_;
};

}  // namespace jt::view
