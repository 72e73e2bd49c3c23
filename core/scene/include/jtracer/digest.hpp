#pragma once
// A 128-bit digest for telling values apart: two independent multiply-xorshift
// lanes, fed 8 bytes a step, so that an accidental match is out of the
// question at the speed of reading. Not cryptographic: it guards against
// mistakes (a stale part, an edited scene), not against an adversary.

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace jt {

struct Digest128 {
    std::uint64_t a = 0x9E3779B97F4A7C15ull;
    std::uint64_t b = 0xC2B2AE3D27D4EB4Full;

    void add(std::uint64_t v) {
        a = (a ^ v) * 0xFF51AFD7ED558CCDull;
        a ^= a >> 33;
        b = (b + v) * 0x94D049BB133111EBull;
        b ^= b >> 31;
    }
    void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }
    // The length first, so that "ab" + "c" and "a" + "bc" differ.
    void add(std::string_view bytes) {
        add(static_cast<std::uint64_t>(bytes.size()));
        std::size_t i = 0;
        for (; i + 8 <= bytes.size(); i += 8) {
            std::uint64_t v = 0;
            std::memcpy(&v, bytes.data() + i, 8);
            add(little_endian(v));
        }
        std::uint64_t rest = 0;
        std::memcpy(&rest, bytes.data() + i, bytes.size() - i);
        add(little_endian(rest));
    }
    // Bytes read as a little-endian number, so that every machine digests a
    // file's or a string's bytes alike.
    static std::uint64_t little_endian(std::uint64_t v) {
        if constexpr (std::endian::native == std::endian::big) return __builtin_bswap64(v);
        return v;
    }
    // Lane a's bytes, then lane b's, each least significant first.
    std::array<std::uint8_t, 16> bytes() const {
        std::array<std::uint8_t, 16> out{};
        for (int i = 0; i < 8; ++i) {
            out[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(a >> (8 * i));
            out[static_cast<std::size_t>(8 + i)] = static_cast<std::uint8_t>(b >> (8 * i));
        }
        return out;
    }
};

}  // namespace jt
