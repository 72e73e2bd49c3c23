#pragma once
// What the frame code's tests start from: a headless viewer (OSMesa, 960x640
// unless the test's fixture asks for another size) and its state, with a
// scene opened and rendered to the end.

#include "app/headless.hpp"
#include "model/image_layout.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt::view {

class ViewerFixture : public ::testing::Test {
  protected:
    explicit ViewerFixture(int width = 960, int height = 640) : viewer(width, height) {}
    void TearDown() override {
        if (!copy_.empty()) std::filesystem::remove_all(copy_.parent_path());
    }

    void open_rendered(const std::filesystem::path& scene) {
        ASSERT_TRUE(viewer.ok()) << viewer.error();
        open_scene(state, scene);
        ASSERT_TRUE(viewer.run_until_complete(state, test::kTimeout));
    }
    // A copy of the test scene in a fresh folder (test::scene_copy), opened
    // and rendered; the folder goes when the test ends.
    std::filesystem::path open_rendered_copy(const std::string& name) {
        copy_ = test::scene_copy(name);
        open_rendered(copy_);
        return copy_;
    }
    // The window point of image point `p` (pixels from the bottom left) as
    // the last frame drew the image.
    WindowPoint window_point(ImagePoint p) const {
        return image_to_window(viewer.image_rect(), state.render.display.width,
                               state.render.display.height, p);
    }

    HeadlessViewer viewer;
    AppState state{test::test_config()};

  private:
    std::filesystem::path copy_;
};

}  // namespace jt::view
