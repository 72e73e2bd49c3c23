#pragma once
// Progress over a whole frame sequence, shown by the same ProgressDisplay as
// one render: the bar or log lines cover every frame, the pass name says
// which frame runs ("frame 3 of 48"), and the ETA is for the sequence.

#include "jtracer/render_job.hpp"

namespace jt::frontend {

// `frame`: the running frame's own progress; `done` frames of `total` are
// finished; `seconds` since the sequence started.
RenderProgress sequence_progress(const RenderProgress& frame, int done, int total, double seconds);

}  // namespace jt::frontend
