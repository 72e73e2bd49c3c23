// What two sequences share at their ends, for the text cursor (bytes) and the
// text diff (lines).

#include "model/common_ends.hpp"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace jt::view {
namespace {

TEST(CommonEnds, CountsTheSharedStartAndEndOfTwoTexts) {
    const CommonEnds ends =
        common_ends(std::string_view("radius: 2;"), std::string_view("radius: 25;"));
    EXPECT_EQ(ends.prefix, 9u);
    EXPECT_EQ(ends.tail, 1u);
    EXPECT_EQ(ends.suffix, 1u);
    const CommonEnds none = common_ends(std::string_view("abc"), std::string_view("xyz"));
    EXPECT_EQ(none.prefix + none.tail + none.suffix, 0u);
    const CommonEnds empty = common_ends(std::string_view(""), std::string_view("a"));
    EXPECT_EQ(empty.prefix + empty.tail + empty.suffix, 0u);
}

// "aa" -> "aaa": both ends share all of "aa"; cut at the prefix, the end
// shares nothing more, and the change is the one 'a' past them.
TEST(CommonEnds, TheSuffixStopsWhereThePrefixEndsButTheTailDoesNot) {
    const CommonEnds ends = common_ends(std::string_view("aa"), std::string_view("aaa"));
    EXPECT_EQ(ends.prefix, 2u);
    EXPECT_EQ(ends.tail, 2u);
    EXPECT_EQ(ends.suffix, 0u);
    const CommonEnds same = common_ends(std::string_view("abc"), std::string_view("abc"));
    EXPECT_EQ(same.prefix, 3u);
    EXPECT_EQ(same.tail, 3u);
    EXPECT_EQ(same.suffix, 0u);
}

TEST(CommonEnds, ComparesLinesAsWholeElements) {
    const std::vector<std::string_view> a{"a", "b", "c", "d"}, b{"a", "x", "y", "d"};
    const CommonEnds ends = common_ends(a, b);
    EXPECT_EQ(ends.prefix, 1u);
    EXPECT_EQ(ends.suffix, 1u);
    const std::vector<std::string_view> longer{"a", "b", "c", "b", "c", "d"};
    EXPECT_EQ(common_ends(a, longer).prefix, 3u);
    EXPECT_EQ(common_ends(a, longer).tail, 3u);
    EXPECT_EQ(common_ends(a, longer).suffix, 1u);
}

}  // namespace
}  // namespace jt::view
