#pragma once
// A rank other than 0. It says hello (its host name) first thing, prepares the
// scene while telling rank 0 every heartbeat_seconds that it is alive, says
// whether that worked (tag_ready), then renders the tiles rank 0 hands it
// until told to stop.

#include "messages.hpp"

#include "jtracer/render_tile.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace jt::mpi {

// What a rank's set-up gives it.
struct RankSetUp {
    std::shared_ptr<const PreparedFrame> frame;  // null when the set-up failed
    std::vector<PixelRect> tiles;
    int exit_code = 0;
    std::string message;  // the set-up's report: diagnostics, or why it failed
};

// Runs `set_up` on a thread of its own, then the tiles of one frame; returns
// the rank's exit code. Its figures go to rank 0 with its last message.
// `another_frame` is set when rank 0's stop said that a frame may follow.
int run_worker(const std::string& host, const std::function<RankSetUp()>& set_up,
               bool& another_frame);

// The index of the frame rank 0 names next (tag_frame), or no_more_frames.
// Waits without spinning: the rank's cores may be rendering for other jobs.
std::int32_t receive_frame_index();

}  // namespace jt::mpi
