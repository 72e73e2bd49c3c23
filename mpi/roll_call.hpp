#pragma once
// Rank 0, before the frame: every worker's hello (its host name) and set-up
// verdict (tag_ready), taken in without blocking, so that a worker whose host
// drops off the network before or during its set-up is named within the rank
// timeout instead of leaving rank 0 waiting for good.

#include "silence_watch.hpp"

#include <optional>
#include <string>
#include <vector>

namespace jt::mpi {

struct RollCall {
    std::vector<std::string> hosts;     // per rank; empty for a worker never heard from
    std::vector<int> exit_codes;        // per rank: its set-up's
    std::vector<std::string> messages;  // per worker: why its set-up failed
    std::optional<LostRank> lost;       // the first worker that stopped answering
};

// Waits until every worker is ready or one has been silent (not even a
// heartbeat) for `rank_timeout` seconds.
RollCall call_the_roll(int ranks, const std::string& own_host, int own_exit_code,
                       double rank_timeout);

}  // namespace jt::mpi
