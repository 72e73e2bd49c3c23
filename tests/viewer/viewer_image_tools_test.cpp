// The image tools through the frame code: Render region (a Ctrl+drag renders
// that rectangle alone, as jtracer-cli --region does) and A/B compare.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "common/files.hpp"
#include "common/run_program.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/image_diff.hpp"
#include "jtracer/region.hpp"
#include "model/ab_compare.hpp"
#include "model/app_actions.hpp"
#include "model/render_region.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

namespace jt::view {
namespace {

namespace fs = std::filesystem;
using namespace jt::test;

class ViewerImageTools : public ViewerFixture {
  protected:
    void SetUp() override {
        open_rendered(kScene);
        ASSERT_EQ(state.render.display.width, kW);
    }
    WindowPoint at(double x, double y) const { return window_point({x, y}); }
    // jtracer-cli's image of the scene as the viewer has it now, with `extra` arguments.
    Image8 cli_image(const std::vector<std::string>& extra) {
        const fs::path scene = dir / "scene.jts";
        write_file(scene, document_text(state.doc));
        Command command{{JT_CLI_EXE, scene.string(), "-o", (dir / "cli.bmp").string()}, {}};
        command.argv.insert(command.argv.end(), extra.begin(), extra.end());
        const ProgramRun run = run_program(command);
        EXPECT_EQ(run.code, 0) << run.out << run.err;
        Expected<Image8> image = read_bmp(dir / "cli.bmp");
        EXPECT_TRUE(image) << (image ? "" : image.error().message);
        return image ? *image : Image8{};
    }

    static constexpr int kW = 64, kH = 48;
    fs::path dir = make_scratch_dir("viewer-image-tools");
};

TEST_F(ViewerImageTools, ACtrlDragRendersTheRegionAloneAsTheCliRendersIt) {
    const Image8 before = state.render.display;
    const WindowPoint a = at(10.3, 40.6), b = at(41.7, 12.2);
    viewer.drag(state, 0, a.x, a.y, b.x, b.y, kCtrl);
    EXPECT_FALSE(state.view.free_camera_active) << "a Ctrl+drag does not orbit";
    ASSERT_TRUE(state.view.render_region);
    // Whole pixels from the top left, half-open: columns 10..41, rows 48-40.6..48-12.2.
    EXPECT_EQ(*state.view.render_region, (FrameRegion{10, 7, 42, 36}));
    // An edit now re-renders the region alone; the rest keeps what it showed.
    edit_scene(state, [](Scene& s) { s.primitives[1].material.pigment = Colour(0.1, 0.9, 0.2); });
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    ASSERT_TRUE(state.render.started && state.render.started->options.region);
    const PixelRect inside = to_image_rect(*state.view.render_region, kH);
    const Image8 cli = cli_image({"--region", format_frame_region(*state.view.render_region)});
    ASSERT_EQ(cli.width, kW);
    ASSERT_EQ(cli.height, kH);
    EXPECT_EQ(crop_image(state.render.display, inside), crop_image(cli, inside))
        << "the region's pixels are the CLI's --region bytes";
    EXPECT_NE(crop_image(state.render.display, inside), crop_image(before, inside))
        << "it re-rendered";
    int outside = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (x >= inside.x0 && x < inside.x1 && y >= inside.y0 && y < inside.y1) continue;
            ++outside;
            ASSERT_EQ(std::memcmp(state.render.display.pixel(x, y), before.pixel(x, y), 3), 0)
                << "outside the region the image keeps what it showed, at " << x << ", " << y;
        }
    EXPECT_GT(outside, 0);
    // The texture shows it too, and the region is drawn over the image, not into it.
    EXPECT_EQ(viewer.presenter().read_texture(), state.render.display);

    // Clear region: the whole image renders again, as the CLI renders it.
    ASSERT_TRUE(viewer.click(state, "Clear region"));
    EXPECT_FALSE(state.view.render_region);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.display, cli_image({}));
}

TEST_F(ViewerImageTools, ACtrlClickSetsNoRegionAndADragPastTheImageStopsAtItsEdge) {
    const WindowPoint a = at(20.5, 20.5);
    viewer.drag(state, 0, a.x, a.y, a.x, a.y, kCtrl);
    EXPECT_FALSE(state.view.render_region);
    const WindowPoint b = at(-30, 70);  // past the top left corner
    viewer.drag(state, 0, a.x, a.y, b.x, b.y, kCtrl);
    ASSERT_TRUE(state.view.render_region);
    EXPECT_EQ(*state.view.render_region, (FrameRegion{0, 0, 21, 28}));
}

// A region, then the camera moves: the rest of the image
// showed the old view beside the region's new one. The region is cleared and
// the whole image is the new view's, as the CLI renders it.
TEST_F(ViewerImageTools, MovingTheCameraClearsTheRegionAndRendersTheWholeNewView) {
    const WindowPoint a = at(10.3, 40.6), b = at(41.7, 12.2);
    viewer.drag(state, 0, a.x, a.y, b.x, b.y, kCtrl);
    ASSERT_TRUE(state.view.render_region);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const WindowPoint c = at(20, 20), d = at(30, 24);
    viewer.drag(state, 0, c.x, c.y, d.x, d.y);  // orbits
    ASSERT_TRUE(state.view.free_camera_active);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_FALSE(state.view.render_region);
    ASSERT_TRUE(state.render.started);
    EXPECT_FALSE(state.render.started->options.region);
    ASSERT_TRUE(copy_free_camera_to_scene(state, "moved"));
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.display, cli_image({"--camera", "moved"}))
        << "every pixel of the new view";
}

// Snapshot A, an edit, then A against the live image.
class ViewerCompare : public ViewerImageTools {
  protected:
    void SetUp() override {
        ViewerImageTools::SetUp();
        state.view.image_view = actual_pixels_view();  // one framebuffer pixel per image pixel
        viewer.frame(state);
        ASSERT_TRUE(viewer.click(state, "Snapshot A"));
        ASSERT_TRUE(state.view.compare.a);
        a = *state.view.compare.a;
        edit_scene(state,
                   [](Scene& s) { s.primitives[1].material.pigment = Colour(0.1, 0.9, 0.2); });
        ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
        ASSERT_NE(state.render.display, a);
    }
    // Image pixel (x, y) (rows from the bottom) as the last frame drew it on screen.
    const std::uint8_t* on_screen(const Image8& screen, int x, int y) const {
        const ScreenRect r = viewer.image_rect();
        const int wx = static_cast<int>(r.x0) + x, wy = static_cast<int>(r.y0) + (kH - 1 - y);
        return screen.pixel(wx, viewer.height() - 1 - wy);
    }
    Image8 a;
};

TEST_F(ViewerCompare, TheSplitShowsALeftOfTheLineAndLiveRight) {
    EXPECT_EQ(state.view.compare.mode, CompareMode::split) << "a snapshot starts the split";
    state.view.compare.split = 0.4f;
    viewer.frame(state);
    viewer.frame(state);
    const int split = split_column(state.view.compare, state.render.display);
    ASSERT_EQ(split, 26);  // 0.4 of 64, rounded
    const Image8 screen = viewer.screenshot();
    int from_a = 0, from_live = 0, differing_columns = 0;
    for (int x = 0; x < kW; ++x) {
        if (x == split - 1 || x == split) continue;  // under the line
        bool a_differs_here = false;
        for (int y = 0; y < kH; ++y) {
            const Image8& expected = x < split ? a : state.render.display;
            ASSERT_EQ(std::memcmp(on_screen(screen, x, y), expected.pixel(x, y), 3), 0)
                << "pixel " << x << ", " << y << (x < split ? " shows A" : " shows live");
            a_differs_here |= std::memcmp(a.pixel(x, y), state.render.display.pixel(x, y), 3) != 0;
            ++(x < split ? from_a : from_live);
        }
        differing_columns += a_differs_here;
    }
    EXPECT_GT(differing_columns, 4) << "A and live differ, so the split tells them apart";
    EXPECT_GT(from_a, 0);
    EXPECT_GT(from_live, 0);
    // The A key shows A alone, and again live.
    viewer.press_key(state, keys::letter('A'));
    EXPECT_EQ(state.view.compare.mode, CompareMode::a);
    const Image8 shows_a = viewer.screenshot();
    for (int y = 0; y < kH; y += 5)
        for (int x = 0; x < kW; x += 3)
            ASSERT_EQ(std::memcmp(on_screen(shows_a, x, y), a.pixel(x, y), 3), 0);
    viewer.press_key(state, keys::letter('A'));
    EXPECT_EQ(state.view.compare.mode, CompareMode::live);
}

TEST_F(ViewerCompare, TheDifferenceIsTheCoreDiffsHeatMap) {
    ASSERT_TRUE(viewer.click(state, "Difference"));
    viewer.frame(state);
    const ImageDiff expected = diff_images(a, state.render.display);
    ASSERT_GT(expected.pixels_over, 0u);
    EXPECT_EQ(viewer.compare_texture().read_texture(), expected.image);
    const Image8 screen = viewer.screenshot();
    for (int y = 0; y < kH; y += 3)
        for (int x = 0; x < kW; x += 3)
            ASSERT_EQ(std::memcmp(on_screen(screen, x, y), expected.image.pixel(x, y), 3), 0)
                << "pixel " << x << ", " << y;
    EXPECT_NE(find_item(viewer.ui_items(), "Difference"), nullptr);
}

TEST(RenderRegion, SpansTheWholePixelsADragCovers) {
    EXPECT_EQ(region_spanning({0.5, 0.5}, {63.5, 47.5}, 64, 48), (FrameRegion{0, 0, 64, 48}));
    EXPECT_EQ(region_spanning({3.0, 47.0}, {5.0, 45.0}, 64, 48), (FrameRegion{3, 1, 5, 3}))
        << "on pixel edges: the pixels between";
    EXPECT_FALSE(region_spanning({3.0, 4.2}, {3.0, 9.0}, 64, 48)) << "no width";
}

}  // namespace
}  // namespace jt::view
