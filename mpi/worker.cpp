#include "worker.hpp"

#include "work_tiles.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <future>
#include <optional>
#include <string>
#include <thread>

namespace jt::mpi {

namespace {

using Clock = std::chrono::steady_clock;

// For the tests only: true when the environment variable `name` holds this
// rank's number.
bool test_hook_names_me(const char* name) {
    const char* rank_text = std::getenv(name);
    if (!rank_text) return false;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return std::to_string(rank) == rank_text;
}

// JT_MPI_TEST_ABORT_RANK=N makes rank N die after rendering its first tile,
// before sending it, as a crashed machine would.
bool told_to_die() {
    return test_hook_names_me("JT_MPI_TEST_ABORT_RANK");
}

// JT_MPI_TEST_SLOW_SETUP_RANK=N makes rank N's set-up take a minute longer, as
// a machine reading a big model from a slow share would (it keeps answering).
constexpr auto slow_setup_delay = std::chrono::seconds(60);
bool told_to_set_up_slowly() {
    return test_hook_names_me("JT_MPI_TEST_SLOW_SETUP_RANK");
}

// Works on a thread of its own while the rank's main thread (the only one that
// calls MPI) keeps rank 0 told that this rank is alive.
class Worker {
    // Runs `job` on a thread of its own, saying meanwhile that this rank is alive.
    template <class Job>
    auto keeping_alive(Job job) {
        auto done = std::async(std::launch::async, std::move(job));
        while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready)
            keep_alive();
        return done.get();
    }

  public:
    int run(const std::string& host, const std::function<RankSetUp()>& set_up,
            bool& another_frame) {
        MPI_Send(host.data(), static_cast<int>(host.size()), MPI_CHAR, 0, tag_hello,
                 MPI_COMM_WORLD);
        last_said_ = Clock::now();
        const auto start = Clock::now();
        const bool slowly = told_to_set_up_slowly();
        set_up_ = keeping_alive([&] {
            if (slowly) std::this_thread::sleep_for(slow_setup_delay);
            return set_up();
        });
        stats_.setup_seconds = std::chrono::duration<double>(Clock::now() - start).count();
        say_ready();
        render_until_stopped();
        drop_late_assignments();
        MPI_Send(&stats_, sizeof stats_, MPI_BYTE, 0, tag_stopped, MPI_COMM_WORLD);
        another_frame = another_frame_;
        return set_up_.exit_code;
    }

  private:
    RankSetUp set_up_;
    RankStats stats_;
    Clock::time_point last_said_;
    bool stopped_ = false;
    bool another_frame_ = false;  // what the stop said

    void say(int tag) {
        send_signal(0, tag);
        last_said_ = Clock::now();
    }

    void keep_alive() {
        if (std::chrono::duration<double>(Clock::now() - last_said_).count() >= heartbeat_seconds)
            say(tag_heartbeat);
    }

    void say_ready() {
        std::string verdict(sizeof(std::int32_t), '\0');
        const std::int32_t code = set_up_.exit_code;
        std::memcpy(verdict.data(), &code, sizeof code);
        if (code != 0) verdict += set_up_.message.substr(0, ready_message_bytes);
        MPI_Send(verdict.data(), static_cast<int>(verdict.size()), MPI_CHAR, 0, tag_ready,
                 MPI_COMM_WORLD);
        last_said_ = Clock::now();
    }

    // Rank 0 hands out no tile once a set-up failed: a rank without a frame
    // only waits for the stop.
    void render_until_stopped() {
        const bool die = told_to_die();
        while (true) {
            const auto waiting = Clock::now();
            const std::optional<std::int32_t> index = next_assignment();
            stats_.wait_seconds += std::chrono::duration<double>(Clock::now() - waiting).count();
            if (!index || !set_up_.frame) return;
            const PixelRect rect = set_up_.tiles[static_cast<std::size_t>(*index)];
            WorkTile tile = keeping_alive([&] { return render_work_tile(*set_up_.frame, rect); });
            if (die) std::abort();
            stats_.tiles += 1;
            stats_.render_seconds += tile.seconds;
            // Rank 0 may have had this tile from another rank meanwhile.
            if (stop_arrived()) return;
            send_result(*index, tile);
        }
    }

    bool stop_arrived() {
        if (stopped_) return true;
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(0, tag_stop, MPI_COMM_WORLD, &arrived, &status);
        if (arrived) {
            std::int32_t more = 0;
            MPI_Recv(&more, 1, MPI_INT32_T, 0, tag_stop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            another_frame_ = more != 0;
            stopped_ = true;
        }
        return stopped_;
    }

    // Tiles handed out before the stop that this rank never took (another
    // rank's copy came back first): gone before the next frame's tiles come,
    // and all here, since rank 0 sent them before the stop.
    void drop_late_assignments() {
        while (true) {
            int arrived = 0;
            MPI_Iprobe(0, tag_assign, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
            if (!arrived) return;
            std::int32_t index = 0;
            MPI_Recv(&index, 1, MPI_INT32_T, 0, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        }
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
                if (index >= 0 && index < static_cast<std::int32_t>(set_up_.tiles.size()))
                    return index;
            } else if (arrived && stop_arrived()) {
                return std::nullopt;
            }
            keep_alive();
            if (!arrived) std::this_thread::sleep_for(std::chrono::microseconds(100));
        }
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

int run_worker(const std::string& host, const std::function<RankSetUp()>& set_up,
               bool& another_frame) {
    return Worker().run(host, set_up, another_frame);
}

// How often a worker between frames looks for the next one: rank 0 may take
// long to set a frame up or to write one, and a millisecond's wait is nothing
// beside a frame while it leaves the cores to others.
constexpr auto frame_index_poll = std::chrono::milliseconds(1);

std::int32_t receive_frame_index() {
    while (true) {
        int arrived = 0;
        MPI_Iprobe(0, tag_frame, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
        if (arrived) {
            std::int32_t index = no_more_frames;
            MPI_Recv(&index, 1, MPI_INT32_T, 0, tag_frame, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            return index;
        }
        std::this_thread::sleep_for(frame_index_poll);
    }
}

}  // namespace jt::mpi
