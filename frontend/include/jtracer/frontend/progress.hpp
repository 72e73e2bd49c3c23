#pragma once
// What the command-line renderers show while they render: a bar with an ETA
// on a terminal, nothing otherwise unless asked (--progress log: a plain line
// per 10% for a farm's log), nothing when quiet.

#include "jtracer/region.hpp"
#include "jtracer/render_job.hpp"

#include <cstdio>
#include <optional>
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

// The log style writes "rendering: 30% (1.52 s)" when the render passes a
// multiple of 10% (below 100%, after its first second): always a multiple of
// 10, each at most once, rising. A jump past several (80% to 97%) writes one
// line, for the highest passed (90%), so the lines name the milestones a log
// reader greps for, never the odd percentage the jump happened to land on.
class ProgressDisplay {
  public:
    explicit ProgressDisplay(ProgressStyle style, std::FILE* out = stderr)
        : style_(style), out_(out) {}
    void update(const RenderProgress& progress);
    // Clears the bar so that what follows starts on a clean line.
    void finish();

  private:
    ProgressStyle style_;
    std::FILE* out_;
    bool drawn_ = false;
    int last_logged_percent_ = 0;
    double last_logged_seconds_ = 0.0;
};

// "1.23 s", "4 min 05 s", "2 h 04 min 05 s"
std::string format_duration(double seconds);

// "800x450, 1 sample, 0.84 s, 1.97 M rays, 2.35 Mrays/s"; for a region of the
// frame "80x50 (region 40,20,120,70 of 160x90), ...": the pixels rendered.
std::string render_summary(int width, int height, int samples, const RenderProgress& progress,
                           const std::optional<FrameRegion>& region = std::nullopt);

}  // namespace jt::frontend
