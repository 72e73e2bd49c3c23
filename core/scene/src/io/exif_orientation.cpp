#include "io/exif_orientation.hpp"

#include "io/jpeg.hpp"

#include <algorithm>
#include <cstddef>

namespace jt {

namespace {

constexpr std::uint16_t kOrientationTag = 0x0112;
constexpr std::uint16_t kShort = 3;

// Reads within one TIFF block, in its byte order; 0 past its end.
class TiffBytes {
  public:
    TiffBytes(std::span<const std::uint8_t> bytes, bool big_endian)
        : bytes_(bytes), big_(big_endian) {}
    bool has(std::size_t at, std::size_t n) const {
        return at <= bytes_.size() && n <= bytes_.size() - at;
    }
    std::uint32_t u16(std::size_t at) const {
        if (!has(at, 2)) return 0;
        return big_ ? (bytes_[at] << 8 | bytes_[at + 1]) : (bytes_[at + 1] << 8 | bytes_[at]);
    }
    std::uint32_t u32(std::size_t at) const {
        return big_ ? (u16(at) << 16 | u16(at + 2)) : (u16(at + 2) << 16 | u16(at));
    }

  private:
    std::span<const std::uint8_t> bytes_;
    bool big_;
};

// The orientation in IFD0 of the TIFF block an Exif segment holds, or 1.
int orientation_in(std::span<const std::uint8_t> tiff) {
    if (tiff.size() < 8) return 1;
    const bool big = tiff[0] == 'M' && tiff[1] == 'M';
    if (!big && !(tiff[0] == 'I' && tiff[1] == 'I')) return 1;
    const TiffBytes in(tiff, big);
    if (in.u16(2) != 42) return 1;
    const std::size_t ifd = in.u32(4);
    if (!in.has(ifd, 2)) return 1;
    const std::uint32_t entries = in.u16(ifd);
    for (std::uint32_t k = 0; k < entries; ++k) {
        const std::size_t entry = ifd + 2 + 12 * static_cast<std::size_t>(k);
        if (!in.has(entry, 12)) return 1;
        if (in.u16(entry) != kOrientationTag) continue;
        if (in.u16(entry + 2) != kShort || in.u32(entry + 4) != 1) return 1;
        const std::uint32_t value = in.u16(entry + 8);
        return value >= 1 && value <= 8 ? static_cast<int>(value) : 1;
    }
    return 1;
}

}  // namespace

int exif_orientation(std::span<const std::uint8_t> jpeg) {
    static constexpr char kExif[6] = {'E', 'x', 'i', 'f', 0, 0};
    const auto tiff = jpeg_segment(jpeg, kJpegApp1, {kExif, sizeof kExif});
    return tiff ? orientation_in(*tiff) : 1;
}

std::vector<std::uint8_t> turn_upright(const std::vector<std::uint8_t>& stored, int width,
                                       int height, int orientation) {
    if (orientation < 2 || orientation > 8) return stored;
    const bool swap = swaps_sides(orientation);
    const int shown_width = swap ? height : width, shown_height = swap ? width : height;
    std::vector<std::uint8_t> shown(stored.size());
    for (int j = 0; j < shown_height; ++j) {
        // (x, y) as shown and (sx, sy) as stored, both with y = 0 at the top,
        // as the EXIF standard gives them.
        const int y = shown_height - 1 - j;
        for (int x = 0; x < shown_width; ++x) {
            int sx = x, sy = y;
            switch (orientation) {
                case 2:
                    sx = width - 1 - x;
                    break;
                case 3:
                    sx = width - 1 - x, sy = height - 1 - y;
                    break;
                case 4:
                    sy = height - 1 - y;
                    break;
                case 5:
                    sx = y, sy = x;
                    break;
                case 6:
                    sx = y, sy = height - 1 - x;
                    break;
                case 7:
                    sx = width - 1 - y, sy = height - 1 - x;
                    break;
                case 8:
                    sx = width - 1 - y, sy = x;
                    break;
            }
            const std::size_t from = 3 * (static_cast<std::size_t>(height - 1 - sy) * width +
                                          static_cast<std::size_t>(sx));
            const std::size_t to =
                3 * (static_cast<std::size_t>(j) * shown_width + static_cast<std::size_t>(x));
            shown[to] = stored[from];
            shown[to + 1] = stored[from + 1];
            shown[to + 2] = stored[from + 2];
        }
    }
    return shown;
}

}  // namespace jt
