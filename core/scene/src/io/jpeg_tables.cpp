#include "io/jpeg_tables.hpp"

namespace jt {

namespace {

constexpr std::uint8_t marker_start = 0xFF;
constexpr std::uint8_t start_of_image = 0xD8;
constexpr std::uint8_t end_of_image = 0xD9;
constexpr std::uint8_t define_huffman_tables = 0xC4;
constexpr int most_symbols = 256;

// Markers that stand alone, without a length: a stuffed 0xFF byte in scan
// data (0x00), TEM, and the restart markers RST0-RST7.
bool stands_alone(std::uint8_t marker) {
    return marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7);
}

// The tables of one DHT segment starting at `at` (after its length), read as
// stb_image reads them: while the declared length lasts, a class/slot byte,
// 16 code counts and as many symbols as the counts add up to. Past the end of
// the file stb_image reads zeros, and so does this.
std::string huffman_segment_problem(std::span<const std::uint8_t> bytes, std::size_t at,
                                    int length) {
    while (length > 0 && at < bytes.size()) {
        int symbols = 0;
        for (std::size_t i = at + 1; i < at + 17 && i < bytes.size(); ++i) symbols += bytes[i];
        if (symbols > most_symbols)
            return "a corrupt JPEG: a Huffman table of " + std::to_string(symbols) +
                   " codes (at most 256)";
        at += 17 + static_cast<std::size_t>(symbols);
        length -= 17 + symbols;
    }
    return "";
}

}  // namespace

std::string jpeg_table_problem(std::span<const std::uint8_t> bytes) {
    // stb_image, like the standard, lets fill bytes (0xFF) come before any marker.
    std::size_t at = 0;
    while (at < bytes.size() && bytes[at] == marker_start) ++at;
    if (at == 0 || at == bytes.size() || bytes[at] != start_of_image) return "";
    ++at;
    // Segments carry their length; the data of a scan does not, so it is
    // walked byte by byte up to the next marker.
    while (at + 1 < bytes.size()) {
        if (bytes[at] != marker_start || bytes[at + 1] == marker_start) {
            ++at;
            continue;
        }
        const std::uint8_t marker = bytes[at + 1];
        if (marker == end_of_image) break;
        if (stands_alone(marker)) {
            at += 2;
            continue;
        }
        if (at + 4 > bytes.size()) break;
        const int length = bytes[at + 2] << 8 | bytes[at + 3];
        if (marker == define_huffman_tables)
            if (std::string problem = huffman_segment_problem(bytes, at + 4, length - 2);
                !problem.empty())
                return problem;
        at += 2 + static_cast<std::size_t>(length);
    }
    return "";
}

}  // namespace jt
