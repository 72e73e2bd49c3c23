#pragma once
// A region file: one part of a frame, as `jtracer-cli --region-output` writes
// it and jtracer-merge reads it.
//
// It is an ordinary 24-bit BMP of the region's pixels that any viewer opens.
// Where the part belongs travels inside it: a 32-byte record between the BMP
// headers and the pixels (the header's pixel offset skips it, as the format
// allows), so parts can be renamed, copied and globbed freely:
//
//   "JTRG", version, frame width, frame height, X0, Y0, X1, Y1
//
// all little-endian uint32, the region in top-left-origin bounds (region.hpp).
// Version 2 (96 bytes) adds what the part was rendered from, so that parts of
// different renders are never merged into one frame:
//
//   samples, camera index (uint32), clock (IEEE double), the scene's 16-byte
//   digest, the camera's name (32 bytes, NUL-padded, cut at 32)
//
// Version 1 (32 bytes, written before the fingerprint existed) is still read,
// without a fingerprint.

#include "jtracer/error.hpp"
#include "jtracer/image.hpp"
#include "jtracer/region.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace jt {

// What a part was rendered from besides its size and region: parts of one
// frame agree on all of it.
struct RenderFingerprint {
    // The scene's content: every value that decides the pixels (after the
    // defines and the clock), and the bytes of the files it names
    // (render_fingerprint.hpp).
    std::array<std::uint8_t, 16> scene{};
    int samples = 0;
    int camera = 0;           // index into the scene's cameras
    std::string camera_name;  // for messages: at most 32 bytes are kept
    double clock = 0.0;
    bool operator==(const RenderFingerprint&) const = default;
};

struct RegionPlacement {
    int frame_width = 0;
    int frame_height = 0;
    FrameRegion region;
    // None in a version 1 record.
    std::optional<RenderFingerprint> fingerprint = std::nullopt;
    bool operator==(const RegionPlacement&) const = default;
};

// One part of a frame: its pixels (row 0 at the region's bottom) and where
// they belong.
struct RegionPart {
    std::string name;  // for messages: the file it came from
    Image8 pixels;
    RegionPlacement placement;
};

// Atomic write (atomic_file.hpp): a version 2 record when the placement has
// a fingerprint, else version 1.
Expected<void> write_region_bmp(const std::filesystem::path& path, const Image8& part,
                                const RegionPlacement& placement);

// Reads the pixels and the record, named after `path`. A plain BMP is refused
// ("carries no region record").
Expected<RegionPart> read_region_bmp(const std::filesystem::path& path);

}  // namespace jt
