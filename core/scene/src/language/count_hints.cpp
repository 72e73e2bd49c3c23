#include "language/count_hints.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace jt::lang {

BraceAndColonCount count_braces_and_colons(std::string_view text) {
    constexpr std::uint64_t ones = 0x0101010101010101ull, lows = 0x7F7F7F7F7F7F7F7Full;
    // 0x01 in each byte of `w` equal to `byte`, 0 in the others.
    auto matches = [](std::uint64_t w, unsigned char byte) {
        const std::uint64_t x = w ^ (ones * byte);
        return (~(((x & lows) + lows) | x | lows)) >> 7;
    };
    // The sum of the eight byte counters of `lanes`, each at most 255.
    auto sum = [](std::uint64_t lanes) {
        constexpr std::uint64_t even = 0x00FF00FF00FF00FFull;
        const std::uint64_t pairs = (lanes & even) + ((lanes >> 8) & even);
        return static_cast<std::size_t>((pairs * 0x0001000100010001ull) >> 48);
    };
    constexpr std::size_t words_per_flush = 255;  // a byte counter holds 255
    BraceAndColonCount count;
    const char* p = text.data();
    std::size_t left = text.size();
#if defined(__SSE2__)
    // Sixteen bytes at a time with SSE2 (every x86-64 has it): a comparison
    // makes 0xFF of each match, and subtracting that adds one to a byte
    // counter; the counters are summed before they can pass 255.
    const __m128i braces16 = _mm_set1_epi8('{'), colons16 = _mm_set1_epi8(':');
    const __m128i zero = _mm_setzero_si128();
    auto total = [&](__m128i counters) {  // the sum of the 16 byte counters
        const __m128i sums = _mm_sad_epu8(counters, zero);
        return static_cast<std::size_t>(_mm_cvtsi128_si32(sums)) +
               static_cast<std::size_t>(_mm_cvtsi128_si32(_mm_unpackhi_epi64(sums, sums)));
    };
    while (left >= 16) {
        const std::size_t blocks = std::min(left / 16, words_per_flush);
        __m128i braces = zero, colons = zero;
        for (std::size_t k = 0; k < blocks; ++k, p += 16) {
            const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
            braces = _mm_sub_epi8(braces, _mm_cmpeq_epi8(v, braces16));
            colons = _mm_sub_epi8(colons, _mm_cmpeq_epi8(v, colons16));
        }
        count.braces += total(braces);
        count.colons += total(colons);
        left -= blocks * 16;
    }
#endif
    while (left >= 8) {
        const std::size_t words = std::min(left / 8, words_per_flush);
        std::uint64_t braces = 0, colons = 0;
        for (std::size_t k = 0; k < words; ++k, p += 8) {
            std::uint64_t w;
            std::memcpy(&w, p, 8);
            braces += matches(w, '{');
            colons += matches(w, ':');
        }
        count.braces += sum(braces);
        count.colons += sum(colons);
        left -= words * 8;
    }
    for (; left > 0; --left, ++p) {
        count.braces += *p == '{';
        count.colons += *p == ':';
    }
    return count;
}

std::size_t primitive_count_hint(std::string_view text, const BraceAndColonCount& count) {
    constexpr std::size_t bytes_per_primitive_at_least = 32;  // a hint, not a limit
    return std::min(count.braces, text.size() / bytes_per_primitive_at_least);
}

std::size_t property_count_hint(std::string_view text, const BraceAndColonCount& count) {
    return std::min(count.colons, text.size() / 4);
}

}  // namespace jt::lang
