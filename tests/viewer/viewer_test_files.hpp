#pragma once
// The viewer tests' scene, copies of it to change, and their configuration.

#include "common/scratch_dir.hpp"
#include "model/app_state.hpp"

#include <chrono>
#include <filesystem>
#include <string>

namespace jt::test {

inline const std::filesystem::path kScene =
    std::filesystem::path(JT_VIEWER_TEST_DIR) / "scenes" / "two_cameras.jts";
constexpr auto kTimeout = std::chrono::minutes(2);

// A copy of the test scene in a fresh folder, for tests that change the file.
inline std::filesystem::path scene_copy(const std::string& name) {
    const std::filesystem::path dir = make_scratch_dir(name);
    std::filesystem::copy_file(kScene, dir / "scene.jts");
    return dir / "scene.jts";
}

// Polls the file on every frame.
inline view::ViewerConfig test_config() {
    view::ViewerConfig config;
    config.watch_interval = std::chrono::milliseconds(0);
    return config;
}

}  // namespace jt::test
