#pragma once
// What the ranks say to each other. Rank 0 sends a worker the index of its
// next tile (tag_assign; no_more_tiles to stop); the worker answers with a
// TileResultHeader followed by the tile's RGB bytes (tag_result). A worker is
// kept two tiles ahead, so that it never idles for a round trip.

#include <mpi.h>

#include <cstdint>

namespace jt::mpi {

constexpr int tag_assign = 1;
constexpr int tag_result = 2;
constexpr std::int32_t no_more_tiles = -1;
constexpr int tiles_ahead = 2;

struct TileResultHeader {
    std::int32_t tile = 0;
    std::int32_t reserved = 0;
    std::uint64_t rays = 0;
    double seconds = 0.0;  // the worker's time rendering it
};

// Per-rank figures gathered at the end for --stats.
struct RankStats {
    double tiles = 0;
    double render_seconds = 0;  // rendering tiles
    double wait_seconds = 0;    // waiting for messages (workers: for work)
    double merge_seconds = 0;   // rank 0: receiving results and pasting them in
    double setup_seconds = 0;   // reading, validating and preparing the scene
};

// Waits for a message from `source` with `tag` by probing and sleeping briefly:
// OpenMPI's blocking calls spin, which would take a core from the renderer on
// a shared machine. Returns the time spent waiting.
double wait_for_message(int source, int tag, MPI_Status& status);

}  // namespace jt::mpi
