#pragma once
// Cases stb_image 2.27 (Debian 12's libstb-dev) mishandles, both found by
// fuzz/image_map_fuzzer: when a PNG's first IDAT chunk is empty it copies those
// 0 bytes into its image-data buffer before it has allocated one (memcpy to a
// null pointer, undefined behaviour); and it grows that buffer to hold the
// length an IDAT chunk claims before reading it, so that 108 bytes had it
// reserve 2 GiB. Every PNG's chunks are walked here first and such a file is
// refused.

#include <cstdint>
#include <span>
#include <string>

namespace jt {

// "" when `bytes` are not a PNG, or its first IDAT chunk holds data and every
// chunk before IEND lies inside the file; else what is wrong and at which byte.
std::string png_chunk_problem(std::span<const std::uint8_t> bytes);

}  // namespace jt
