#pragma once
// Rank 0: hands out tiles on demand, renders tiles itself in between, and
// pastes every result into the frame.

#include "messages.hpp"

#include "jtracer/frontend/progress.hpp"
#include "jtracer/image.hpp"
#include "jtracer/render_tile.hpp"

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace jt::mpi {

struct CoordinatorResult {
    bool complete = false;  // false: stopped by `stop` before every tile came back
    Image8 frame;
    std::uint64_t rays = 0;            // over all ranks
    std::uint64_t bytes_received = 0;  // tile messages from other ranks
    int messages_received = 0;
    double seconds = 0.0;  // from the first tile handed out to the last pasted in
    RankStats stats;       // rank 0's own
};

// `frame` is `width` x `height` pixels; `ranks` counts rank 0. Returns early,
// incomplete, when `stop` becomes true; the workers are then still waiting and
// the caller must abort the job.
CoordinatorResult run_coordinator(const std::shared_ptr<const PreparedFrame>& frame, int width,
                                  int height, const std::vector<PixelRect>& tiles, int ranks,
                                  const std::atomic<bool>& stop, frontend::ProgressStyle progress);

}  // namespace jt::mpi
