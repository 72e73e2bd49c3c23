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

#include "jtracer/error.hpp"
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

// One part of a frame: its pixels (row 0 at the region's bottom) and where
// they belong.
struct RegionPart {
    std::string name;  // for messages: the file it came from
    Image8 pixels;
    RegionPlacement placement;
};

// Atomic write (atomic_file.hpp).
Expected<void> write_region_bmp(const std::filesystem::path& path, const Image8& part,
                                const RegionPlacement& placement);

// Reads the pixels and the record, named after `path`. A plain BMP is refused
// ("carries no region record").
Expected<RegionPart> read_region_bmp(const std::filesystem::path& path);

}  // namespace jt
