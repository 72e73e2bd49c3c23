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
    // A key held over a frame is released at once (after a frame in which
    // it did not change: the release just passed is that frame's change).
    taps.frame_done(sink);
    passed.clear();
    taps.event({z, 0, press, 0}, sink);
    taps.frame_done(sink);
    taps.event({z, 0, release, 0}, sink);
    ASSERT_EQ(passed.size(), 2u);
    EXPECT_EQ(passed[1].action, release);
    taps.frame_done(sink);
    EXPECT_EQ(passed.size(), 2u) << "nothing held back";
}

// Three Backspaces within one frame delete three characters: one a frame, in
// order, while the other keys go on as they come.
TEST(KeyTaps, EachKeyChangesAtMostOnceAFrame) {
    constexpr int press = 1, release = 0, repeat = 2, backspace = 259, a = 65;
    KeyTaps taps(press, release);
    std::vector<KeyEvent> passed;
    const KeyTaps::Sink sink = [&](const KeyEvent& e) { passed.push_back(e); };
    for (int i = 0; i < 3; ++i) {
        taps.event({backspace, 0, press, 0}, sink);
        taps.event({backspace, 0, release, 0}, sink);
    }
    taps.event({a, 0, press, 0}, sink);
    ASSERT_EQ(passed.size(), 2u);
    EXPECT_EQ(passed[0].action, press);
    EXPECT_EQ(passed[1].key, a) << "another key is not held back";
    // Frame by frame: release, press, release, press, release.
    const int expected[] = {release, press, release, press, release};
    for (int action : expected) {
        passed.clear();
        taps.frame_done(sink);
        ASSERT_EQ(passed.size(), 1u);
        EXPECT_EQ(passed[0].key, backspace);
        EXPECT_EQ(passed[0].action, action);
    }
    passed.clear();
    taps.frame_done(sink);
    EXPECT_TRUE(passed.empty());
    // A held-down key's repeats pass at once.
    taps.event({backspace, 0, press, 0}, sink);
    taps.event({backspace, 0, repeat, 0}, sink);
    taps.event({backspace, 0, repeat, 0}, sink);
    EXPECT_EQ(passed.size(), 3u);
}

}  // namespace
}  // namespace jt::view
