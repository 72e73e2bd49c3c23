#include "work_tiles.hpp"

#include <algorithm>
#include <chrono>

namespace jt::mpi {

std::vector<PixelRect> cut_work_tiles(const PixelRect& area, int size) {
    std::vector<PixelRect> tiles;
    for (int top = area.y1; top > area.y0; top -= size)
        for (int x = area.x0; x < area.x1; x += size)
            tiles.push_back({x, std::max(area.y0, top - size), std::min(area.x1, x + size), top});
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
