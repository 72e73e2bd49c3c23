#pragma once
// Files for the viewer's GL tests: the test scene, copies of it to change, and
// whole-file reads and writes.

#include "app_state.hpp"
#include "jtracer/parser.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace jt::view::test {

namespace fs = std::filesystem;

inline const fs::path kScene = fs::path(JT_VIEWER_TEST_DIR) / "scenes" / "two_cameras.jts";
constexpr auto kTimeout = std::chrono::minutes(2);

inline std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

inline void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// scenes/showcase.jts at another size.
inline Scene showcase_at(int width, int height) {
    ParseResult parsed = parse_scene(read(fs::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts"));
    EXPECT_TRUE(parsed.ok());
    parsed.scene.settings.width = width;
    parsed.scene.settings.height = height;
    return parsed.scene;
}

// A copy of the test scene in a fresh folder, for tests that change the file.
inline fs::path scene_copy(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("jtracer-view-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(kScene, dir / "scene.jts");
    return dir / "scene.jts";
}

// Polls the file on every frame.
inline ViewerConfig test_config() {
    ViewerConfig config;
    config.watch_interval = std::chrono::milliseconds(0);
    return config;
}

}  // namespace jt::view::test
