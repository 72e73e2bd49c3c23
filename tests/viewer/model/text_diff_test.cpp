// The line diff the reload choice shows between the viewer's text and the file's.

#include "model/text_diff.hpp"

#include <gtest/gtest.h>

namespace jt::view {
namespace {

using Kind = DiffLine::Kind;

TEST(TextDiff, ShowsTheChangedLinesWithTheirContextAndNumbers) {
    const std::string mine = "a\nb\nc\nd\ne\nf\ng\nh\ni\n";
    const std::string theirs = "a\nb\nc\nd\nE\nf\ng\nh\ni\nj\n";
    const TextDiff diff = diff_lines(mine, theirs, 1);
    EXPECT_EQ(diff.removed, 1);
    EXPECT_EQ(diff.added, 2);
    EXPECT_FALSE(diff.coarse);
    ASSERT_EQ(diff.lines.size(), 6u);
    EXPECT_EQ(diff.lines[0].text, "d");
    EXPECT_EQ(diff.lines[1].kind, Kind::removed);
    EXPECT_EQ(diff.lines[1].text, "e");
    EXPECT_EQ(diff.lines[1].old_line, 5);
    EXPECT_EQ(diff.lines[2].kind, Kind::added);
    EXPECT_EQ(diff.lines[2].text, "E");
    EXPECT_EQ(diff.lines[2].new_line, 5);
    EXPECT_EQ(diff.lines[3].text, "f");
    EXPECT_EQ(diff.lines[4].text, "i");
    EXPECT_EQ(diff.lines[5].kind, Kind::added);
    EXPECT_EQ(diff.lines[5].text, "j");
    EXPECT_EQ(diff.lines[5].new_line, 10);
}

TEST(TextDiff, KeepsLinesBothTextsShareInsideTheChange) {
    const TextDiff diff = diff_lines("x\n1\ny\n2\nz\n", "x\ny\n3\nz\n", 0);
    EXPECT_EQ(diff.removed, 2);  // 1 and 2
    EXPECT_EQ(diff.added, 1);    // 3
    for (const DiffLine& line : diff.lines) EXPECT_NE(line.text, "y") << "y is in both";
    EXPECT_TRUE(diff_lines("same\n", "same\n").lines.empty());
}

TEST(TextDiff, HugeMiddlesAreShownWholeRatherThanCompared) {
    std::string a, b;
    for (int i = 0; i < 3000; ++i) {
        a += "a" + std::to_string(i) + "\n";
        b += "b" + std::to_string(i) + "\n";
    }
    const TextDiff diff = diff_lines(a, b);
    EXPECT_TRUE(diff.coarse);
    EXPECT_EQ(diff.removed, 3000);
    EXPECT_EQ(diff.added, 3000);
}

}  // namespace
}  // namespace jt::view
