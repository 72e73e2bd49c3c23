#pragma once
// A rank other than 0: renders the tiles rank 0 hands it until told to stop.

#include "messages.hpp"

#include "jtracer/render_job.hpp"

#include <memory>
#include <vector>

namespace jt::mpi {

RankStats run_worker(const std::shared_ptr<const PreparedScene>& scene, const RenderOptions& frame,
                     const std::vector<PixelRect>& tiles);

}  // namespace jt::mpi
