#pragma once
// Lets ImGui 1.86 see every key tap, and typing in the order it was typed.
// ImGui reads a key as "down at the start of the frame": a key pressed and
// released between two frames (a tap while a frame renders, or two events in
// one batch) was never seen down, and its shortcut (Ctrl+Z, Esc, Space) was
// lost; three Backspaces typed within one slow frame deleted one character.
// And a text field takes the frame's typed characters before its keys: in
// `877|`, Backspace x3 then "123" in one frame gave "871". So the events wait
// in one queue, in order, and each frame takes them from its front while
//   - each key changes (is pressed or let go) at most once a frame,
//   - a modifier (Shift, Ctrl, Alt, Super) changes in no frame in which
//     another key was pressed before it: Ctrl let go just after Z (a quick
//     chord) would leave the frame seeing Z without Ctrl, and Ctrl pressed
//     just after Q would make a typed Q the shortcut Ctrl+Q, and
//   - a character comes in no frame in which an editing key (Backspace,
//     Delete, Enter, an arrow...: a key that is no character or modifier) or
//     a shortcut (a key with Ctrl, Alt or Super) was pressed before it.
// Mouse buttons go through the same queue, or a click made after typing
// overtakes the typing held back: on a slow frame, a path typed into a field
// and then a click on Open lost the characters after the click to the
// image's shortcuts (X deleted the selection, S saved an image, T closed
// the text editor). So
//   - a button changes at most once a frame, like a key,
//   - a button changes in no frame in which a key was pressed or a
//     character typed before it (the field typed in takes them first), and
//   - a key changes, and a character comes, in no frame in which a button
//     changed before it (the click moves the focus first).
// The frame that takes a button's change sees the mouse where it was then
// (KeyEvent::x, y), so that a click held back lands where it was made.
// The mouse wheel goes through the queue too: turned past Ctrl held back, it
// dollied the camera instead of zooming the image, and turned before Ctrl was
// let go, it zoomed after the release. ImGui reads one sum of the wheel a
// frame, at one mouse position, with the keys as they are then, so
//   - a wheel turn comes in no frame in which a button changed, or the
//     wheel turned, at another place before it (the frame sees the mouse
//     where it was turned), and
//   - no key, character or button comes in a frame in which the wheel
//     turned before it (the turn is seen with the keys of its time).

#include <deque>
#include <functional>
#include <vector>

namespace jt::view {

// A key event (key, scancode, action, mods as GLFW passes them), when
// `codepoint` is not 0 a typed character, when `mouse_button` is not -1
// a mouse button's press or release (`action`) with the mouse at (x, y), and
// when `wheel` a turn of the mouse wheel by (scroll_x, scroll_y) with the
// mouse at (x, y).
struct KeyEvent {
    int key = 0, scancode = 0, action = 0, mods = 0;
    unsigned codepoint = 0;
    int mouse_button = -1;
    float x = 0.0f, y = 0.0f;
    bool wheel = false;
    float scroll_x = 0.0f, scroll_y = 0.0f;
};

inline KeyEvent typed_character(unsigned codepoint) {
    KeyEvent e;
    e.codepoint = codepoint;
    return e;
}

inline KeyEvent mouse_button_event(int button, int action, float x, float y) {
    KeyEvent e;
    e.mouse_button = button;
    e.action = action;
    e.x = x;
    e.y = y;
    return e;
}

inline KeyEvent wheel_event(float scroll_x, float scroll_y, float x, float y) {
    KeyEvent e;
    e.wheel = true;
    e.scroll_x = scroll_x;
    e.scroll_y = scroll_y;
    e.x = x;
    e.y = y;
    return e;
}

class KeyTaps {
  public:
    using Sink = std::function<void(const KeyEvent&)>;
    // `press` and `release`: the platform's action codes (GLFW_PRESS, GLFW_RELEASE).
    KeyTaps(int press, int release) : press_(press), release_(release) {}

    // Passes `event` on to `sink` now, or holds it back behind the events
    // that wait, or because this frame cannot take it (see above).
    void event(const KeyEvent& event, const Sink& sink);
    // After each frame: passes on, in order, the held-back events the frame
    // to come can take.
    void frame_done(const Sink& sink);
    // Events wait for a frame: the frame loop must not sleep.
    bool holding() const { return !held_.empty(); }

  private:
    bool fits_this_frame(const KeyEvent& event) const;
    void pass(const KeyEvent& event, const Sink& sink);
    void pass_what_fits(const Sink& sink);

    int press_, release_;
    std::vector<int> changed_;          // keys pressed or released since the last frame
    bool editing_key_pressed_ = false;  // since the last frame
    bool key_pressed_ = false;          // a key other than a modifier, since the last frame
    bool typed_ = false;                // a key other than a modifier, or a character, since then
    bool mouse_changed_ = false;        // a mouse button, since the last frame
    bool wheeled_ = false;              // the wheel turned, since the last frame
    // Where the mouse is for the frame to come: a button changed or the wheel
    // turned there since the last frame.
    bool mouse_placed_ = false;
    float mouse_x_ = 0.0f, mouse_y_ = 0.0f;
    std::deque<KeyEvent> held_;
};

}  // namespace jt::view
