#include "worker.hpp"

#include "work_tiles.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

namespace jt::mpi {

namespace {

// For the tests only: JT_MPI_TEST_ABORT_RANK=N makes rank N die after
// rendering its first tile, before sending it, as a crashed machine would.
bool told_to_die() {
    const char* rank_text = std::getenv("JT_MPI_TEST_ABORT_RANK");
    if (!rank_text) return false;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return std::to_string(rank) == rank_text;
}

}  // namespace

RankStats run_worker(const PreparedFrame& frame, const std::vector<PixelRect>& tiles) {
    RankStats stats;
    const bool die = told_to_die();
    std::vector<std::uint8_t> message;
    while (true) {
        MPI_Status status;
        stats.wait_seconds += wait_for_message(0, tag_assign, status);
        std::int32_t index = no_more_tiles;
        MPI_Recv(&index, 1, MPI_INT32_T, 0, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (index < 0 || index >= static_cast<std::int32_t>(tiles.size())) break;
        WorkTile tile = render_work_tile(frame, tiles[static_cast<std::size_t>(index)]);
        if (die) std::abort();
        stats.tiles += 1;
        stats.render_seconds += tile.seconds;
        TileResultHeader header{index, 0, tile.rays, tile.seconds};
        message.resize(sizeof header + tile.pixels.rgb.size());
        std::memcpy(message.data(), &header, sizeof header);
        std::memcpy(message.data() + sizeof header, tile.pixels.rgb.data(), tile.pixels.rgb.size());
        MPI_Send(message.data(), static_cast<int>(message.size()), MPI_BYTE, 0, tag_result,
                 MPI_COMM_WORLD);
    }
    return stats;
}

}  // namespace jt::mpi
