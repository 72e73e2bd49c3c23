#pragma once
// The neighbouring float below or above, by the bit pattern: the same result
// as std::nextafter toward -inf or +inf for every float, NaN left a NaN, but
// inline. The library call showed in the profile of a million sphere bounds.

#include <bit>
#include <cstdint>
#include <limits>

namespace jt {

inline float next_float_down(float f) {
    if (f != f || f == -std::numeric_limits<float>::infinity()) return f;
    if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<std::uint32_t>(f);
    // The magnitude grows below zero and shrinks above it.
    return std::bit_cast<float>(bits & 0x80000000u ? bits + 1u : bits - 1u);
}

inline float next_float_up(float f) {
    if (f != f || f == std::numeric_limits<float>::infinity()) return f;
    if (f == 0.0f) return std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(bits & 0x80000000u ? bits - 1u : bits + 1u);
}

// The largest float at or below x, and the smallest at or above it: the
// nearest float, stepped one bit pattern when it lies on the wrong side of x,
// as next_float_down and next_float_up would step it, but without a branch.
// Whether a coordinate rounds up or down is as good as random, and a Morton
// build asks for a million spheres' boxes three times each: mispredicted
// branches took most of a box's time. A zero is stepped only from the side its
// sign comes from (a negative x rounds to -0), where its bit pattern steps
// right too; NaN never compares, and infinity steps to the largest float.
inline float float_at_or_below(double x) {
    const float f = static_cast<float>(x);
    const auto bits = std::bit_cast<std::uint32_t>(f);
    const auto step = static_cast<std::uint32_t>(static_cast<double>(f) > x);
    // The magnitude grows below zero and shrinks above it.
    return std::bit_cast<float>(bits + step * (2u * (bits >> 31) - 1u));
}

inline float float_at_or_above(double x) {
    const float f = static_cast<float>(x);
    const auto bits = std::bit_cast<std::uint32_t>(f);
    const auto step = static_cast<std::uint32_t>(static_cast<double>(f) < x);
    return std::bit_cast<float>(bits + step * (1u - 2u * (bits >> 31)));
}

}  // namespace jt
