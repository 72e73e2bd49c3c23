#pragma once
// What the ranks say to each other. Before each frame rank 0 tells every worker
// which frame it is (tag_frame: an int32, the frame's index, -1 when none is
// left: no_more_frames), so that a frame rank 0 keeps (--skip-existing: its
// file is already there) is not even prepared by the workers. A worker then
// says tag_hello (its host name) first thing, so that rank 0 can name it from
// then on, and tag_ready once it has prepared the scene (an int32 exit code,
// then the set-up's message when it failed, at most ready_message_bytes of it).
// Rank 0 then sends a worker the index of its next tile (tag_assign); the
// worker answers with a TileResultHeader and then the tile's RGB bytes in
// pieces of at most result_piece_bytes, each a tag_result message. A worker is
// kept two tiles ahead, so that it never idles for a round trip. A worker that
// has been silent for heartbeat_seconds (preparing the scene, waiting, or
// rendering a long tile) sends an empty tag_heartbeat, so that rank 0 can tell
// a slow rank from a lost one. Once the frame is complete, or when a rank's
// set-up failed, rank 0 sends tag_stop (an int32: 1 when another frame of a
// sequence may follow, to be named by the next tag_frame, 0 when the job ends);
// the worker drops the tiles it still holds, assigned or still on their way,
// and answers tag_stopped with its RankStats, the last thing it sends for the
// frame. For the next frame of a sequence every worker starts again with
// tag_hello; messages between two ranks keep their order, so nothing of one
// frame is read as the next one's.
//
// Rank 0 never blocks on a worker: it receives with MPI_Iprobe / MPI_Irecv and
// no collective call is made, and a piece is small enough to cross a slow link
// well within the rank timeout, so a worker that stops answering at any point
// (before its hello, in its set-up, halfway through a tile) is a silence like
// any other.

#include <mpi.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace jt::mpi {

constexpr int tag_assign = 1;
constexpr int tag_result = 2;
constexpr int tag_heartbeat = 3;
constexpr int tag_stop = 4;
constexpr int tag_stopped = 5;
constexpr int tag_hello = 6;
constexpr int tag_ready = 7;
constexpr int tag_frame = 8;
// tag_frame's index when the job has no frame left: the worker ends.
constexpr std::int32_t no_more_frames = -1;
constexpr int tiles_ahead = 2;
constexpr double heartbeat_seconds = 1.0;
// 32 KiB: a quarter of a second at 1 Mbit/s, and within OpenMPI's eager limit.
constexpr int result_piece_bytes = 32 * 1024;
// Within the eager limit too: a worker's own set-up error is a few lines.
constexpr int ready_message_bytes = 8 * 1024;

struct TileResultHeader {
    std::int32_t tile = 0;
    std::int32_t reserved = 0;
    std::uint64_t rays = 0;
    double seconds = 0.0;  // the worker's time rendering it
};

// Per-rank figures, sent with tag_stopped, for --stats.
struct RankStats {
    double tiles = 0;
    double render_seconds = 0;  // rendering tiles
    double wait_seconds = 0;    // waiting for messages (workers: for work)
    double merge_seconds = 0;   // rank 0: receiving results and pasting them in
    double setup_seconds = 0;   // reading, validating and preparing the scene
};

// Sends a message without a payload.
inline void send_signal(int rank, int tag) {
    MPI_Send(nullptr, 0, MPI_BYTE, rank, tag, MPI_COMM_WORLD);
}

// Tells a worker which frame to set up next: `index`, or no_more_frames.
inline void send_frame(int rank, std::int32_t index) {
    MPI_Send(&index, 1, MPI_INT32_T, rank, tag_frame, MPI_COMM_WORLD);
}

// Tells a worker to stop the frame, and whether another one may follow.
inline void send_stop(int rank, bool another_frame) {
    const std::int32_t more = another_frame ? 1 : 0;
    MPI_Send(&more, 1, MPI_INT32_T, rank, tag_stop, MPI_COMM_WORLD);
}

// Rank 0, given a message no worker sends: names `rank` and aborts the job.
[[noreturn]] inline void abort_on_malformed_message(int rank) {
    std::fprintf(stderr, "jtracer-mpi: rank %d sent a malformed message; nothing was written\n",
                 rank);
    MPI_Abort(MPI_COMM_WORLD, 3);
    std::abort();  // MPI_Abort does not return
}

}  // namespace jt::mpi
