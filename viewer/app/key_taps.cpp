#include "key_taps.hpp"

#include <algorithm>
#include <utility>

namespace jt::view {

void KeyTaps::event(const KeyEvent& event, const Sink& sink) {
    if (event.action == press_) pressed_.push_back(event.key);
    const bool tapped = std::find(pressed_.begin(), pressed_.end(), event.key) != pressed_.end();
    if (event.action == release_ && tapped) {
        held_.push_back(event);
        return;
    }
    sink(event);
}

void KeyTaps::frame_done(const Sink& sink) {
    pressed_.clear();
    const std::vector<KeyEvent> held = std::exchange(held_, {});
    for (const KeyEvent& event : held) sink(event);
}

}  // namespace jt::view
