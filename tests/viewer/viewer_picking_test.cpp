// Picking through the frame code: a click on the image selects the primitive
// under it, outlines it over the image (never in it), opens it in the Objects
// panel; the background clears; the list stays a few rows with 100,000 objects.

#include "app_actions.hpp"
#include "headless.hpp"
#include "jtracer/render_job.hpp"
#include "picking.hpp"
#include "viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <thread>

namespace jt::view {
namespace {

using namespace jt::test;
using Kind = Selection::Kind;

class ViewerPicking : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(viewer.ok()) << viewer.error();
        open_scene(state, kScene);
        ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    }
    // The window point of image pixel (x, y) (from the bottom left).
    WindowPoint window_point(double x, double y) const {
        const UiItem* panel = find_item(viewer.ui_items(), "panel");
        const float x0 = panel->rect.x1, x1 = static_cast<float>(viewer.width());
        const ScreenRect area{x0, 0, x1, find_item(viewer.ui_items(), "status")->rect.y0};
        const ScreenRect where =
            place_image(state.display.width, state.display.height, area, 1.0f, state.fit);
        const WindowPoint p =
            image_to_window(where, state.display.width, state.display.height, {x, y});
        return p;
    }
    void click_pixel(int x, int y) {
        const WindowPoint p = window_point(x + 0.5, y + 0.5);
        viewer.drag(state, 0, p.x, p.y, p.x, p.y);
        viewer.frame(state);  // the frame after the click shows what it selected
    }

    HeadlessViewer viewer{960, 640};
    AppState state{test_config()};
};

TEST_F(ViewerPicking, AClickSelectsOutlinesOverTheImageAndOpensTheObject) {
    const Image8 before = state.display;
    click_pixel(32, 20);  // the sphere, in the middle of the 64x48 image
    ASSERT_EQ(state.selection, (Selection{Kind::primitive, 1})) << state.message;
    EXPECT_FALSE(state.free_camera_active) << "a click does not move the camera";
    // The sidebar scrolls to the list in the frame that reveals it; its rows
    // are drawn once the list is in view.
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "sphere 2"), nullptr) << "listed in the open panel";
    // The outline comes once the ids are computed off the UI thread.
    const auto deadline = std::chrono::steady_clock::now() + kTimeout;
    while (viewer.overlay().outlined_pixels() == 0 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        viewer.frame(state);
    }
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    int sphere_pixels = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            if (const auto pick = pick_primitive(*frame, x, y); pick && pick->primitive == 1)
                ++sphere_pixels;
    EXPECT_EQ(viewer.overlay().outlined_pixels(), sphere_pixels);
    EXPECT_EQ(state.display, before) << "the outline is drawn over the image, not into it";

    click_pixel(32, 46);  // the sky above the sphere
    EXPECT_EQ(state.selection.kind, Kind::none);
    viewer.frame(state);
    EXPECT_EQ(viewer.overlay().outlined_pixels(), 0);
}

TEST_F(ViewerPicking, HoveringThePictureInspectsThePixelUnderTheMouse) {
    const WindowPoint p = window_point(32.5, 20.5);
    viewer.move_mouse(state, p.x, p.y);
    const std::uint8_t* rgb = state.display.pixel(32, 20);
    char expected[64];
    std::snprintf(expected, sizeof expected, "x 32, y 27   RGB %d %d %d", rgb[0], rgb[1], rgb[2]);
    EXPECT_EQ(state.inspected.rfind(expected, 0), 0u) << state.inspected;
    EXPECT_NE(state.inspected.find("sphere 2 at distance"), std::string::npos) << state.inspected;
    viewer.move_mouse(state, 20, 20);  // over the panel
    EXPECT_TRUE(state.inspected.empty());
}

TEST_F(ViewerPicking, TheObjectsListDrawsOnlyTheRowsInViewOfAHundredThousand) {
    edit_scene(state, [](Scene& s) {
        for (int i = 0; i < 100000; ++i)
            s.primitives.push_back(Primitive{Sphere{Vec3(i * 0.01, -5, -20), 0.001}, {}, {}});
    });
    // Render settings and Camera closed first, so that the list is inside the window.
    ASSERT_TRUE(viewer.click(state, "Render settings"));
    ASSERT_TRUE(viewer.click(state, "Camera"));
    ASSERT_TRUE(viewer.click(state, "Objects"));
    viewer.frame(state);
    const auto rows = [&] {
        int n = 0;
        for (const UiItem& item : viewer.ui_items()) n += item.label.rfind("sphere ", 0) == 0;
        return n;
    };
    EXPECT_GT(rows(), 0);
    EXPECT_LT(rows(), 40) << "only the rows in view are drawn";
    select(state, {Kind::primitive, 60000});
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "sphere 60001"), nullptr) << "scrolled to the selection";
    state.object_filter = "sphere 99999";
    viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "sphere 99999"), nullptr);
    EXPECT_EQ(rows(), 1 + (find_item(viewer.ui_items(), "sphere 60001") ? 1 : 0))
        << "the filter lists only what matches";
}

}  // namespace
}  // namespace jt::view
