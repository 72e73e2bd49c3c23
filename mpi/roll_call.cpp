#include "roll_call.hpp"

#include "messages.hpp"

#include <chrono>
#include <cstring>
#include <thread>

namespace jt::mpi {

RollCall call_the_roll(int ranks, const std::string& own_host, int own_exit_code,
                       double rank_timeout) {
    const auto count = static_cast<std::size_t>(ranks);
    RollCall call{std::vector<std::string>(count), std::vector<int>(count, 0),
                  std::vector<std::string>(count), std::nullopt};
    call.hosts[0] = own_host;
    call.exit_codes[0] = own_exit_code;
    std::vector<bool> ready(count, false);
    SilenceWatch watch(ranks, rank_timeout);
    for (int waiting = ranks - 1; waiting > 0;) {
        bool busy = false;
        for (int rank = 1; rank < ranks; ++rank) {
            const auto r = static_cast<std::size_t>(rank);
            // A worker that is ready only sends heartbeats until its first tile.
            int arrived = 0;
            MPI_Status status;
            MPI_Iprobe(rank, ready[r] ? tag_heartbeat : MPI_ANY_TAG, MPI_COMM_WORLD, &arrived,
                       &status);
            if (!arrived) continue;
            busy = true;
            watch.heard(rank);
            int bytes = 0;
            MPI_Get_count(&status, MPI_CHAR, &bytes);
            const int tag = status.MPI_TAG;
            const bool expected =
                (tag == tag_heartbeat && bytes == 0) ||
                (tag == tag_hello && bytes <= MPI_MAX_PROCESSOR_NAME) ||
                (tag == tag_ready && bytes >= static_cast<int>(sizeof(std::int32_t)) &&
                 bytes <= static_cast<int>(sizeof(std::int32_t)) + ready_message_bytes);
            if (!expected) abort_on_malformed_message(rank);
            // Within the eager limit: the whole message is in once probed, so
            // this receive does not wait.
            std::string text(static_cast<std::size_t>(bytes), '\0');
            MPI_Recv(text.data(), bytes, MPI_CHAR, rank, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (tag == tag_hello) call.hosts[r] = text;
            if (tag == tag_ready) {
                std::int32_t code = 0;
                std::memcpy(&code, text.data(), sizeof code);
                call.exit_codes[r] = code;
                call.messages[r] = text.substr(sizeof code);
                ready[r] = true;
                --waiting;
            }
        }
        if ((call.lost = watch.lost())) return call;
        if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return call;
}

}  // namespace jt::mpi
