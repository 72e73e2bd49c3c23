// The line diff the reload choice shows between the viewer's text and the file's.

#include "model/text_diff.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

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

// Found in the real window: a 400,000-line scene with the width edited in
// the viewer and a comment appended on disk. The middle between the first
// and last lines both share was every line, too many for the table of
// common lengths: "400017 lines removed, 400018 added" for two changed
// lines. A long text with few changes is compared line by line too.
TEST(TextDiff, ALongTextWithFewChangesIsComparedLineByLine) {
    std::string mine = "width: 1920;\n", theirs = "width: 640;\n";
    for (int i = 0; i < 20000; ++i) {
        const std::string line = "sphere " + std::to_string(i) + "\n";
        mine += line;
        theirs += i == 10000 ? "sphere ten thousand\n" : line;
    }
    theirs += "# appended\n";
    const TextDiff diff = diff_lines(mine, theirs, 1);
    EXPECT_FALSE(diff.coarse);
    EXPECT_EQ(diff.removed, 2);  // the width, sphere 10000
    EXPECT_EQ(diff.added, 3);    // the width, "ten thousand", the comment
    ASSERT_EQ(diff.lines.size(), 9u);
    EXPECT_EQ(diff.lines[0].kind, Kind::removed);
    EXPECT_EQ(diff.lines[0].text, "width: 1920;");
    EXPECT_EQ(diff.lines[1].kind, Kind::added);
    EXPECT_EQ(diff.lines[1].text, "width: 640;");
    EXPECT_EQ(diff.lines[2].text, "sphere 0");
    EXPECT_EQ(diff.lines[4].kind, Kind::removed);
    EXPECT_EQ(diff.lines[4].old_line, 10002);
    EXPECT_EQ(diff.lines[5].kind, Kind::added);
    EXPECT_EQ(diff.lines[5].text, "sphere ten thousand");
    EXPECT_EQ(diff.lines[5].new_line, 10002);
    EXPECT_EQ(diff.lines[7].text, "sphere 19999");
    EXPECT_EQ(diff.lines[8].kind, Kind::added);
    EXPECT_EQ(diff.lines[8].text, "# appended");
    EXPECT_EQ(diff.lines[8].new_line, 20002);
}

// The long texts' diff read one way gives the old text back, read the other
// the new one, and lists no more lines than the edits made.
TEST(TextDiff, ALongTextsDiffGivesBothTextsBack) {
    std::mt19937 random(7);
    for (int round = 0; round < 20; ++round) {
        std::vector<std::string> old_lines, new_lines;
        for (int i = 0; i < 5000; ++i) old_lines.push_back("line " + std::to_string(i % 700));
        new_lines = old_lines;
        const int edits = 1 + static_cast<int>(random() % 40);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = random() % new_lines.size();
            switch (random() % 3) {
                case 0:
                    new_lines.erase(new_lines.begin() + static_cast<long>(at));
                    break;
                case 1:
                    new_lines.insert(new_lines.begin() + static_cast<long>(at), "new");
                    break;
                default:
                    new_lines[at] = "changed";
                    break;
            }
        }
        std::string old_text, new_text;
        for (const std::string& l : old_lines) old_text += l + "\n";
        for (const std::string& l : new_lines) new_text += l + "\n";
        const TextDiff diff = diff_lines(old_text, new_text, 1 << 20);
        ASSERT_FALSE(diff.coarse) << "round " << round;
        std::string old_back, new_back;
        for (const DiffLine& line : diff.lines) {
            if (line.kind != Kind::added) old_back += line.text + "\n";
            if (line.kind != Kind::removed) new_back += line.text + "\n";
        }
        EXPECT_EQ(old_back, old_text) << "round " << round;
        EXPECT_EQ(new_back, new_text) << "round " << round;
        EXPECT_LE(diff.removed + diff.added, 2 * edits) << "round " << round;
    }
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
