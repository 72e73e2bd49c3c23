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

RenderedTile render_work_tile(const std::shared_ptr<const PreparedScene>& scene,
                              const RenderOptions& frame, const PixelRect& tile) {
    const auto start = std::chrono::steady_clock::now();
    RenderOptions options = frame;
    options.previews = false;
    options.region = tile;
    RenderJob job(scene, options);
    job.run();
    RenderedTile out;
    out.pixels = job.region_image();
    out.rays = job.progress().rays;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace jt::mpi
