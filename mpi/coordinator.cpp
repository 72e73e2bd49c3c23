#include "coordinator.hpp"

#include "silence_watch.hpp"
#include "work_tiles.hpp"

#include "jtracer/region.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <future>
#include <thread>

namespace jt::mpi {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// A tile is handed out at most this many times: once, and once more to a rank
// left idle at the end of the frame (the first copy back wins; tiles render
// deterministically, so which one does not change a byte).
constexpr int max_copies = 2;
constexpr int no_tile = -1;

// A tile whose pixels are arriving, piece by piece.
struct ArrivingTile {
    std::int32_t tile = no_tile;  // none until its header is in
    TileResultHeader header;
    Image8 pixels;
    std::size_t bytes_in = 0;
};

struct WorkerState {
    std::deque<std::int32_t> held;  // handed out and not yet back, in the order it renders them
    bool stopped = false;           // it has acknowledged the stop
    // The message being received from it, if any: one at a time, in order.
    MPI_Request receiving = MPI_REQUEST_NULL;
    int receiving_tag = 0;
    int receiving_bytes = 0;
    TileResultHeader header_in;
    ArrivingTile arriving;
};

class Coordinator {
  public:
    Coordinator(const std::shared_ptr<const PreparedFrame>& frame, int width, int height,
                const std::vector<PixelRect>& tiles, const CoordinatorSettings& settings)
        : frame_(frame),
          frame_image_(width, height),
          tiles_(tiles),
          settings_(settings),
          workers_(static_cast<std::size_t>(settings.ranks)),
          watch_(settings.ranks, settings.rank_timeout),
          copies_(tiles.size(), 0),
          second_holder_(tiles.size(), no_tile),
          pasted_tile_(tiles.size(), false) {
        result_.rank_stats.resize(static_cast<std::size_t>(settings.ranks));
    }

    CoordinatorResult run(const std::function<bool()>& stop,
                          const std::function<bool(const Image8&)>& deliver) {
        start_ = Clock::now();
        for (int rank = 1; rank < settings_.ranks; ++rank)
            for (int i = 0; i < tiles_ahead; ++i) hand_out(rank);
        start_local_tile();
        auto last_shown = Clock::now();
        while (pasted_ < tiles_.size() && !stop() && !lost()) {
            serve_once();
            if (settings_.on_progress && seconds_since(last_shown) > 0.1) {
                settings_.on_progress(progress(seconds_since(start_)));
                last_shown = Clock::now();
            }
        }
        // Once more as it ends: a frame quicker than the interval still counts.
        if (settings_.on_progress) settings_.on_progress(progress(seconds_since(start_)));
        result_.seconds = seconds_since(start_);
        if (pasted_ < tiles_.size()) return std::move(result_);
        result_.complete = true;
        const bool delivered = deliver(frame_image_);
        result_.another_frame = settings_.another_frame && delivered && !stop();
        for (int rank = 1; rank < settings_.ranks; ++rank) send_stop(rank, result_.another_frame);
        winding_down_ = true;
        while (!all_stopped() && !lost()) serve_once();
        return std::move(result_);
    }

  private:
    std::shared_ptr<const PreparedFrame> frame_;
    Image8 frame_image_;
    const std::vector<PixelRect>& tiles_;
    CoordinatorSettings settings_;
    Clock::time_point start_;
    std::vector<WorkerState> workers_;  // index 0 (rank 0 itself) unused
    SilenceWatch watch_;
    std::vector<int> copies_;         // per tile: times handed out
    std::vector<int> second_holder_;  // per tile: the rank given its second copy
    std::vector<bool> pasted_tile_;
    std::size_t next_tile_ = 0;
    std::size_t pasted_ = 0;
    bool winding_down_ = false;  // the frame is in: the idle time no longer counts
    std::future<WorkTile> local_;
    std::int32_t local_tile_ = no_tile;
    RankStats stopped_stats_;  // where a worker's last message lands
    CoordinatorResult result_;

    void serve_once() {
        bool busy = collect_local_tile();
        for (int rank = 1; rank < settings_.ranks; ++rank) busy |= receive_from(rank);
        if (!busy) {
            if (winding_down_) {
                std::this_thread::sleep_for(std::chrono::microseconds(100));
                return;
            }
            const auto idle = Clock::now();
            std::this_thread::sleep_for(std::chrono::microseconds(100));
            result_.stats.wait_seconds += seconds_since(idle);
        }
    }

    bool holds(int rank, std::int32_t tile) const {
        if (rank == 0) return local_tile_ == tile;
        const auto& held = workers_[static_cast<std::size_t>(rank)].held;
        return std::find(held.begin(), held.end(), tile) != held.end();
    }

    // The next tile not yet handed out; once there is none, and only for a rank
    // with nothing left in hand, the oldest tile still out that no one holds
    // twice. (A rank still busy is not given more: if it is the slow one, the
    // copy would only be one more tile to wait for.)
    std::int32_t pick_tile(int rank) {
        if (next_tile_ < tiles_.size()) return static_cast<std::int32_t>(next_tile_++);
        if (rank != 0 && !workers_[static_cast<std::size_t>(rank)].held.empty()) return no_tile;
        for (std::size_t i = 0; i < tiles_.size(); ++i) {
            const auto tile = static_cast<std::int32_t>(i);
            if (!pasted_tile_[i] && copies_[i] < max_copies && !holds(rank, tile)) return tile;
        }
        return no_tile;
    }

    std::int32_t take_tile(int rank) {
        const std::int32_t tile = pick_tile(rank);
        if (tile == no_tile) return tile;
        const auto i = static_cast<std::size_t>(tile);
        if (++copies_[i] == max_copies) {
            second_holder_[i] = rank;
            ++result_.second_copies;
        }
        return tile;
    }

    void hand_out(int rank) {
        const std::int32_t tile = take_tile(rank);
        if (tile == no_tile) return;
        MPI_Send(&tile, 1, MPI_INT32_T, rank, tag_assign, MPI_COMM_WORLD);
        workers_[static_cast<std::size_t>(rank)].held.push_back(tile);
    }

    // Rank 0 renders a tile on a thread of its own whenever it has none, so
    // that its cores work too while this thread only answers messages.
    void start_local_tile() {
        local_tile_ = take_tile(0);
        if (local_tile_ == no_tile) return;
        local_ = std::async(std::launch::async,
                            [frame = frame_, rect = tiles_[static_cast<std::size_t>(local_tile_)]] {
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
        paste(local_tile_, 0, tile.pixels, tile.rays);
        start_local_tile();
        return true;
    }

    void paste(std::int32_t tile, int rank, const Image8& pixels, std::uint64_t rays) {
        const auto i = static_cast<std::size_t>(tile);
        if (pasted_tile_[i]) return;  // the other copy came back first
        const PixelRect& rect = tiles_[i];
        paste_image(frame_image_, pixels, rect.x0, rect.y0);
        pasted_tile_[i] = true;
        ++pasted_;
        result_.rays += rays;
        if (second_holder_[i] == rank) ++result_.second_copies_won;
    }

    // Takes in what `rank` has sent, without waiting: a message is received
    // with MPI_Irecv and tested on later calls, so that a transfer that stops
    // halfway leaves the worker silent rather than rank 0 blocked.
    bool receive_from(int rank) {
        WorkerState& worker = workers_[static_cast<std::size_t>(rank)];
        // What a stopped worker sends next is the next frame's hello.
        if (worker.stopped) return false;
        if (worker.receiving == MPI_REQUEST_NULL && !start_receiving(rank, worker)) return false;
        int done = 0;
        MPI_Test(&worker.receiving, &done, MPI_STATUS_IGNORE);
        if (!done) return false;
        watch_.heard(rank);
        const auto start = Clock::now();
        take_in(rank, worker);
        result_.stats.merge_seconds += seconds_since(start);
        return true;
    }

    bool start_receiving(int rank, WorkerState& worker) {
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(rank, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
        if (!arrived) return false;
        watch_.heard(rank);
        int bytes = 0;
        MPI_Get_count(&status, MPI_BYTE, &bytes);
        void* into = destination(worker, status.MPI_TAG, bytes);
        if (!into) abort_on_malformed_message(rank);
        worker.receiving_tag = status.MPI_TAG;
        worker.receiving_bytes = bytes;
        MPI_Irecv(into, bytes, MPI_BYTE, rank, status.MPI_TAG, MPI_COMM_WORLD, &worker.receiving);
        return true;
    }

    // Where a message of `bytes` with `tag` goes, or null when no such message is expected.
    void* destination(WorkerState& worker, int tag, int bytes) {
        const auto size = static_cast<std::size_t>(bytes);
        ArrivingTile& arriving = worker.arriving;
        if (tag == tag_heartbeat && size == 0) return &worker.header_in;
        if (tag == tag_stopped && size == sizeof(RankStats)) return &stopped_stats_;
        if (tag != tag_result) return nullptr;
        if (arriving.tile == no_tile)
            return size == sizeof(TileResultHeader) ? &worker.header_in : nullptr;
        if (size == 0 || arriving.bytes_in + size > arriving.pixels.rgb.size()) return nullptr;
        return arriving.pixels.rgb.data() + arriving.bytes_in;
    }

    void take_in(int rank, WorkerState& worker) {
        ArrivingTile& arriving = worker.arriving;
        if (worker.receiving_tag == tag_stopped) {
            result_.rank_stats[static_cast<std::size_t>(rank)] = stopped_stats_;
            worker.stopped = true;
            watch_.finished(rank);
            return;
        }
        if (worker.receiving_tag != tag_result) return;
        result_.bytes_received += static_cast<std::uint64_t>(worker.receiving_bytes);
        if (arriving.tile == no_tile) {
            const TileResultHeader& header = worker.header_in;
            if (std::find(worker.held.begin(), worker.held.end(), header.tile) ==
                worker.held.end()) {
                std::fprintf(stderr,
                             "jtracer-mpi: rank %d sent tile %d, which it was not given; nothing "
                             "was written\n",
                             rank, header.tile);
                MPI_Abort(MPI_COMM_WORLD, 3);
            }
            const PixelRect& rect = tiles_[static_cast<std::size_t>(header.tile)];
            arriving.tile = header.tile;
            arriving.header = header;
            arriving.pixels = Image8(rect.width(), rect.height());
            arriving.bytes_in = 0;
            return;
        }
        arriving.bytes_in += static_cast<std::size_t>(worker.receiving_bytes);
        if (arriving.bytes_in < arriving.pixels.rgb.size()) return;
        ++result_.tiles_received;
        worker.held.erase(std::find(worker.held.begin(), worker.held.end(), arriving.tile));
        if (pasted_ < tiles_.size()) hand_out(rank);  // first, so that the worker stays busy
        paste(arriving.tile, rank, arriving.pixels, arriving.header.rays);
        arriving.tile = no_tile;
    }

    // Records the first worker silent for longer than the timeout allows.
    bool lost() {
        result_.lost = watch_.lost();
        return result_.lost.has_value();
    }

    bool all_stopped() const {
        for (int rank = 1; rank < settings_.ranks; ++rank)
            if (!workers_[static_cast<std::size_t>(rank)].stopped) return false;
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
                                  int height, const std::vector<PixelRect>& tiles,
                                  const CoordinatorSettings& settings,
                                  const std::function<bool()>& stop,
                                  const std::function<bool(const Image8&)>& deliver) {
    return Coordinator(frame, width, height, tiles, settings).run(stop, deliver);
}

}  // namespace jt::mpi
