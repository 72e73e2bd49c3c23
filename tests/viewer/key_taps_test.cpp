// The window's key events reach ImGui through KeyTaps, so that a key tapped
// between two frames is still seen.

#include "key_taps.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace jt::view {
namespace {

// A key pressed and released between two frames is seen down for one frame.
TEST(KeyTaps, AReleaseInTheFrameOfItsPressWaitsForTheFrame) {
    constexpr int press = 1, release = 0, ctrl = 341, z = 90;
    KeyTaps taps(press, release);
    std::vector<KeyEvent> passed;
    const KeyTaps::Sink sink = [&](const KeyEvent& e) { passed.push_back(e); };
    // Ctrl+Z tapped within one frame: both presses now, both releases after it.
    for (auto [key, action] : {std::pair{ctrl, press}, {z, press}, {z, release}, {ctrl, release}})
        taps.event({key, 0, action, 0}, sink);
    ASSERT_EQ(passed.size(), 2u);
    EXPECT_EQ(passed[0].key, ctrl);
    EXPECT_EQ(passed[1].key, z);
    EXPECT_EQ(passed[1].action, press);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 4u);
    EXPECT_EQ(passed[2].key, z);
    EXPECT_EQ(passed[2].action, release);
    EXPECT_EQ(passed[3].key, ctrl);
    EXPECT_EQ(passed[3].action, release);
    // A key held over a frame is released at once.
    passed.clear();
    taps.event({z, 0, press, 0}, sink);
    taps.frame_done(sink);
    taps.event({z, 0, release, 0}, sink);
    ASSERT_EQ(passed.size(), 2u);
    EXPECT_EQ(passed[1].action, release);
    taps.frame_done(sink);
    EXPECT_EQ(passed.size(), 2u) << "nothing held back";
}

}  // namespace
}  // namespace jt::view
