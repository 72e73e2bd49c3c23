#pragma once
// What the command-line renderers show while they render: a bar with an ETA
// on a terminal, nothing otherwise unless asked (--progress log: a plain line
// per 10% for a farm's log), nothing when quiet.

#include "jtracer/render_job.hpp"

#include <string>

namespace jt::frontend {

// --progress: auto (a bar on a terminal, nothing otherwise), bar, log, none.
enum class ProgressMode { automatic, bar, log, none };
enum class ProgressStyle { none, bar, log };

// The style a render shows: -q silences it; `auto` draws the bar only when
// stderr is a terminal, so scripts and CI logs stay clean.
ProgressStyle progress_style(ProgressMode mode, bool quiet, bool stderr_is_terminal);

// progress_style() for this process's stderr.
ProgressStyle progress_style_for_stderr(ProgressMode mode, bool quiet);

class ProgressDisplay {
  public:
    explicit ProgressDisplay(ProgressStyle style) : style_(style) {}
    void update(const RenderProgress& progress);
    // Clears the bar so that what follows starts on a clean line.
    void finish();

  private:
    ProgressStyle style_;
    bool drawn_ = false;
    int last_logged_percent_ = 0;
};

// "1.23 s", "4 min 05 s"
std::string format_duration(double seconds);

// "800x450, 1 sample, 0.84 s, 1.97 M rays, 2.35 Mrays/s"
std::string render_summary(int width, int height, int samples, const RenderProgress& progress);

}  // namespace jt::frontend
