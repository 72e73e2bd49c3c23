#pragma once
// A check stb_image 2.27 (Debian 12's libstb-dev) lacks: it builds a JPEG
// Huffman table from the code counts a DHT segment gives before checking that
// they add up to at most 256 symbols, and writes past the table when they do
// not (found by fuzz/image_map_fuzzer). Later stb versions refuse such a
// table; until then every JPEG is walked here first.

#include <cstdint>
#include <span>
#include <string>

namespace jt {

// "" when `bytes` are not a JPEG or every Huffman table in them is sound,
// else what is wrong. Walks the segments and the scans' data the way stb_image
// reads them, so that it sees every DHT segment stb_image would.
std::string jpeg_table_problem(std::span<const std::uint8_t> bytes);

}  // namespace jt
