#pragma once
// What the command-line renderers show while they render: a bar with an ETA
// on a terminal, occasional plain lines in a log, nothing when quiet.

#include "jtracer/render_job.hpp"

#include <string>

namespace jt::frontend {

class ProgressDisplay {
  public:
    ProgressDisplay(bool quiet, bool terminal) : quiet_(quiet), terminal_(terminal) {}
    void update(const RenderProgress& progress);
    // Clears the bar so that what follows starts on a clean line.
    void finish();

  private:
    bool quiet_;
    bool terminal_;
    bool drawn_ = false;
    int last_logged_percent_ = 0;
};

// "1.23 s", "4 min 05 s"
std::string format_duration(double seconds);

// "800x450, 1 sample, 0.84 s, 1.97 M rays, 2.35 Mrays/s"
std::string render_summary(int width, int height, int samples, const RenderProgress& progress);

}  // namespace jt::frontend
