#pragma once
// A case stb_image 2.27 (Debian 12's libstb-dev) mishandles: when a PNG's
// first IDAT chunk is empty it copies those 0 bytes into its image-data buffer
// before it has allocated one, memcpy to a null pointer, which is undefined
// behaviour (found by fuzz/image_map_fuzzer under UBSan). Every PNG's chunks
// are walked here first and such a file is refused.

#include <cstdint>
#include <span>
#include <string>

namespace jt {

// "" when `bytes` are not a PNG or its first IDAT chunk holds data, else what
// is wrong and at which byte.
std::string png_chunk_problem(std::span<const std::uint8_t> bytes);

}  // namespace jt
