// A list's stored distance is the largest float at or below the double bound,
// and keeps the order of the bounds: a walk that stops at the first shape
// beyond its hit tests at least the shapes the doubles would let it test.

#include "render/listed_shapes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace jt::test {
namespace {

TEST(ListedShapes, AStoredDistanceIsTheLargestFloatAtOrBelowItsBound) {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> bounds = {0.0, std::numeric_limits<double>::denorm_min(), 1.0,  1.0 + 1e-12,
                                  0.1, std::numeric_limits<float>::max(),         1e300};
    for (int i = 0; i < 100000; ++i) bounds.push_back(unit(rng) * std::pow(10.0, 12 * unit(rng)));
    std::sort(bounds.begin(), bounds.end());
    ListedDistance previous = 0.0f;
    for (const double bound : bounds) {
        const ListedDistance stored = listed_distance(bound);
        ASSERT_LE(stored, bound) << "never above the bound: " << bound;
        ASSERT_GT(next_float_up(stored), bound) << "the nearest float below: " << bound;
        ASSERT_LE(previous, stored) << "in the bounds' order";
        previous = stored;
    }
    EXPECT_EQ(listed_distance(std::numeric_limits<double>::infinity()),
              std::numeric_limits<float>::infinity());
}

}  // namespace
}  // namespace jt::test
