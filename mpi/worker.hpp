#pragma once
// A rank other than 0: renders the tiles rank 0 hands it until told to stop.

#include "messages.hpp"

#include "jtracer/render_tile.hpp"

#include <memory>
#include <vector>

namespace jt::mpi {

RankStats run_worker(const PreparedFrame& frame, const std::vector<PixelRect>& tiles);

}  // namespace jt::mpi
