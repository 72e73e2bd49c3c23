#include "worker.hpp"

#include "work_tiles.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <future>
#include <optional>
#include <string>
#include <thread>

namespace jt::mpi {

namespace {

using Clock = std::chrono::steady_clock;

// For the tests only: JT_MPI_TEST_ABORT_RANK=N makes rank N die after
// rendering its first tile, before sending it, as a crashed machine would.
bool told_to_die() {
    const char* rank_text = std::getenv("JT_MPI_TEST_ABORT_RANK");
    if (!rank_text) return false;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return std::to_string(rank) == rank_text;
}

// Renders on a thread of its own while the rank's main thread (the only one
// that calls MPI) keeps rank 0 told that this rank is alive.
class Worker {
  public:
    Worker(const PreparedFrame& frame, const std::vector<PixelRect>& tiles, double setup_seconds)
        : frame_(frame), tiles_(tiles) {
        stats_.setup_seconds = setup_seconds;
    }

    void run() {
        const bool die = told_to_die();
        say(tag_heartbeat);  // ready: rank 0 starts listening for this rank's silence
        while (true) {
            const auto waiting = Clock::now();
            const std::optional<std::int32_t> index = next_assignment();
            stats_.wait_seconds += std::chrono::duration<double>(Clock::now() - waiting).count();
            if (!index) break;
            WorkTile tile = render(tiles_[static_cast<std::size_t>(*index)]);
            if (die) std::abort();
            stats_.tiles += 1;
            stats_.render_seconds += tile.seconds;
            // Rank 0 may have had this tile from another rank meanwhile.
            if (stop_arrived()) break;
            send_result(*index, tile);
        }
        MPI_Send(&stats_, sizeof stats_, MPI_BYTE, 0, tag_stopped, MPI_COMM_WORLD);
    }

  private:
    const PreparedFrame& frame_;
    const std::vector<PixelRect>& tiles_;
    RankStats stats_;
    Clock::time_point last_said_;
    bool stopped_ = false;

    void say(int tag) {
        send_signal(0, tag);
        last_said_ = Clock::now();
    }

    void keep_alive() {
        if (std::chrono::duration<double>(Clock::now() - last_said_).count() >= heartbeat_seconds)
            say(tag_heartbeat);
    }

    bool stop_arrived() {
        if (stopped_) return true;
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(0, tag_stop, MPI_COMM_WORLD, &arrived, &status);
        if (arrived) {
            MPI_Recv(nullptr, 0, MPI_BYTE, 0, tag_stop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            stopped_ = true;
        }
        return stopped_;
    }

    // The next tile index, or nothing once rank 0 says stop. Probes and sleeps
    // briefly rather than blocking: OpenMPI's blocking calls spin, which would
    // take a core from the renderer on a shared machine.
    std::optional<std::int32_t> next_assignment() {
        while (true) {
            int arrived = 0;
            MPI_Status status;
            MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
            if (arrived && status.MPI_TAG == tag_assign) {
                std::int32_t index = 0;
                MPI_Recv(&index, 1, MPI_INT32_T, 0, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                if (index >= 0 && index < static_cast<std::int32_t>(tiles_.size())) return index;
            } else if (arrived && stop_arrived()) {
                return std::nullopt;
            }
            keep_alive();
            if (!arrived) std::this_thread::sleep_for(std::chrono::microseconds(100));
        }
    }

    WorkTile render(const PixelRect& rect) {
        std::future<WorkTile> job =
            std::async(std::launch::async, [this, rect] { return render_work_tile(frame_, rect); });
        while (job.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready)
            keep_alive();
        return job.get();
    }

    void send_result(std::int32_t index, const WorkTile& tile) {
        TileResultHeader header{index, 0, tile.rays, tile.seconds};
        MPI_Send(&header, sizeof header, MPI_BYTE, 0, tag_result, MPI_COMM_WORLD);
        const std::vector<std::uint8_t>& rgb = tile.pixels.rgb;
        for (std::size_t at = 0; at < rgb.size(); at += result_piece_bytes) {
            const std::size_t piece = std::min<std::size_t>(result_piece_bytes, rgb.size() - at);
            MPI_Send(rgb.data() + at, static_cast<int>(piece), MPI_BYTE, 0, tag_result,
                     MPI_COMM_WORLD);
        }
        last_said_ = Clock::now();
    }
};

}  // namespace

void run_worker(const PreparedFrame& frame, const std::vector<PixelRect>& tiles,
                double setup_seconds) {
    Worker(frame, tiles, setup_seconds).run();
}

}  // namespace jt::mpi
