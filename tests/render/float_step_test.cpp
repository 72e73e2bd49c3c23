// The bit-pattern float neighbours against std::nextafter: a spread of every
// float's bit patterns plus the edges where the arithmetic changes (zeros,
// subnormals, the largest finite, infinities, NaNs). The floats at or below
// and at or above a double against rounding and stepping with nextafter, on
// doubles at, between and around those floats.

#include "geometry/float_step.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace jt::test {
namespace {

// Prime, so the sample meets every exponent and many mantissa endings.
constexpr std::uint32_t sample_stride = 4099;
// Bit patterns taken whole on each side of each edge.
constexpr std::uint32_t edge_span = 4096;

bool same_float(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

std::vector<std::uint32_t> patterns() {
    std::vector<std::uint32_t> out;
    for (std::uint64_t bits = 0; bits <= 0xFFFFFFFFu; bits += sample_stride)
        out.push_back(static_cast<std::uint32_t>(bits));
    const float edges[] = {0.0f,
                           std::numeric_limits<float>::denorm_min(),
                           std::numeric_limits<float>::min(),
                           1.0f,
                           std::numeric_limits<float>::max(),
                           std::numeric_limits<float>::infinity(),
                           std::numeric_limits<float>::quiet_NaN()};
    for (float edge : edges)
        for (float signed_edge : {edge, -edge}) {
            const std::uint32_t centre = std::bit_cast<std::uint32_t>(signed_edge);
            for (std::uint32_t d = 0; d < edge_span; ++d) {
                out.push_back(centre + d);
                out.push_back(centre - d);
            }
        }
    out.push_back(std::bit_cast<std::uint32_t>(std::numeric_limits<float>::signaling_NaN()));
    return out;
}

TEST(FloatStep, EqualsNextafterDownAndUp) {
    const float infinity = std::numeric_limits<float>::infinity();
    std::size_t mismatches = 0;
    for (std::uint32_t bits : patterns()) {
        const float f = std::bit_cast<float>(bits);
        if (!same_float(next_float_down(f), std::nextafter(f, -infinity))) ++mismatches;
        if (!same_float(next_float_up(f), std::nextafter(f, infinity))) ++mismatches;
    }
    EXPECT_EQ(mismatches, 0u);
}

TEST(FloatStep, EdgesByName) {
    const float infinity = std::numeric_limits<float>::infinity();
    const float tiny = std::numeric_limits<float>::denorm_min();
    EXPECT_TRUE(same_float(next_float_down(0.0f), -tiny));
    EXPECT_TRUE(same_float(next_float_down(-0.0f), -tiny));
    EXPECT_TRUE(same_float(next_float_up(-0.0f), tiny));
    EXPECT_TRUE(same_float(next_float_down(infinity), std::numeric_limits<float>::max()));
    EXPECT_TRUE(same_float(next_float_up(-infinity), -std::numeric_limits<float>::max()));
    EXPECT_TRUE(same_float(next_float_up(infinity), infinity));
    EXPECT_TRUE(same_float(next_float_down(-infinity), -infinity));
    EXPECT_TRUE(std::isnan(next_float_up(std::numeric_limits<float>::quiet_NaN())));
}

// Doubles on each float of the sample, a little off it either way, half way
// to its neighbours, and past the float range and the smallest subnormal.
std::vector<double> doubles_around_floats() {
    const double infinity = std::numeric_limits<double>::infinity();
    std::vector<double> out;
    for (std::uint32_t bits : patterns()) {
        const float f = std::bit_cast<float>(bits);
        const double d = f;
        out.push_back(d);
        out.push_back(std::nextafter(d, -infinity));
        out.push_back(std::nextafter(d, infinity));
        out.push_back(0.5 * (d + static_cast<double>(std::nextafter(f, -infinity))));
        out.push_back(0.5 * (d + static_cast<double>(std::nextafter(f, infinity))));
    }
    for (double d : {1e-300, 1e-46, 1e39, 1e300, std::numeric_limits<double>::denorm_min()}) {
        out.push_back(d);
        out.push_back(-d);
    }
    return out;
}

TEST(FloatStep, AtOrBelowAndAboveEqualRoundingThenNextafter) {
    const float infinity = std::numeric_limits<float>::infinity();
    std::size_t mismatches = 0;
    for (double x : doubles_around_floats()) {
        const float nearest = static_cast<float>(x);
        const double back = nearest;
        const float below = back > x ? std::nextafter(nearest, -infinity) : nearest;
        const float above = back < x ? std::nextafter(nearest, infinity) : nearest;
        if (!same_float(float_at_or_below(x), below)) ++mismatches;
        if (!same_float(float_at_or_above(x), above)) ++mismatches;
    }
    EXPECT_EQ(mismatches, 0u);
}

}  // namespace
}  // namespace jt::test
