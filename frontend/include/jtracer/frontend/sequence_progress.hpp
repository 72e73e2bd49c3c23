#pragma once
// Progress over a whole frame sequence, shown by the same ProgressDisplay as
// one render: the bar or log lines cover every frame, the pass name says
// which frame runs ("frame 3 of 48"), and the ETA is for the sequence.

#include "jtracer/render_job.hpp"

#include <string>

namespace jt::frontend {

// `frame`: the running frame's own progress; `done` frames of `total` are
// finished; `seconds` since the sequence started.
RenderProgress sequence_progress(const RenderProgress& frame, int done, int total, double seconds);

// The line that ends a sequence of `total` frames, `written` of them rendered
// and `kept` already there (--skip-existing), in `seconds`: "wrote 8 frames
// and kept 40 already there in 3 min 05 s\n", or "kept all 48 frames, already
// there (2 s)\n" when none was rendered. jtracer-cli and jtracer-mpi say it
// alike.
std::string sequence_summary(int total, int written, int kept, double seconds);

// What a sequence stopped before frame `index` leaves of frames `first` to
// index - 1, `kept` of them already there (--skip-existing) and the others
// written: "frames 0..3 were written", "frames 0..7 are there (4 written, 4
// kept)" or "frames 0..3 were kept, already there". Needs index > first.
std::string frames_there(int first, int index, int kept);

}  // namespace jt::frontend
