#pragma once
// The units of work jtracer-mpi hands out: square tiles of the frame, and the
// rendering of one of them.

#include "jtracer/image.hpp"
#include "jtracer/render_tile.hpp"

#include <cstdint>
#include <vector>

namespace jt::mpi {

// Squares of `size` pixels (Image8 coordinates) covering `area` (the whole
// frame, or --region's window), clipped to it, from the top row of tiles
// down, so that the image fills in reading order.
std::vector<PixelRect> cut_work_tiles(const PixelRect& area, int size);

struct WorkTile {
    Image8 pixels;  // the tile's own size, row 0 at its bottom
    std::uint64_t rays = 0;
    double seconds = 0.0;  // rendering it
};

// Renders the pixels of `tile` exactly as a render of the whole frame would,
// with the rank's local cores (oneTBB). Every tile of the rank shares the
// frame's view table, built by its first tile.
WorkTile render_work_tile(const PreparedFrame& frame, const PixelRect& tile);

}  // namespace jt::mpi
