#pragma once
// Rendering one frame tile by tile: the step below RenderJob. RenderJob's
// passes (whole frames and regions alike) and jtracer-mpi's ranks all render
// through it, so a tile's pixels are the same whoever renders it.
//
// A PreparedFrame is a prepared scene seen through one camera at one image
// size: the camera's view and the direction table of the shapes around the
// camera, which every primary ray reads. The table is built once per frame,
// by the first tile that traces full-resolution rays, and shared read-only by
// every tile and thread after it.

#include "jtracer/image.hpp"
#include "jtracer/render_job.hpp"

#include <cstdint>
#include <memory>

namespace jt {

struct PreparedFrame;  // defined in the core's private headers

// The frame `options` describes: width, height, camera, the samples a pixel
// gets from render_tile and the cores it uses (threads; previews and region do
// not matter here). `scene` must not be null (JT_DCHECK).
std::shared_ptr<const PreparedFrame> prepare_frame(std::shared_ptr<const PreparedScene> scene,
                                                   const RenderOptions& options);

struct RenderedTile {
    Image8 pixels;  // the tile's own size, row 0 at its bottom
    std::uint64_t rays = 0;
};

// The final pixels of `tile` (Image8 coordinates, clipped to the frame), every
// sample of each, exactly as a render of the whole frame has them, on the
// calling thread and the oneTBB pool (at most `threads` cores).
RenderedTile render_tile(const PreparedFrame& frame, const PixelRect& tile);

}  // namespace jt
