#include "coordinator.hpp"

#include "jtracer/frontend/progress.hpp"
#include "work_tiles.hpp"

#include "jtracer/region.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <future>
#include <thread>

namespace jt::mpi {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

class Coordinator {
  public:
    Coordinator(const std::shared_ptr<const PreparedFrame>& frame, int width, int height,
                const std::vector<PixelRect>& tiles, int ranks)
        : frame_(frame), tiles_(tiles), ranks_(ranks) {
        result_.frame = Image8(width, height);
    }

    CoordinatorResult run(const std::atomic<bool>& stop, frontend::ProgressStyle progress_style) {
        const auto start = Clock::now();
        frontend::ProgressDisplay display(progress_style);
        for (int rank = 1; rank < ranks_; ++rank)
            for (int i = 0; i < tiles_ahead; ++i) hand_out(rank);
        start_local_tile();
        auto last_shown = Clock::now();
        while (pasted_ < tiles_.size()) {
            if (stop.load()) break;
            bool busy = receive_one() | collect_local_tile();
            if (!busy) {
                const auto idle = Clock::now();
                std::this_thread::sleep_for(std::chrono::microseconds(100));
                result_.stats.wait_seconds += seconds_since(idle);
            }
            if (seconds_since(last_shown) > 0.1) {
                display.update(progress(seconds_since(start)));
                last_shown = Clock::now();
            }
        }
        display.finish();
        result_.seconds = seconds_since(start);
        result_.complete = pasted_ == tiles_.size();
        if (result_.complete)
            for (int rank = 1; rank < ranks_; ++rank) send_tile_index(rank, no_more_tiles);
        else if (local_.valid())
            local_.wait();  // its thread must not outlive the frame it renders for
        return std::move(result_);
    }

  private:
    std::shared_ptr<const PreparedFrame> frame_;
    const std::vector<PixelRect>& tiles_;
    int ranks_;
    std::size_t next_tile_ = 0;
    std::size_t pasted_ = 0;
    std::future<WorkTile> local_;
    PixelRect local_rect_;
    std::vector<std::uint8_t> message_;
    CoordinatorResult result_;

    void send_tile_index(int rank, std::int32_t index) {
        MPI_Send(&index, 1, MPI_INT32_T, rank, tag_assign, MPI_COMM_WORLD);
    }

    void hand_out(int rank) {
        if (next_tile_ < tiles_.size())
            send_tile_index(rank, static_cast<std::int32_t>(next_tile_++));
    }

    // Rank 0 renders a tile on a thread of its own whenever it has none, so
    // that its cores work too while this thread only answers messages.
    void start_local_tile() {
        if (next_tile_ >= tiles_.size()) return;
        local_rect_ = tiles_[next_tile_++];
        local_ = std::async(std::launch::async, [frame = frame_, rect = local_rect_] {
            return render_work_tile(*frame, rect);
        });
    }

    bool collect_local_tile() {
        if (!local_.valid() ||
            local_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
            return false;
        WorkTile tile = local_.get();
        result_.stats.tiles += 1;
        result_.stats.render_seconds += tile.seconds;
        result_.rays += tile.rays;
        paste_image(result_.frame, tile.pixels, local_rect_.x0, local_rect_.y0);
        ++pasted_;
        start_local_tile();
        return true;
    }

    bool receive_one() {
        if (ranks_ < 2) return false;
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, tag_result, MPI_COMM_WORLD, &arrived, &status);
        if (!arrived) return false;
        const auto start = Clock::now();
        int bytes = 0;
        MPI_Get_count(&status, MPI_BYTE, &bytes);
        message_.resize(static_cast<std::size_t>(bytes));
        MPI_Recv(message_.data(), bytes, MPI_BYTE, status.MPI_SOURCE, tag_result, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        hand_out(status.MPI_SOURCE);  // first, so that the worker stays busy
        TileResultHeader header;
        if (message_.size() >= sizeof header) std::memcpy(&header, message_.data(), sizeof header);
        const bool known = message_.size() >= sizeof header && header.tile >= 0 &&
                           static_cast<std::size_t>(header.tile) < tiles_.size();
        const PixelRect rect = known ? tiles_[static_cast<std::size_t>(header.tile)] : PixelRect{};
        Image8 pixels(rect.width(), rect.height());
        if (!known || message_.size() != sizeof header + pixels.rgb.size()) {
            std::fprintf(stderr,
                         "jtracer-mpi: rank %d sent a malformed tile; nothing was written\n",
                         status.MPI_SOURCE);
            MPI_Abort(MPI_COMM_WORLD, 3);
        }
        std::memcpy(pixels.rgb.data(), message_.data() + sizeof header, pixels.rgb.size());
        paste_image(result_.frame, pixels, rect.x0, rect.y0);
        result_.rays += header.rays;
        result_.bytes_received += message_.size();
        ++result_.messages_received;
        ++pasted_;
        result_.stats.merge_seconds += seconds_since(start);
        return true;
    }

    RenderProgress progress(double seconds) const {
        RenderProgress p;
        p.pass_name = std::to_string(pasted_) + "/" + std::to_string(tiles_.size()) + " tiles";
        p.fraction = static_cast<double>(pasted_) / static_cast<double>(tiles_.size());
        p.rays = result_.rays;
        p.seconds = seconds;
        return p;
    }
};

}  // namespace

CoordinatorResult run_coordinator(const std::shared_ptr<const PreparedFrame>& frame, int width,
                                  int height, const std::vector<PixelRect>& tiles, int ranks,
                                  const std::atomic<bool>& stop, frontend::ProgressStyle progress) {
    return Coordinator(frame, width, height, tiles, ranks).run(stop, progress);
}

}  // namespace jt::mpi
