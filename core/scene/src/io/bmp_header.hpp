#pragma once
// What a BMP image map's header says, read here rather than asked of stb_image:
// stb_image 2.27 gives a top-down BMP's height as stored (negative), and when
// it refuses a BMP its reason is lost under "unknown image type" (it goes on
// to try its other formats). This names what is not supported instead.

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace jt {

struct BmpHeader {
    std::uint32_t info_size = 0;  // 12 (OS/2 core header), 40, 56, 108 or 124
    std::int64_t width = 0;
    std::int64_t height = 0;  // negative: rows stored top-down
    std::uint32_t bits_per_pixel = 0;
    std::uint32_t compression = 0;  // 0 BI_RGB, 1-2 RLE, 3 BI_BITFIELDS, 4 JPEG, 5 PNG
};

bool has_bmp_signature(std::span<const std::uint8_t> bytes);

// The header of a file that starts with "BM", or nothing when the file ends
// before the fields read here.
std::optional<BmpHeader> read_bmp_header(std::span<const std::uint8_t> bytes);

// Why stb_image cannot read a BMP with this header ("RLE-compressed BMP is not
// supported"), or "" when it can.
std::string bmp_header_problem(const BmpHeader& header);

}  // namespace jt
