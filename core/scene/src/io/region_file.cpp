#include "jtracer/region_file.hpp"

#include "io/file_bytes.hpp"
#include "jtracer/atomic_file.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/limits.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

namespace jt {

namespace {

constexpr std::size_t bmp_headers = 54;  // file header + BITMAPINFOHEADER
constexpr std::size_t record_size_v1 = 32;
constexpr std::size_t record_size_v2 = 96;
constexpr std::size_t camera_name_bytes = 32;
constexpr std::array<std::uint8_t, 4> magic{'J', 'T', 'R', 'G'};

void put32(std::uint8_t* p, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::uint32_t get32(const std::uint8_t* p) {
    return p[0] | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) |
           (std::uint32_t{p[3]} << 24);
}

void put64(std::uint8_t* p, std::uint64_t v) {
    put32(p, static_cast<std::uint32_t>(v));
    put32(p + 4, static_cast<std::uint32_t>(v >> 32));
}

std::uint64_t get64(const std::uint8_t* p) {
    return get32(p) | (std::uint64_t{get32(p + 4)} << 32);
}

}  // namespace

Expected<void> write_region_bmp(const std::filesystem::path& path, const Image8& part,
                                const RegionPlacement& p) {
    std::vector<std::uint8_t> bytes = encode_bmp(part);
    const std::size_t record_size = p.fingerprint ? record_size_v2 : record_size_v1;
    std::vector<std::uint8_t> record(record_size, 0);
    std::copy(magic.begin(), magic.end(), record.begin());
    const std::uint32_t fields[] = {p.fingerprint ? 2u : 1u,
                                    static_cast<std::uint32_t>(p.frame_width),
                                    static_cast<std::uint32_t>(p.frame_height),
                                    static_cast<std::uint32_t>(p.region.left),
                                    static_cast<std::uint32_t>(p.region.top),
                                    static_cast<std::uint32_t>(p.region.right),
                                    static_cast<std::uint32_t>(p.region.bottom)};
    for (std::size_t i = 0; i < std::size(fields); ++i) put32(&record[4 + 4 * i], fields[i]);
    if (const std::optional<RenderFingerprint>& f = p.fingerprint) {
        put32(&record[32], static_cast<std::uint32_t>(f->samples));
        put32(&record[36], static_cast<std::uint32_t>(f->camera));
        put64(&record[40], std::bit_cast<std::uint64_t>(f->clock));
        std::copy(f->scene.begin(), f->scene.end(), record.begin() + 48);
        std::copy_n(f->camera_name.begin(), std::min(f->camera_name.size(), camera_name_bytes),
                    record.begin() + 64);
    }
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
    if (get32(&bytes[10]) < bmp_headers + record_size_v1 ||
        !std::equal(magic.begin(), magic.end(), bytes.begin() + bmp_headers))
        return Error{file_message(path,
                                  "carries no region record (only BMPs written by "
                                  "'jtracer-cli --region ... --region-output' can be merged)")};
    const std::uint8_t* r = &bytes[bmp_headers];
    const std::uint32_t version = get32(r + 4);
    if (version != 1 && version != 2)
        return Error{file_message(path, "region record of unknown version " +
                                            std::to_string(version) +
                                            " (written by a newer JTracer?)")};
    if (version == 2 && get32(&bytes[10]) < bmp_headers + record_size_v2)
        return Error{file_message(path, "region record is cut short")};
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
    if (version == 2) {
        RenderFingerprint f;
        f.samples = static_cast<int>(std::min<std::uint32_t>(get32(r + 32), 1u << 30));
        f.camera = static_cast<int>(std::min<std::uint32_t>(get32(r + 36), 1u << 30));
        f.clock = std::bit_cast<double>(get64(r + 40));
        std::copy_n(r + 48, f.scene.size(), f.scene.begin());
        const char* name = reinterpret_cast<const char*>(r + 64);
        f.camera_name.assign(name, std::find(name, name + camera_name_bytes, '\0'));
        p.fingerprint = std::move(f);
    }
    return part;
}

}  // namespace jt
