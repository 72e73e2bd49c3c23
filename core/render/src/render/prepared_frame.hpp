#pragma once
// What render_tile.hpp's PreparedFrame holds, and the one routine that traces
// the rays of one pass over one tile, for RenderJob and render_tile alike.

#include "jtracer/render_tile.hpp"

#include "render/camera_rays.hpp"
#include "render/render_passes.hpp"
#include "render/view_table.hpp"

#include <atomic>
#include <mutex>
#include <vector>

namespace jt {

// A tile is cut from the frame as squares of tile_blocks x tile_blocks rays.
inline constexpr int tile_blocks = 32;

struct PreparedFrame {
    std::shared_ptr<const PreparedScene> scene;
    RenderOptions options;  // as frame_options leaves them
    CameraFrame camera;

    // The shapes each block of the image may see first. Built on first use,
    // not with the frame: previews trace a few rays a block, for which the
    // table (milliseconds for thousands of shapes) would cost more than it
    // saves. Call it before a parallel loop over tiles, never inside one: a
    // worker that waited inside it for the once_flag could be handed another
    // tile's wait.
    const ViewTable& view_table() const;

  private:
    mutable std::once_flag table_built_;
    mutable ViewTable table_;
};

// `options` as a frame renders them: samples clamped to kMinSamples..kMaxSamples, sizes to >= 0.
RenderOptions frame_options(RenderOptions options);

// The quantized pixels of one tile, row by row, and the running sum of each
// pixel's clamped samples when the frame takes more than one sample.
struct TileBuffer {
    PixelRect rect;
    std::vector<std::uint8_t> rgb;
    std::vector<Colour> sums;

    explicit TileBuffer(const PixelRect& r)
        : rect(r), rgb(static_cast<std::size_t>(r.width()) * r.height() * 3) {}
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y - rect.y0) * static_cast<std::size_t>(rect.width()) +
               static_cast<std::size_t>(x - rect.x0);
    }
};

// Traces `pass` over `out.rect`: one ray a block for a preview, else samples
// [sample_begin, sample_end) of each pixel, added in index order to out.sums
// (which hold the earlier samples' sums when sample_begin > 0). The camera
// table must be built when the pass is at full resolution. Returns false when
// `cancel` became true part way (`out` is then incomplete).
bool trace_tile(const PreparedFrame& frame, const RenderPass& pass, TileBuffer& out,
                const std::atomic<bool>& cancel, std::uint64_t& rays);

}  // namespace jt
