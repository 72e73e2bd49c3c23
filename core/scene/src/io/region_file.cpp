#include "jtracer/region_file.hpp"

#include "io/file_bytes.hpp"
#include "jtracer/atomic_file.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/limits.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace jt {

namespace {

constexpr std::size_t bmp_headers = 54;  // file header + BITMAPINFOHEADER
constexpr std::size_t record_size = 32;
constexpr std::array<std::uint8_t, 4> magic{'J', 'T', 'R', 'G'};
constexpr std::uint32_t version = 1;

void put32(std::uint8_t* p, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::uint32_t get32(const std::uint8_t* p) {
    return p[0] | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) |
           (std::uint32_t{p[3]} << 24);
}

}  // namespace

Expected<void> write_region_bmp(const std::filesystem::path& path, const Image8& part,
                                const RegionPlacement& p) {
    std::vector<std::uint8_t> bytes = encode_bmp(part);
    std::array<std::uint8_t, record_size> record{};
    std::copy(magic.begin(), magic.end(), record.begin());
    const std::uint32_t fields[] = {version,
                                    static_cast<std::uint32_t>(p.frame_width),
                                    static_cast<std::uint32_t>(p.frame_height),
                                    static_cast<std::uint32_t>(p.region.left),
                                    static_cast<std::uint32_t>(p.region.top),
                                    static_cast<std::uint32_t>(p.region.right),
                                    static_cast<std::uint32_t>(p.region.bottom)};
    for (std::size_t i = 0; i < std::size(fields); ++i) put32(&record[4 + 4 * i], fields[i]);
    bytes.insert(bytes.begin() + bmp_headers, record.begin(), record.end());
    if (bytes.size() > kMaxBmpFileBytes)
        return Error{"cannot write " +
                     file_message(path, "the region is too large for a BMP (4 GiB)")};
    put32(&bytes[2], static_cast<std::uint32_t>(bytes.size()));
    put32(&bytes[10], get32(&bytes[10]) + record_size);  // the pixels move past the record
    return write_file_atomically(path, bytes);
}

Expected<RegionPart> read_region_bmp(const std::filesystem::path& path) {
    Expected<std::vector<std::uint8_t>> read = read_file_bytes(path);
    if (!read) return read.error();
    const std::vector<std::uint8_t>& bytes = *read;
    Expected<Image8> pixels = decode_bmp(bytes);
    if (!pixels) return Error{file_message(path, pixels.error().message)};
    if (get32(&bytes[10]) < bmp_headers + record_size ||
        !std::equal(magic.begin(), magic.end(), bytes.begin() + bmp_headers))
        return Error{file_message(path,
                                  "carries no region record (only BMPs written by "
                                  "'jtracer-cli --region ... --region-output' can be merged)")};
    const std::uint8_t* r = &bytes[bmp_headers];
    if (get32(r + 4) != version)
        return Error{
            file_message(path, "region record of unknown version " + std::to_string(get32(r + 4)))};
    auto field = [&](int i) {
        std::uint32_t v = get32(r + 8 + 4 * i);
        return v > static_cast<std::uint32_t>(kMaxImageSide) ? -1 : static_cast<int>(v);
    };
    RegionPart part{path.string(), std::move(*pixels), {}};
    RegionPlacement& p = part.placement;
    p.frame_width = field(0);
    p.frame_height = field(1);
    p.region = {field(2), field(3), field(4), field(5)};
    if (p.frame_width <= 0 || p.frame_height <= 0 || p.region.left < 0 || p.region.top < 0 ||
        p.region.right < 0 || p.region.bottom < 0)
        return Error{file_message(path, "region record holds numbers out of range")};
    return part;
}

}  // namespace jt
