// Where the text editor's cursor goes when the app replaces the text.

#include "model/text_cursor.hpp"

#include <gtest/gtest.h>

namespace jt::view {
namespace {

TEST(TextCursor, AnUndoOfTypingPutsTheCursorWhereTheTypingStarted) {
    const std::string typed = "a\n# hello\nb\n", undone = "a\n\nb\n";
    EXPECT_EQ(cursor_after_replace(typed, undone, 9), 2) << "after the typed text";
    EXPECT_EQ(cursor_after_replace(typed, undone, 5), 2) << "inside it";
    EXPECT_EQ(cursor_after_replace(typed, undone, 1), 1) << "before it: kept";
    EXPECT_EQ(cursor_after_replace(typed, undone, 11), 4) << "after it: moved with the text";
    EXPECT_EQ(cursor_after_replace(undone, typed, 2), 9) << "a redo: after the text, as typed";
    EXPECT_EQ(cursor_after_replace(undone, typed, 1), 1) << "a redo before the cursor: kept";
    EXPECT_EQ(cursor_after_replace(undone, typed, 3), 10) << "after it: moved";
}

TEST(TextCursor, AnUndoOfADeletionPutsTheCursorAfterTheTextItBringsBack) {
    EXPECT_EQ(cursor_after_replace("radius: ;", "radius: 2.5;", 8), 11);
    EXPECT_EQ(cursor_after_replace("radius: ;", "radius: 2.5;", 9), 12) << "after it: moved";
}

// A character typed beside its own twin (a doubled digit, a space of
// indentation) could have been typed at several places: the cursor's is one.
TEST(TextCursor, ARedoOfARepeatedCharacterLeavesTheCursorAfterIt) {
    // "  foo" with a space typed at 0, undone, redone.
    EXPECT_EQ(cursor_after_replace("  foo", "   foo", 0), 1);
    // "value 1|00;" backspaced to "value 1|0;", the deletion undone.
    EXPECT_EQ(cursor_after_replace("value 10;", "value 100;", 7), 8);
}

TEST(TextCursor, StaysInsideTheNewText) {
    EXPECT_EQ(cursor_after_replace("abcdef", "", 4), 0);
    EXPECT_EQ(cursor_after_replace("abc", "abc", 99), 3);
    EXPECT_EQ(cursor_after_replace("abc", "xbc", -4), 0);
    EXPECT_EQ(cursor_after_replace("width: 1;", "width: 25;", 8), 9);
}

}  // namespace
}  // namespace jt::view
