// jtracer-view as a program: the headless --screenshot path needs no display.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("jtracer-view-cli-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Runs the viewer with `arguments` (each single-quoted for the shell) and no
// DISPLAY; returns its exit code.
int run_viewer(const std::vector<std::string>& arguments, const fs::path& log) {
    std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY '" JT_VIEWER_EXE "'";
    for (const std::string& argument : arguments) {
        command += " '";
        command += argument;
        command += "'";
    }
    command += " > '";
    command += log.string();
    command += "' 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

unsigned be32(const std::string& bytes, std::size_t at) {
    return (unsigned(std::uint8_t(bytes[at])) << 24) |
           (unsigned(std::uint8_t(bytes[at + 1])) << 16) |
           (unsigned(std::uint8_t(bytes[at + 2])) << 8) | unsigned(std::uint8_t(bytes[at + 3]));
}

const std::string kScene = std::string(JT_VIEWER_TEST_DIR) + "/scenes/two_cameras.jts";

TEST(ViewerCli, ScreenshotWritesAPngOfTheRequestedSizeWithoutADisplay) {
    const fs::path dir = temp_dir("shot");
    const fs::path png = dir / "view.png";
    const int code =
        run_viewer({kScene, "--screenshot", png.string(), "--size", "400x300"}, dir / "log");
    EXPECT_EQ(code, 0) << read(dir / "log");
    const std::string bytes = read(png);
    ASSERT_GT(bytes.size(), 24u) << read(dir / "log");
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(be32(bytes, 16), 400u);
    EXPECT_EQ(be32(bytes, 20), 300u);
}

TEST(ViewerCli, ScreenshotOfABrokenSceneFailsCleanlyWithItsDiagnostics) {
    const fs::path dir = temp_dir("broken");
    std::ofstream(dir / "bad.jts") << "scene {\n  sphere { radius 2; }\n}\n";
    const int code = run_viewer({(dir / "bad.jts").string(), "--screenshot",
                                 (dir / "out.png").string(), "--size", "320x240"},
                                dir / "log");
    EXPECT_EQ(code, 1);
    EXPECT_NE(read(dir / "log").find("bad.jts:2:"), std::string::npos) << read(dir / "log");
}

TEST(ViewerCli, BadArgumentsAreRefusedWithoutWritingAnything) {
    const fs::path dir = temp_dir("args");
    EXPECT_EQ(run_viewer({kScene, "--screenshot", (dir / "a.png").string(), "--size", "12x"},
                         dir / "log"),
              2);
    EXPECT_NE(read(dir / "log").find("--size"), std::string::npos);
    EXPECT_EQ(run_viewer({kScene, "--screenshot", (dir / "a.jpg").string()}, dir / "log"), 2);
    EXPECT_FALSE(fs::exists(dir / "a.png"));
    EXPECT_FALSE(fs::exists(dir / "a.jpg"));
}

TEST(ViewerCli, WithoutADisplayTheWindowModeExplainsInsteadOfCrashing) {
    const fs::path dir = temp_dir("nodisplay");
    EXPECT_EQ(run_viewer({kScene}, dir / "log"), 1);
    EXPECT_NE(read(dir / "log").find("--screenshot"), std::string::npos) << read(dir / "log");
}

}  // namespace
