// The window's key events reach ImGui through KeyTaps, so that a key tapped
// between two frames is still seen.

#include "app/key_taps.hpp"

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

// Ctrl held over a frame, then Z pressed and Ctrl let go before the next one
// (a quick chord: Ctrl comes up before Z, as xdotool and fast hands send it):
// the frame must see Z down with Ctrl still down, or Ctrl+Z is lost (and
// Ctrl pressed just after a letter must not turn that letter into a shortcut).
TEST(KeyTaps, AModifierChangesInNoFrameWhoseKeyWasPressedBeforeIt) {
    constexpr int press = 1, release = 0, ctrl = 341, z = 90, q = 81;
    constexpr int ctrl_mod = 0x0002;
    KeyTaps taps(press, release);
    std::vector<KeyEvent> passed;
    const KeyTaps::Sink sink = [&](const KeyEvent& e) { passed.push_back(e); };
    taps.event({ctrl, 0, press, 0}, sink);
    taps.frame_done(sink);
    passed.clear();
    taps.event({z, 0, press, ctrl_mod}, sink);
    taps.event({ctrl, 0, release, ctrl_mod}, sink);
    taps.event({z, 0, release, 0}, sink);
    ASSERT_EQ(passed.size(), 1u) << "Ctrl's release waits for the frame that sees Z";
    EXPECT_EQ(passed[0].key, z);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 3u);
    EXPECT_EQ(passed[1].key, ctrl);
    EXPECT_EQ(passed[1].action, release);
    EXPECT_EQ(passed[2].key, z);
    EXPECT_EQ(passed[2].action, release);
    taps.frame_done(sink);
    passed.clear();

    // Q typed, then Ctrl pressed within the same frame: that frame is no Ctrl+Q.
    taps.event({q, 0, press, 0}, sink);
    taps.event({ctrl, 0, press, 0}, sink);
    ASSERT_EQ(passed.size(), 1u);
    EXPECT_EQ(passed[0].key, q);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 2u);
    EXPECT_EQ(passed[1].key, ctrl);
}

// Three Backspaces within one frame delete three characters: one a frame, in
// order, and what was typed after them waits its turn.
TEST(KeyTaps, EachKeyChangesAtMostOnceAFrameAndLaterEventsWait) {
    constexpr int press = 1, release = 0, repeat = 2, backspace = 259, a = 65;
    KeyTaps taps(press, release);
    std::vector<KeyEvent> passed;
    const KeyTaps::Sink sink = [&](const KeyEvent& e) { passed.push_back(e); };
    for (int i = 0; i < 3; ++i) {
        taps.event({backspace, 0, press, 0}, sink);
        taps.event({backspace, 0, release, 0}, sink);
    }
    taps.event({a, 0, press, 0}, sink);
    ASSERT_EQ(passed.size(), 1u);
    EXPECT_EQ(passed[0].action, press);
    EXPECT_TRUE(taps.holding());
    // Frame by frame: release, press, release, press, release (and A's press with it).
    const int expected[] = {release, press, release, press, release};
    for (int action : expected) {
        passed.clear();
        taps.frame_done(sink);
        ASSERT_GE(passed.size(), 1u);
        EXPECT_EQ(passed[0].key, backspace);
        EXPECT_EQ(passed[0].action, action);
    }
    ASSERT_EQ(passed.size(), 2u);
    EXPECT_EQ(passed[1].key, a) << "another key after the last Backspace, in its frame";
    EXPECT_FALSE(taps.holding());
    passed.clear();
    taps.frame_done(sink);
    EXPECT_TRUE(passed.empty());
    // A held-down key's repeats pass at once.
    taps.event({backspace, 0, press, 0}, sink);
    taps.event({backspace, 0, repeat, 0}, sink);
    taps.event({backspace, 0, repeat, 0}, sink);
    EXPECT_EQ(passed.size(), 3u);
}

// A text field takes the characters of a frame before its keys: a character
// typed after Backspace (or a shortcut such as Ctrl+V) waits for the next
// frame; one typed after a letter's own key does not.
TEST(KeyTaps, ACharacterAfterAnEditingKeyWaitsForTheNextFrame) {
    constexpr int press = 1, release = 0, backspace = 259, one = '1', v = 'V', ctrl = 341;
    KeyTaps taps(press, release);
    std::vector<KeyEvent> passed;
    const KeyTaps::Sink sink = [&](const KeyEvent& e) { passed.push_back(e); };
    taps.event({one, 0, press, 0}, sink);
    taps.event(typed_character('1'), sink);
    EXPECT_EQ(passed.size(), 2u) << "a letter's key and its character go together";
    taps.event({one, 0, release, 0}, sink);
    taps.frame_done(sink);
    passed.clear();

    taps.event({backspace, 0, press, 0}, sink);
    taps.event(typed_character('2'), sink);
    taps.event({backspace, 0, release, 0}, sink);
    ASSERT_EQ(passed.size(), 1u);
    EXPECT_EQ(passed[0].key, backspace);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 3u);
    EXPECT_EQ(passed[1].codepoint, '2');
    EXPECT_EQ(passed[2].action, release);
    taps.frame_done(sink);
    passed.clear();

    constexpr int ctrl_mod = 0x0002;
    taps.event({ctrl, 0, press, ctrl_mod}, sink);
    taps.event({v, 0, press, ctrl_mod}, sink);
    taps.event(typed_character('3'), sink);
    EXPECT_EQ(passed.size(), 2u) << "after Ctrl+V (a paste), the character waits";
    taps.frame_done(sink);
    EXPECT_EQ(passed.size(), 3u);
    EXPECT_EQ(passed[2].codepoint, '3');
}

// A click made after typing waits for the typing held back before it: the
// field typed in takes its characters in a frame before the click moves the
// focus, and what is typed after the click waits for the frame after it.
TEST(KeyTaps, AMouseButtonKeepsItsPlaceAmongTheKeys) {
    constexpr int press = 1, release = 0, a = 'A', ctrl = 341, left = 0;
    KeyTaps taps(press, release);
    std::vector<KeyEvent> passed;
    const KeyTaps::Sink sink = [&](const KeyEvent& e) { passed.push_back(e); };
    // A typed twice in one frame: the second A waits a frame, and the click after it too.
    for (int i = 0; i < 2; ++i) {
        taps.event({a, 0, press, 0}, sink);
        taps.event(typed_character('a'), sink);
        taps.event({a, 0, release, 0}, sink);
    }
    taps.event(mouse_button_event(left, press, 10, 20), sink);
    taps.event(mouse_button_event(left, release, 11, 21), sink);
    taps.event({a, 0, press, 0}, sink);
    taps.event(typed_character('a'), sink);
    ASSERT_EQ(passed.size(), 2u) << "the first A's key and character";
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 3u) << "its release: the second A waits for the next frame";
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 5u) << "the second A's key and character";
    EXPECT_EQ(passed[4].codepoint, unsigned('a'));
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 7u) << "its release, then the press: a frame without typing";
    EXPECT_EQ(passed[5].key, a);
    EXPECT_EQ(passed[6].mouse_button, left);
    EXPECT_EQ(passed[6].action, press);
    EXPECT_EQ(passed[6].x, 10.0f) << "where the press was made";
    EXPECT_EQ(passed[6].y, 20.0f);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 8u) << "the release alone: the A after it waits for the next frame";
    EXPECT_EQ(passed[7].mouse_button, left);
    EXPECT_EQ(passed[7].action, release);
    EXPECT_EQ(passed[7].x, 11.0f);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 10u) << "the A typed after the click";
    EXPECT_EQ(passed[9].codepoint, unsigned('a'));
    EXPECT_FALSE(taps.holding());

    // Ctrl pressed before a click goes with it (a Ctrl+click); pressed after
    // it, it waits (the click is no Ctrl+click).
    taps.frame_done(sink);
    passed.clear();
    taps.event({ctrl, 0, press, 0}, sink);
    taps.event(mouse_button_event(left, press, 0, 0), sink);
    EXPECT_EQ(passed.size(), 2u);
    taps.event({ctrl, 0, release, 0}, sink);
    EXPECT_EQ(passed.size(), 2u);
    taps.frame_done(sink);
    EXPECT_EQ(passed.size(), 3u);
}

// The wheel keeps its place among the keys and buttons: a turn made after
// Ctrl (a zoom) is not seen before Ctrl is, nor Ctrl let go after a turn
// seen with the turn; turns at one place add up in a frame, and one at
// another place waits for the frame that sees the mouse there.
TEST(KeyTaps, TheWheelKeepsItsPlaceAmongTheKeysAndButtons) {
    constexpr int press = 1, release = 0, ctrl = 341, a = 'A', left = 0;
    KeyTaps taps(press, release);
    std::vector<KeyEvent> passed;
    const KeyTaps::Sink sink = [&](const KeyEvent& e) { passed.push_back(e); };
    // A click, then Ctrl and a turn, in one frame: Ctrl waits for the frame
    // after the click, and the turn with it.
    taps.event(mouse_button_event(left, press, 10, 20), sink);
    taps.event({ctrl, 0, press, 0}, sink);
    taps.event(wheel_event(0, 1, 10, 20), sink);
    ASSERT_EQ(passed.size(), 1u) << "the turn waits behind Ctrl";
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 3u);
    EXPECT_EQ(passed[1].key, ctrl);
    EXPECT_TRUE(passed[2].wheel);
    EXPECT_EQ(passed[2].scroll_y, 1.0f);
    EXPECT_EQ(passed[2].x, 10.0f);
    // Ctrl let go and A pressed after a turn: the frame of the turn sees Ctrl down.
    taps.event({ctrl, 0, release, 0}, sink);
    taps.event({a, 0, press, 0}, sink);
    EXPECT_EQ(passed.size(), 3u);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 5u);
    EXPECT_EQ(passed[3].key, ctrl);
    EXPECT_EQ(passed[4].key, a);
    taps.event({a, 0, release, 0}, sink);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 6u);
    taps.frame_done(sink);
    passed.clear();

    // Three turns at one place in a frame add up; one at another place waits.
    taps.event(wheel_event(0, 1, 30, 40), sink);
    taps.event(wheel_event(0, 1, 30, 40), sink);
    taps.event(wheel_event(0, -1, 31, 40), sink);
    taps.event(wheel_event(0, 1, 30, 40), sink);
    ASSERT_EQ(passed.size(), 2u);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 3u);
    EXPECT_EQ(passed[2].x, 31.0f);
    taps.frame_done(sink);
    ASSERT_EQ(passed.size(), 4u) << "the last turn, back at the first place";
    EXPECT_FALSE(taps.holding());
}

}  // namespace
}  // namespace jt::view
