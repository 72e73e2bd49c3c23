#pragma once
// A rank other than 0: renders the tiles rank 0 hands it until told to stop.

#include "messages.hpp"

#include "jtracer/render_tile.hpp"

#include <memory>
#include <vector>

namespace jt::mpi {

// Its figures, with `setup_seconds` (how long it took to prepare the scene), go
// to rank 0 with its last message.
void run_worker(const PreparedFrame& frame, const std::vector<PixelRect>& tiles,
                double setup_seconds);

}  // namespace jt::mpi
