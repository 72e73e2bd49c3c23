#pragma once
// What the frame code's tests start from: a 960x640 headless viewer (OSMesa)
// and its state, with a scene opened and rendered to the end.

#include "app/headless.hpp"
#include "model/image_layout.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace jt::view {

class ViewerFixture : public ::testing::Test {
  protected:
    void open_rendered(const std::filesystem::path& scene) {
        ASSERT_TRUE(viewer.ok()) << viewer.error();
        open_scene(state, scene);
        ASSERT_TRUE(viewer.run_until_complete(state, test::kTimeout));
    }
    // The window point of image point `p` (pixels from the bottom left) as
    // the last frame drew the image.
    WindowPoint window_point(ImagePoint p) const {
        return image_to_window(viewer.image_rect(), state.render.display.width,
                               state.render.display.height, p);
    }

    HeadlessViewer viewer{960, 640};
    AppState state{test::test_config()};
};

}  // namespace jt::view
