#include "jtracer/frontend/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace jt::frontend {

namespace {

constexpr int bar_width = 30;
// A plain log line per 10% only for renders long enough to need them.
constexpr double log_after_seconds = 1.0;
// Between milestones a long render still writes a line this often: a CI job
// or a farm's watchdog that ends a job silent for some minutes (10 on
// several CI services) would otherwise end a render whose 10% take longer.
constexpr double log_at_least_every_seconds = 60.0;

}  // namespace

std::string format_duration(double seconds) {
    char text[64];
    if (seconds < 60.0) {
        std::snprintf(text, sizeof text, "%.2f s", seconds);
    } else if (seconds >= 3600.0) {
        auto whole = static_cast<long>(seconds);
        std::snprintf(text, sizeof text, "%ld h %02ld min %02ld s", whole / 3600, whole / 60 % 60,
                      whole % 60);
    } else {
        auto whole = static_cast<long>(seconds);
        std::snprintf(text, sizeof text, "%ld min %02ld s", whole / 60, whole % 60);
    }
    return text;
}

std::string render_summary(int width, int height, int samples, const RenderProgress& progress,
                           const std::optional<FrameRegion>& region) {
    double mrays = static_cast<double>(progress.rays) / 1e6;
    double rate = progress.seconds > 0.0 ? mrays / progress.seconds : 0.0;
    char rays[48];
    if (progress.rays < 1000000)
        std::snprintf(rays, sizeof rays, "%llu rays",
                      static_cast<unsigned long long>(progress.rays));
    else
        std::snprintf(rays, sizeof rays, "%.2f M rays", mrays);
    char size[120];
    if (region)
        std::snprintf(size, sizeof size, "%dx%d (region %s of %dx%d)", region->width(),
                      region->height(), format_frame_region(*region).c_str(), width, height);
    else
        std::snprintf(size, sizeof size, "%dx%d", width, height);
    char text[300];
    std::snprintf(text, sizeof text, "%s, %d sample%s, %s, %s, %.2f Mrays/s", size, samples,
                  samples == 1 ? "" : "s", format_duration(progress.seconds).c_str(), rays, rate);
    return text;
}

ProgressStyle progress_style(ProgressMode mode, bool quiet, bool stderr_is_terminal) {
    if (quiet) return ProgressStyle::none;
    switch (mode) {
        case ProgressMode::automatic:
            return stderr_is_terminal ? ProgressStyle::bar : ProgressStyle::none;
        case ProgressMode::bar:
            return ProgressStyle::bar;
        case ProgressMode::log:
            return ProgressStyle::log;
        case ProgressMode::none:
            return ProgressStyle::none;
    }
    return ProgressStyle::none;
}

ProgressStyle progress_style_for_stderr(ProgressMode mode, bool quiet) {
    return progress_style(mode, quiet, ::isatty(STDERR_FILENO) == 1);
}

void ProgressDisplay::update(const RenderProgress& progress) {
    if (style_ == ProgressStyle::none) return;
    int percent = static_cast<int>(std::floor(progress.fraction * 100.0));
    if (style_ == ProgressStyle::bar) {
        int filled = static_cast<int>(progress.fraction * bar_width);
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.append(static_cast<std::size_t>(bar_width - filled), '.');
        std::string eta = "--";
        if (progress.fraction > 0.01 && progress.seconds > 0.2)
            eta = format_duration(progress.seconds * (1.0 - progress.fraction) / progress.fraction);
        std::fprintf(out_, "\r[%s] %3d%%  %-12s  ETA %-12s", bar.c_str(), percent,
                     progress.pass_name.c_str(), eta.c_str());
        std::fflush(out_);
        drawn_ = true;
        return;
    }
    if (progress.seconds < log_after_seconds) return;
    const int milestone = percent / 10 * 10;
    const bool passed = milestone > last_logged_percent_ && milestone < 100;
    const bool silent_too_long =
        percent < 100 && progress.seconds - last_logged_seconds_ >= log_at_least_every_seconds;
    if (!passed && !silent_too_long) return;
    std::fprintf(out_, "rendering: %d%% (%s)\n", passed ? milestone : percent,
                 format_duration(progress.seconds).c_str());
    std::fflush(out_);
    if (passed) last_logged_percent_ = milestone;
    last_logged_seconds_ = progress.seconds;
}

void ProgressDisplay::finish() {
    if (drawn_) std::fprintf(out_, "\r%*s\r", bar_width + 50, "");
    drawn_ = false;
}

}  // namespace jt::frontend
