// --progress log: what a log file gets while a render runs.

#include "jtracer/frontend/progress.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace jt::frontend {
namespace {

// The log lines written for renders that reach these fractions, each at
// `seconds` into the render.
std::string logged(std::initializer_list<double> fractions, double seconds = 2.0) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(std::tmpfile(), &std::fclose);
    ProgressDisplay display(ProgressStyle::log, out.get());
    for (double fraction : fractions) {
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

}  // namespace
}  // namespace jt::frontend
