#pragma once
// A region file: one part of a frame, as `jtracer-cli --region-output` writes
// it and jtracer-merge reads it.
//
// It is an ordinary 24-bit BMP of the region's pixels that any viewer opens.
// Where the part belongs travels inside it: a 32-byte record between the BMP
// headers and the pixels (the header's pixel offset skips it, as the format
// allows), so parts can be renamed, copied and globbed freely:
//
//   "JTRG", version 1, frame width, frame height, X0, Y0, X1, Y1
//
// all little-endian uint32, the region in top-left-origin bounds (region.hpp).

#include "jtracer/image.hpp"
#include "jtracer/region.hpp"

#include <filesystem>
#include <string>

namespace jt {

struct RegionPlacement {
    int frame_width = 0;
    int frame_height = 0;
    FrameRegion region;
    bool operator==(const RegionPlacement&) const = default;
};

// Atomic write (atomic_file.hpp). Empty string on success, else the error.
std::string write_region_bmp(const std::filesystem::path& path, const Image8& part,
                             const RegionPlacement& placement);

// Reads the pixels and the record. Empty string on success, else the error
// (including "carries no region record" for a plain BMP).
std::string read_region_bmp(const std::filesystem::path& path, Image8& part,
                            RegionPlacement& placement);

}  // namespace jt
