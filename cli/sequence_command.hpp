#pragma once
// jtracer-cli --frames N: the frames of a sequence, one image each
// (docs/language.md §15.4). The frames' set-up is frontend/'s SceneSequence;
// this renders and writes them, with one progress display for the sequence.

#include "options.hpp"

namespace jt::cli {

// Renders the frames of o.frames (o.frame_range of them); returns the exit
// code. Frames written before a failure stay.
int run_sequence(const Options& o);

}  // namespace jt::cli
