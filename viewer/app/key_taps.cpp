#include "key_taps.hpp"

#include <algorithm>
#include <utility>

namespace jt::view {

namespace {

bool holds(const std::vector<int>& keys, int key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

// A key repeat (GLFW_REPEAT) changes nothing ImGui reads and is never held.
bool KeyTaps::changes_key(const KeyEvent& event) const {
    return event.action == press_ || event.action == release_;
}

void KeyTaps::pass(const KeyEvent& event, const Sink& sink) {
    if (changes_key(event)) changed_.push_back(event.key);
    sink(event);
}

void KeyTaps::event(const KeyEvent& event, const Sink& sink) {
    const bool earlier_held = std::any_of(held_.begin(), held_.end(),
                                          [&](const KeyEvent& e) { return e.key == event.key; });
    if (earlier_held || (changes_key(event) && holds(changed_, event.key))) {
        held_.push_back(event);
        return;
    }
    pass(event, sink);
}

void KeyTaps::frame_done(const Sink& sink) {
    changed_.clear();
    std::vector<KeyEvent> waiting = std::exchange(held_, {});
    std::vector<int> still_held;  // keys with an earlier event still waiting
    for (const KeyEvent& event : waiting) {
        if (holds(still_held, event.key) || (changes_key(event) && holds(changed_, event.key))) {
            held_.push_back(event);
            still_held.push_back(event.key);
            continue;
        }
        pass(event, sink);
    }
}

}  // namespace jt::view
