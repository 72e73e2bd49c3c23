// Ctrl+C (SIGINT), SIGTERM and SIGHUP (a dropped ssh connection) during a
// long render: the CLI stops within a second, exits 130 / 143 / 129, writes nothing and leaves the
// older output intact.

#include "cli_sandbox.hpp"
#include "common/scenes.hpp"

#include <chrono>
#include <csignal>
#include <thread>

namespace jt::test {
namespace {

using Clock = std::chrono::steady_clock;

// The render would run for 15 s or more: stopping well within that is the
// promptness the test asks for, with room for a sanitizer build on a busy
// machine (a tile there takes several times as long).
constexpr double stop_limit_seconds = 5.0;

class Interruption : public CliSandbox, public testing::WithParamInterface<int> {};

TEST_P(Interruption, StopsPromptlyWritesNothingKeepsTheOldOutput) {
    const int signal = GetParam();
    const std::string precious = "an older render\n";
    write_file(dir / "out.bmp", precious);
    // One thread and many samples: a render of 15 s or more.
    RunningProgram render(cli({source_path("scenes/showcase.jts").string(), "-o", "out.bmp",
                               "--samples", "64", "--threads", "1", "--progress", "log"}));
    ASSERT_GT(render.pid(), 0);
    // --progress log: the CLI logs "rendering: N%" once it is well under way.
    const auto give_up = Clock::now() + std::chrono::seconds(120);
    while (render.err_so_far().find("rendering:") == std::string::npos && Clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_NE(render.err_so_far().find("rendering:"), std::string::npos)
        << "the render never reported progress";

    const auto sent = Clock::now();
    ASSERT_EQ(::kill(render.pid(), signal), 0);
    ProgramRun r = render.finish();
    const double seconds = std::chrono::duration<double>(Clock::now() - sent).count();

    EXPECT_EQ(r.signal, 0) << "killed by the signal instead of handling it";
    EXPECT_EQ(r.code, 128 + signal) << r.err;
    EXPECT_LT(seconds, stop_limit_seconds);
    EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
    EXPECT_EQ(read_file(dir / "out.bmp"), precious);
    EXPECT_EQ(files(), (std::vector<std::string>{"out.bmp", "scene.jts"}));
}

INSTANTIATE_TEST_SUITE_P(Signals, Interruption, testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const testing::TestParamInfo<int>& info) {
                             return info.param == SIGINT    ? std::string("SIGINT")
                                    : info.param == SIGTERM ? std::string("SIGTERM")
                                                            : std::string("SIGHUP");
                         });

}  // namespace
}  // namespace jt::test
