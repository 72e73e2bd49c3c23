#include "io/png_chunks.hpp"

#include "jtracer/png.hpp"

#include <algorithm>
#include <iterator>

namespace jt {

namespace {

// The chunk's type as the file spells it when it is four ASCII letters.
std::string chunk_name(std::span<const std::uint8_t, 4> type) {
    const bool letters = std::all_of(type.begin(), type.end(), [](std::uint8_t c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    });
    return letters ? std::string(type.begin(), type.end()) + " chunk" : "chunk";
}

}  // namespace

std::string png_chunk_problem(std::span<const std::uint8_t> bytes) {
    if (!has_png_signature(bytes)) return "";
    static constexpr std::uint8_t idat[4] = {'I', 'D', 'A', 'T'};
    static constexpr std::uint8_t iend[4] = {'I', 'E', 'N', 'D'};
    bool seen_idat = false;
    // Each chunk: its length (4 bytes, big-endian), its type (4), its data, a CRC (4).
    std::uint64_t at = 8;
    while (at + 8 <= bytes.size()) {
        std::uint64_t length = 0;
        for (std::uint64_t i = at; i < at + 4; ++i) length = length << 8 | bytes[i];
        const std::span<const std::uint8_t, 4> type = bytes.subspan(at + 4).first<4>();
        if (std::equal(std::begin(iend), std::end(iend), type.begin())) return "";
        const bool is_idat = std::equal(std::begin(idat), std::end(idat), type.begin());
        if (is_idat && !seen_idat && length == 0)
            return "a PNG whose first IDAT chunk is empty (at byte " + std::to_string(at) + ")";
        seen_idat = seen_idat || is_idat;
        if (at + 12 + length > bytes.size())
            return "a PNG whose " + chunk_name(type) + " at byte " + std::to_string(at) +
                   " claims " + std::to_string(length) + " bytes, past the end of the file (" +
                   std::to_string(bytes.size()) + " bytes)";
        at += 12 + length;
    }
    return "";
}

}  // namespace jt
