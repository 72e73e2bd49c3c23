#include "app/key_taps.hpp"

#include <algorithm>

namespace jt::view {

namespace {

// GLFW's codes: keys below 256 type characters; from 340 they are modifiers
// (Shift, Ctrl, Alt, Super, left and right) and Menu.
constexpr int kFirstNonCharacterKey = 256;
constexpr int kFirstModifierKey = 340;
constexpr int kLastModifierKey = 347;                    // GLFW_KEY_RIGHT_SUPER; 348 is Menu
constexpr int kShortcutMods = 0x0002 | 0x0004 | 0x0008;  // GLFW_MOD_CONTROL, _ALT, _SUPER

bool is_modifier(int key) {
    return key >= kFirstModifierKey && key <= kLastModifierKey;
}

bool holds(const std::vector<int>& keys, int key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// Mouse buttons among the keys changed: above every GLFW key code.
constexpr int kFirstMouseButton = 1000;

}  // namespace

// A key repeat (GLFW_REPEAT) changes nothing ImGui reads: it always fits.
bool KeyTaps::fits_this_frame(const KeyEvent& event) const {
    if (event.wheel) return !mouse_placed_ || (event.x == mouse_x_ && event.y == mouse_y_);
    if (event.mouse_button >= 0)
        return !typed_ && !wheeled_ && !holds(changed_, kFirstMouseButton + event.mouse_button);
    if (event.codepoint != 0) return !editing_key_pressed_ && !mouse_changed_ && !wheeled_;
    const bool changes_key = event.action == press_ || event.action == release_;
    if (!changes_key) return true;
    if (mouse_changed_ || wheeled_) return false;
    if (is_modifier(event.key) && key_pressed_) return false;
    return !holds(changed_, event.key);
}

void KeyTaps::pass(const KeyEvent& event, const Sink& sink) {
    if (event.wheel || event.mouse_button >= 0) {
        if (event.wheel) {
            wheeled_ = true;
        } else {
            changed_.push_back(kFirstMouseButton + event.mouse_button);
            mouse_changed_ = true;
        }
        mouse_placed_ = true;
        mouse_x_ = event.x;
        mouse_y_ = event.y;
        sink(event);
        return;
    }
    if (event.codepoint != 0) typed_ = true;
    if (event.codepoint == 0 && (event.action == press_ || event.action == release_))
        changed_.push_back(event.key);
    if (event.codepoint == 0 && event.action == press_ && !is_modifier(event.key))
        key_pressed_ = typed_ = true;
    if (event.codepoint == 0 && event.action != release_) {
        const bool editing = event.key >= kFirstNonCharacterKey && event.key < kFirstModifierKey;
        if (editing || (event.mods & kShortcutMods) != 0) editing_key_pressed_ = true;
    }
    sink(event);
}

void KeyTaps::pass_what_fits(const Sink& sink) {
    while (!held_.empty() && fits_this_frame(held_.front())) {
        const KeyEvent event = held_.front();
        held_.pop_front();
        pass(event, sink);
    }
}

void KeyTaps::event(const KeyEvent& event, const Sink& sink) {
    held_.push_back(event);
    pass_what_fits(sink);
}

void KeyTaps::frame_done(const Sink& sink) {
    changed_.clear();
    editing_key_pressed_ = false;
    key_pressed_ = false;
    typed_ = false;
    mouse_changed_ = false;
    wheeled_ = false;
    mouse_placed_ = false;
    pass_what_fits(sink);
}

}  // namespace jt::view
