#include "silence_watch.hpp"

namespace jt::mpi {

SilenceWatch::SilenceWatch(int ranks, double timeout)
    : timeout_(timeout),
      last_heard_(static_cast<std::size_t>(ranks), Clock::now()),
      finished_(static_cast<std::size_t>(ranks), false) {
    finished_.front() = true;  // rank 0 is the one watching
}

void SilenceWatch::heard(int rank) {
    last_heard_[static_cast<std::size_t>(rank)] = Clock::now();
}

void SilenceWatch::finished(int rank) {
    finished_[static_cast<std::size_t>(rank)] = true;
}

std::optional<LostRank> SilenceWatch::lost() const {
    const auto now = Clock::now();
    for (std::size_t rank = 0; rank < last_heard_.size(); ++rank) {
        if (finished_[rank]) continue;
        const double silence = std::chrono::duration<double>(now - last_heard_[rank]).count();
        if (silence > timeout_) return LostRank{static_cast<int>(rank), silence};
    }
    return std::nullopt;
}

}  // namespace jt::mpi
