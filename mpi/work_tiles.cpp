#include "work_tiles.hpp"

#include <algorithm>
#include <chrono>

namespace jt::mpi {

std::vector<PixelRect> cut_work_tiles(int width, int height, int size) {
    std::vector<PixelRect> tiles;
    for (int top = height; top > 0; top -= size)
        for (int x = 0; x < width; x += size)
            tiles.push_back({x, std::max(0, top - size), std::min(width, x + size), top});
    return tiles;
}

WorkTile render_work_tile(const PreparedFrame& frame, const PixelRect& tile) {
    const auto start = std::chrono::steady_clock::now();
    RenderedTile rendered = render_tile(frame, tile);
    WorkTile out;
    out.pixels = std::move(rendered.pixels);
    out.rays = rendered.rays;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace jt::mpi
