// jt::Expected: the one error convention outside the language (error.hpp).

#include "jtracer/error.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace jt {
namespace {

Expected<int> halve(int n) {
    if (n % 2 != 0) return Error{std::to_string(n) + " is odd"};
    return n / 2;
}

Expected<void> check_even(int n) {
    if (n % 2 != 0) return Error{"odd"};
    return {};
}

TEST(Expected, HoldsTheValueOrTheError) {
    const Expected<int> half = halve(8);
    ASSERT_TRUE(half);
    EXPECT_TRUE(half.has_value());
    EXPECT_EQ(*half, 4);
    EXPECT_EQ(half.value(), 4);

    const Expected<int> odd = halve(7);
    EXPECT_FALSE(odd);
    EXPECT_FALSE(odd.has_value());
    EXPECT_EQ(odd.error().message, "7 is odd");
}

TEST(Expected, MovesAValueOut) {
    Expected<std::unique_ptr<int>> owned = std::make_unique<int>(5);
    ASSERT_TRUE(owned);
    std::unique_ptr<int> taken = std::move(owned).value();
    ASSERT_TRUE(taken);
    EXPECT_EQ(*taken, 5);
}

TEST(Expected, VoidSaysOnlyWhetherItWorked) {
    EXPECT_TRUE(check_even(2));
    const Expected<void> odd = check_even(3);
    ASSERT_FALSE(odd);
    EXPECT_EQ(odd.error().message, "odd");
}

TEST(ExpectedDeathTest, ReadingTheMissingSideStopsWithTheSkippedError) {
    EXPECT_DEATH(static_cast<void>(halve(7).value()), "7 is odd");
    EXPECT_DEATH(static_cast<void>(halve(8).error()), "succeeded");
    EXPECT_DEATH(static_cast<void>(check_even(2).error()), "succeeded");
}

}  // namespace
}  // namespace jt
