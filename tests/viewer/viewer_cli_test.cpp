// jtracer-view as a program: the headless --screenshot path needs no display.

#include "common/files.hpp"
#include "common/image_header.hpp"
#include "common/run_program.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/version.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

// Runs the viewer with `arguments` and no DISPLAY.
ProgramRun run_viewer(const std::vector<std::string>& arguments) {
    Command command{{"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", JT_VIEWER_EXE}, {}};
    command.argv.insert(command.argv.end(), arguments.begin(), arguments.end());
    return run_program(command);
}

using ViewerCli = ScratchTest;

TEST_F(ViewerCli, ScreenshotWritesAPngOfTheRequestedSizeWithoutADisplay) {
    const fs::path png = dir / "view.png";
    const ProgramRun r =
        run_viewer({kScene.string(), "--screenshot", png.string(), "--size", "400x300"});
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    const std::string bytes = read_file(png);
    ASSERT_GT(bytes.size(), 24u) << r.out << r.err;
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(png_size(bytes).width, 400u);
    EXPECT_EQ(png_size(bytes).height, 300u);
}

TEST_F(ViewerCli, ScreenshotOfABrokenSceneFailsCleanlyWithItsDiagnostics) {
    write_file(dir / "bad.jts", "scene {\n  sphere { radius 2; }\n}\n");
    const ProgramRun r = run_viewer({(dir / "bad.jts").string(), "--screenshot",
                                     (dir / "out.png").string(), "--size", "320x240"});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE((r.out + r.err).find("bad.jts:2:"), std::string::npos) << r.out << r.err;
}

TEST_F(ViewerCli, BadArgumentsAreRefusedWithoutWritingAnything) {
    const ProgramRun r =
        run_viewer({kScene.string(), "--screenshot", (dir / "a.png").string(), "--size", "12x"});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE((r.out + r.err).find("--size"), std::string::npos);
    EXPECT_EQ(run_viewer({kScene.string(), "--screenshot", (dir / "a.jpg").string()}).code, 2);
    EXPECT_FALSE(fs::exists(dir / "a.png"));
    EXPECT_FALSE(fs::exists(dir / "a.jpg"));
}

TEST_F(ViewerCli, HelpShowsExamplesAndUsageErrorsExitTwoWithCli11sMessage) {
    const ProgramRun help = run_viewer({"--help"});
    EXPECT_EQ(help.code, 0);
    EXPECT_NE(help.out.find("Examples:"), std::string::npos) << help.out;
    const ProgramRun version = run_viewer({"--version"});
    EXPECT_EQ(version.code, 0);
    EXPECT_EQ(version.out.rfind(std::string("jtracer-view ") + version_string(), 0), 0u)
        << version.out;
    const ProgramRun unknown = run_viewer({"--no-such-option"});
    EXPECT_EQ(unknown.code, 2);
    EXPECT_NE(unknown.err.find("--no-such-option"), std::string::npos) << unknown.err;
    EXPECT_EQ(run_viewer({kScene.string(), "extra.jts"}).code, 2);
    EXPECT_EQ(run_viewer({kScene.string(), "--size"}).code, 2);
    for (const char* bad : {"0", "-1", "abc", "1e400"}) {
        const ProgramRun r = run_viewer({kScene.string(), "--timeout", bad});
        EXPECT_EQ(r.code, 2) << bad;
        const std::string log = r.out + r.err;
        EXPECT_NE(log.find("--timeout"), std::string::npos) << log;
        EXPECT_NE(log.find(std::string("'") + bad + "'"), std::string::npos) << log;
        EXPECT_LT(log.size(), 300u) << "no 300-digit numbers: " << log;
    }
}

TEST_F(ViewerCli, WithoutADisplayTheWindowModeExplainsInsteadOfCrashing) {
    const ProgramRun r = run_viewer({kScene.string()});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE((r.out + r.err).find("--screenshot"), std::string::npos) << r.out << r.err;
}

}  // namespace
}  // namespace jt::test
