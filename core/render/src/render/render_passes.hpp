#pragma once
// The pass plan of a RenderJob and the tiles each pass is cut into.

#include "jtracer/image.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace jt {

struct RenderPass {
    std::string name;
    int block = 1;         // > 1: one ray per block x block pixels (a preview)
    int sample_begin = 0;  // full-resolution passes: samples [begin, end) of each pixel
    int sample_end = 1;
    std::uint64_t work = 0;  // rays of camera work, for the progress fraction
};

// Previews 1/8, 1/4, 1/2 (when asked; 1/16 first when 1/8 would take more
// than 4096 rays), then 1 sample, then doubling sample counts up to `samples`.
std::vector<RenderPass> plan_passes(const PixelRect& region, int samples, bool previews);

// The pixel rectangles a pass is cut into: squares of `tile_blocks` blocks,
// aligned to the image origin (so blocks never straddle tiles), clipped to
// `region`, in row-major order.
std::vector<PixelRect> cut_tiles(const PixelRect& region, int block, int tile_blocks);

}  // namespace jt
