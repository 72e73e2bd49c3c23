#pragma once
// Rank 0's view of which workers still answer: when each was last heard from,
// and the first one silent for longer than the rank timeout allows. The same
// watch covers every phase in which rank 0 waits for a worker (its set-up, its
// tiles, its stop), so that a host that drops off the network at any point
// ends the run.

#include <chrono>
#include <optional>
#include <vector>

namespace jt::mpi {

struct LostRank {
    int rank = 0;
    double silence = 0.0;  // seconds since it was last heard from
};

class SilenceWatch {
  public:
    // Silence counts from now for every worker (ranks 1 to ranks - 1).
    SilenceWatch(int ranks, double timeout);

    void heard(int rank);
    // It has said its last word: its silence no longer counts.
    void finished(int rank);
    std::optional<LostRank> lost() const;

  private:
    using Clock = std::chrono::steady_clock;
    double timeout_;
    std::vector<Clock::time_point> last_heard_;
    std::vector<bool> finished_;
};

}  // namespace jt::mpi
