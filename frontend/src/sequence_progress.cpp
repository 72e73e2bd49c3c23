#include "jtracer/frontend/sequence_progress.hpp"

#include <string>

namespace jt::frontend {

RenderProgress sequence_progress(const RenderProgress& frame, int done, int total, double seconds) {
    RenderProgress whole = frame;
    const double frames = total > 0 ? static_cast<double>(total) : 1.0;
    whole.fraction = (static_cast<double>(done) + frame.fraction) / frames;
    whole.seconds = seconds;
    whole.pass_name = "frame " + std::to_string(done + 1) + " of " + std::to_string(total);
    whole.finished = frame.finished && done + 1 == total;
    return whole;
}

}  // namespace jt::frontend
