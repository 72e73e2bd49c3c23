#include "io/png_chunks.hpp"

#include "jtracer/png.hpp"

#include <algorithm>
#include <iterator>

namespace jt {

std::string png_chunk_problem(std::span<const std::uint8_t> bytes) {
    if (!has_png_signature(bytes)) return "";
    static constexpr std::uint8_t idat[4] = {'I', 'D', 'A', 'T'};
    static constexpr std::uint8_t iend[4] = {'I', 'E', 'N', 'D'};
    // Each chunk: its length (4 bytes, big-endian), its type (4), its data, a CRC (4).
    std::uint64_t at = 8;
    while (at + 8 <= bytes.size()) {
        std::uint64_t length = 0;
        for (std::uint64_t i = at; i < at + 4; ++i) length = length << 8 | bytes[i];
        const auto type = bytes.begin() + static_cast<std::ptrdiff_t>(at + 4);
        if (std::equal(std::begin(idat), std::end(idat), type))
            return length > 0 ? ""
                              : "a PNG whose first IDAT chunk is empty (at byte " +
                                    std::to_string(at) + ")";
        if (std::equal(std::begin(iend), std::end(iend), type)) return "";
        at += 12 + length;
    }
    return "";
}

}  // namespace jt
