// io/text_give_back.hpp: the whole pages a reader has passed are given back,
// nothing at or after the offset it passed, nor the first partial page.
#include "io/text_give_back.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

namespace jt {
namespace {

#if defined(__linux__)

constexpr std::size_t kMiB = std::size_t{1} << 20;

std::uintptr_t address(const char* p) {
    return reinterpret_cast<std::uintptr_t>(p);
}

TEST(TextGiveBack, GivesBackTheWholeHugePagesBeforeTheOffsetPassed) {
    std::string text(12 * kMiB, 'x');
    TextGiveBack give_back(text);

    give_back.passed(kMiB);  // no whole 2 MiB page before it yet
    EXPECT_FALSE(give_back.gave_back());
    EXPECT_EQ(std::count(text.begin(), text.end(), 'x'), static_cast<std::ptrdiff_t>(text.size()));

    const std::size_t passed = 9 * kMiB + 123;
    give_back.passed(passed);
    ASSERT_TRUE(give_back.gave_back());
    // A page given back reads as zeros: exactly the 2 MiB units wholly inside
    // [text, text + passed) after the first unit boundary.
    const std::uintptr_t unit = 2 * kMiB;
    const std::uintptr_t first = (address(text.data()) + unit - 1) & ~(unit - 1);
    const std::uintptr_t last = (address(text.data()) + passed) & ~(unit - 1);
    ASSERT_GT(last, first);
    for (std::size_t i = 0; i < text.size(); i += 4096) {
        const std::uintptr_t at = address(text.data()) + i;
        const bool given = at >= first && at + 4096 <= last;
        if (given) {
            EXPECT_EQ(text[i], '\0') << "byte " << i;
        } else if (at + 4096 <= first || at >= last) {
            EXPECT_EQ(text[i], 'x') << "byte " << i;
        }
    }
    EXPECT_EQ(text[passed], 'x');
    EXPECT_EQ(text.back(), 'x');

    // Going back gives back nothing more.
    text.back() = 'y';
    give_back.passed(4 * kMiB);
    EXPECT_EQ(text[last - address(text.data())], 'x');
}

#endif

}  // namespace
}  // namespace jt
