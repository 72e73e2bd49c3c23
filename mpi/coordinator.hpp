#pragma once
// Rank 0: hands out tiles on demand, renders tiles itself in between, pastes
// every result into the frame, and watches for ranks that stop answering.

#include "messages.hpp"
#include "silence_watch.hpp"

#include "jtracer/image.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/render_tile.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace jt::mpi {

struct CoordinatorSettings {
    int ranks = 1;  // counting rank 0
    // A worker silent this long (no tile, no heartbeat) is declared lost.
    double rank_timeout = 10.0;
    // Called about ten times a second, and once at the end, with the frame's progress; the caller
    // owns the display, so that one bar or log covers a whole sequence.
    std::function<void(const RenderProgress&)> on_progress;
    // A sequence has a frame after this one: the workers are told so when
    // they stop, unless delivering this frame failed or a stop was asked
    // for meanwhile (then they end as the frame does, rather than wait for a
    // frame that never comes).
    bool another_frame = false;
};

struct CoordinatorResult {
    bool complete = false;              // every tile came back (and `deliver` was called)
    bool another_frame = false;         // the workers were told that a frame follows
    std::optional<LostRank> lost;       // the worker that stopped answering, if one did
    std::uint64_t rays = 0;             // over all ranks
    std::uint64_t bytes_received = 0;   // tile messages from other ranks
    int tiles_received = 0;             // from other ranks
    int second_copies = 0;              // tiles handed out again once every tile was out
    int second_copies_won = 0;          // of those, the ones whose second copy came back first
    double seconds = 0.0;               // from the first tile handed out to the last pasted in
    RankStats stats;                    // rank 0's own
    std::vector<RankStats> rank_stats;  // every worker's, as it sent them when it stopped
};

// Renders `tiles` of a `width` x `height` frame over the job's ranks, every
// worker having said it is ready (roll_call.hpp); as soon
// as every tile is in, calls `deliver` with the frame (which says whether it
// went well), then tells the workers to stop and waits for each to say it has. Returns early,
// incomplete, when `stop` becomes true or a rank is lost; the workers are then still waiting and
// the caller must abort the job. `stop` is polled between the messages.
CoordinatorResult run_coordinator(const std::shared_ptr<const PreparedFrame>& frame, int width,
                                  int height, const std::vector<PixelRect>& tiles,
                                  const CoordinatorSettings& settings,
                                  const std::function<bool()>& stop,
                                  const std::function<bool(const Image8&)>& deliver);

}  // namespace jt::mpi
