#include "render/render_passes.hpp"

#include <algorithm>

namespace jt {

namespace {

constexpr std::uint64_t first_preview_max_rays = 4096;

int floor_div(int a, int b) {
    return a / b;
}  // a >= 0 here
int ceil_div(int a, int b) {
    return (a + b - 1) / b;
}

std::uint64_t blocks_in(const PixelRect& r, int block) {
    if (r.empty()) return 0;
    auto across = static_cast<std::uint64_t>(ceil_div(r.x1, block) - floor_div(r.x0, block));
    auto down = static_cast<std::uint64_t>(ceil_div(r.y1, block) - floor_div(r.y0, block));
    return across * down;
}

}  // namespace

std::vector<RenderPass> plan_passes(const PixelRect& region, int samples, bool previews) {
    std::vector<RenderPass> passes;
    if (region.empty()) return passes;
    if (previews) {
        // The first preview is there to show something at once: past a few
        // thousand rays (1280x720 at 1/8 is 14,400) it no longer does, so a
        // large image starts at 1/16.
        const bool coarse_first = blocks_in(region, 8) > first_preview_max_rays;
        for (int block : {16, 8, 4, 2}) {
            if (block == 16 && !coarse_first) continue;
            RenderPass p;
            p.name = "preview 1/" + std::to_string(block);
            p.block = block;
            p.work = blocks_in(region, block);
            passes.push_back(p);
        }
    }
    const std::uint64_t pixels = blocks_in(region, 1);
    int done = 0;
    while (done < samples) {
        int next = done == 0 ? 1 : std::min(samples, done * 2);
        RenderPass p;
        p.name = next == 1 ? "1 sample" : std::to_string(next) + " samples";
        p.sample_begin = done;
        p.sample_end = next;
        p.work = pixels * static_cast<std::uint64_t>(next - done);
        passes.push_back(p);
        done = next;
    }
    return passes;
}

std::vector<PixelRect> cut_tiles(const PixelRect& region, int block, int tile_blocks) {
    std::vector<PixelRect> tiles;
    if (region.empty()) return tiles;
    const int size = block * tile_blocks;
    for (int ty = floor_div(region.y0, size); ty * size < region.y1; ++ty) {
        for (int tx = floor_div(region.x0, size); tx * size < region.x1; ++tx) {
            PixelRect t{std::max(region.x0, tx * size), std::max(region.y0, ty * size),
                        std::min(region.x1, (tx + 1) * size), std::min(region.y1, (ty + 1) * size)};
            if (!t.empty()) tiles.push_back(t);
        }
    }
    return tiles;
}

}  // namespace jt
