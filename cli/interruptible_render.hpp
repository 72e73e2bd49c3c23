#pragma once
// Runs a render job while drawing its progress and watching for Ctrl-C,
// SIGTERM and SIGHUP, which cancel it (within a tile) instead of ending the process.

#include "jtracer/frontend/progress.hpp"
#include "jtracer/render_job.hpp"

#include <functional>

namespace jt::cli {

// From now on SIGINT, SIGTERM and SIGHUP cancel the running render (and a
// write under way is finished first); one ignored on entry stays ignored.
void catch_interrupts();

// The signal that asked to stop (SIGINT, SIGTERM, SIGHUP), 0 while none has.
int interrupting_signal();

// Maps a job's progress to what the display shows (a sequence shows its own).
using ProgressView = std::function<RenderProgress(const RenderProgress&)>;

// Runs `job` on a thread of its own while this one updates `display` and
// cancels the job on a signal. Returns false when it was cancelled.
bool render_interruptibly(RenderJob& job, frontend::ProgressDisplay& display,
                          const ProgressView& view = {});

// "jtracer-cli: interrupted by SIGINT; WHAT\n", and the exit code for it.
int report_interrupt(const char* what);

}  // namespace jt::cli
