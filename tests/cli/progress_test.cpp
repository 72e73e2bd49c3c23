// --progress log: what a log file gets while a render runs; the summary line.

#include "jtracer/frontend/progress.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace jt::frontend {
namespace {

// The log lines written for a render that reaches each fraction at its own
// time: {fraction, seconds}.
std::string logged_at(const std::vector<std::pair<double, double>>& updates) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(std::tmpfile(), &std::fclose);
    ProgressDisplay display(ProgressStyle::log, out.get());
    for (const auto& [fraction, seconds] : updates) {
        RenderProgress progress;
        progress.fraction = fraction;
        progress.seconds = seconds;
        display.update(progress);
    }
    std::fflush(out.get());
    std::rewind(out.get());
    std::string text;
    for (int c; (c = std::fgetc(out.get())) != EOF;) text += static_cast<char>(c);
    return text;
}

// As `logged_at`, every fraction reached `seconds` into the render.
std::string logged(std::initializer_list<double> fractions, double seconds = 2.0) {
    std::vector<std::pair<double, double>> updates;
    for (double fraction : fractions) updates.emplace_back(fraction, seconds);
    return logged_at(updates);
}

// A render whose 10% take longer than a minute still writes a line a minute,
// for a CI job or a watchdog that ends a job silent for some minutes.
TEST(ProgressLog, ASlowRenderWritesALineAtLeastEveryMinute) {
    EXPECT_EQ(logged_at({{0.11, 2.0},
                         {0.12, 30.0},
                         {0.13, 62.5},
                         {0.14, 100.0},
                         {0.15, 123.0},
                         {0.20, 124.0},
                         {0.21, 150.0},
                         {1.0, 400.0}}),
              "rendering: 10% (2.00 s)\n"
              "rendering: 13% (1 min 02 s)\n"
              "rendering: 15% (2 min 03 s)\n"
              "rendering: 20% (2 min 04 s)\n");
}

TEST(ProgressLog, DurationsOfHoursSayHours) {
    EXPECT_EQ(format_duration(59.5), "59.50 s");
    EXPECT_EQ(format_duration(3599.0), "59 min 59 s");
    EXPECT_EQ(format_duration(3600.0 * 10 + 65.0), "10 h 01 min 05 s");
}

TEST(ProgressLog, EachLineIsTheMultipleOfTenJustPassed) {
    EXPECT_EQ(logged({0.05, 0.15, 0.19, 0.2, 0.8}),
              "rendering: 10% (2.00 s)\n"
              "rendering: 20% (2.00 s)\n"
              "rendering: 80% (2.00 s)\n");
}

TEST(ProgressLog, AJumpPastSeveralWritesTheHighestPassed) {
    // 80% to 97% passes 90%: the log says 90%, not 97%, so that its lines
    // always read as milestones; 100% is the summary's line, not the log's.
    EXPECT_EQ(logged({0.83, 0.97, 0.999, 1.0}),
              "rendering: 80% (2.00 s)\n"
              "rendering: 90% (2.00 s)\n");
}

TEST(ProgressLog, NothingInTheFirstSecond) {
    EXPECT_EQ(logged({0.3, 0.6, 0.9}, 0.5), "");
}

// The summary names the pixels rendered: a region job's are the region's,
// not the frame's (`--region 40,20,120,70` of 160x90 rendered 80x50).
TEST(RenderSummary, SaysTheRegionAndTheFrameItLiesIn) {
    RenderProgress progress;
    progress.seconds = 2.0;
    progress.rays = 4000000;
    EXPECT_EQ(render_summary(800, 450, 1, progress),
              "800x450, 1 sample, 2.00 s, 4.00 M rays, 2.00 Mrays/s");
    EXPECT_EQ(render_summary(160, 90, 16, progress, FrameRegion{40, 20, 120, 70}),
              "80x50 (region 40,20,120,70 of 160x90), 16 samples, 2.00 s, 4.00 M rays, "
              "2.00 Mrays/s");
}

}  // namespace
}  // namespace jt::frontend
