// The image view's zoom and pan (image_layout.hpp): the one mapping between
// window and image points that picking, the inspector and the overlays use.

#include "model/image_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace jt::view {
namespace {

constexpr int kW = 64, kH = 48;
const ScreenRect kArea{100, 20, 420, 260};  // 320 x 240 window units

TEST(ImageView, ZoomIsFramebufferPixelsPerImagePixel) {
    const ImageView view{false, 4.0f, 0.0f, 0.0f};
    const ScreenRect r = place_image(kW, kH, kArea, 1.0f, view);
    EXPECT_FLOAT_EQ(r.width(), 256);
    EXPECT_FLOAT_EQ(r.height(), 192);
    const ScreenRect hidpi = place_image(kW, kH, kArea, 2.0f, view);
    EXPECT_FLOAT_EQ(hidpi.width(), 128) << "128 window units are 256 framebuffer pixels";
    EXPECT_FLOAT_EQ(shown_zoom(kW, kH, kArea, 1.0f, ImageView{}), 5.0f) << "fit: 320/64";
}

TEST(ImageView, TheCornerIsOnAWholeFramebufferPixel) {
    const ImageView view{false, 3.0f, 0.3f, 0.7f};
    for (float scale : {1.0f, 2.0f, 1.5f}) {
        const ScreenRect r = place_image(kW, kH, kArea, scale, view);
        EXPECT_FLOAT_EQ(r.x0 * scale, std::round(r.x0 * scale));
        EXPECT_FLOAT_EQ(r.y0 * scale, std::round(r.y0 * scale));
    }
}

TEST(ImageView, ZoomingKeepsThePointUnderTheMouse) {
    // Zoomed in far enough that the pan's clamp leaves the point alone.
    const ImageView start{false, 8.0f, 0.0f, 0.0f};
    const float x = 300, y = 100;
    const ScreenRect before = place_image(kW, kH, kArea, 1.0f, start);
    const std::optional<ImagePoint> under = window_to_image(before, kW, kH, x, y);
    ASSERT_TRUE(under);
    const ImageView zoomed = zoom_view_to(start, kW, kH, kArea, 1.0f, 16.0f, x, y);
    EXPECT_FLOAT_EQ(zoomed.zoom, 16.0f);
    const ScreenRect after = place_image(kW, kH, kArea, 1.0f, zoomed);
    const WindowPoint back = image_to_window(after, kW, kH, *under);
    EXPECT_NEAR(back.x, x, 1.0f) << "within the pixel snap";
    EXPECT_NEAR(back.y, y, 1.0f);
}

TEST(ImageView, StepsArePowersOfTwoFromAFittedZoom) {
    const ImageView in = zoom_view_step(ImageView{}, kW, kH, kArea, 1.0f, 1, 260, 140);
    EXPECT_FLOAT_EQ(in.zoom, 8.0f) << "fitted at 5: the next power of two up";
    const ImageView out = zoom_view_step(ImageView{}, kW, kH, kArea, 1.0f, -1, 260, 140);
    EXPECT_FLOAT_EQ(out.zoom, 4.0f);
    EXPECT_FLOAT_EQ(zoom_view_step(in, kW, kH, kArea, 1.0f, 1, 260, 140).zoom, 16.0f);
    EXPECT_FLOAT_EQ(zoom_view_step(in, kW, kH, kArea, 1.0f, -2, 260, 140).zoom, 2.0f);
    ImageView far = in;
    for (int i = 0; i < 20; ++i) far = zoom_view_step(far, kW, kH, kArea, 1.0f, 1, 260, 140);
    EXPECT_FLOAT_EQ(far.zoom, kMaxImageZoom);
}

TEST(ImageView, APanCannotLoseTheImage) {
    const ImageView big{false, 8.0f, 0.0f, 0.0f};  // 512 x 384 in a 320 x 240 area
    const ImageView panned = pan_view(big, kW, kH, kArea, 1.0f, 1e6f, -1e6f);
    const ScreenRect r = place_image(kW, kH, kArea, 1.0f, panned);
    EXPECT_LE(r.x0, kArea.x0);
    EXPECT_GE(r.x1, kArea.x1) << "a larger image always covers the area";
    EXPECT_LE(r.y0, kArea.y0);
    EXPECT_GE(r.y1, kArea.y1);
    EXPECT_FLOAT_EQ(r.x0, kArea.x0) << "pushed right as far as it goes";
    EXPECT_FLOAT_EQ(r.y1, kArea.y1) << "pushed up as far as it goes";
    // Smaller than the area: centred whatever the pan.
    const ImageView small = pan_view(ImageView{false, 2.0f, 0, 0}, kW, kH, kArea, 1.0f, 500, 500);
    const ScreenRect s = place_image(kW, kH, kArea, 1.0f, small);
    EXPECT_FLOAT_EQ(s.x0, 100 + (320 - 128) / 2);
    EXPECT_FLOAT_EQ(s.y0, 20 + (240 - 96) / 2);
}

TEST(ImageView, APanMovesTheImageByTheMouse) {
    const ImageView big{false, 8.0f, 0.0f, 0.0f};
    const ScreenRect before = place_image(kW, kH, kArea, 1.0f, big);
    const ScreenRect after =
        place_image(kW, kH, kArea, 1.0f, pan_view(big, kW, kH, kArea, 1.0f, 30, -20));
    EXPECT_FLOAT_EQ(after.x0 - before.x0, 30);
    EXPECT_FLOAT_EQ(after.y0 - before.y0, -20);
    // Panning a fitted view starts from the fitted zoom.
    EXPECT_FLOAT_EQ(pan_view(ImageView{}, kW, kH, kArea, 1.0f, 5, 5).zoom, 5.0f);
}

TEST(ImageView, WindowAndImagePointsMapBothWaysAtAZoomWithAPan) {
    const ImageView view = pan_view(ImageView{false, 4.0f, 0, 0}, kW, kH, kArea, 1.0f, -17, 11);
    const ScreenRect r = place_image(kW, kH, kArea, 1.0f, view);
    for (int y = 0; y < kH; y += 7)
        for (int x = 0; x < kW; x += 5) {
            const WindowPoint p = image_to_window(r, kW, kH, {x + 0.5, y + 0.5});
            const std::optional<ImagePoint> back = window_to_image(r, kW, kH, p.x, p.y);
            ASSERT_TRUE(back);
            EXPECT_EQ(static_cast<int>(back->x), x);
            EXPECT_EQ(static_cast<int>(back->y), y);
        }
    // A 4x4 block of window pixels is one image pixel.
    const std::optional<ImagePoint> a = window_to_image(r, kW, kH, r.x0 + 0.1f, r.y1 - 0.1f);
    const std::optional<ImagePoint> b = window_to_image(r, kW, kH, r.x0 + 3.9f, r.y1 - 3.9f);
    const std::optional<ImagePoint> c = window_to_image(r, kW, kH, r.x0 + 4.1f, r.y1 - 4.1f);
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(static_cast<int>(a->x), 0);
    EXPECT_EQ(static_cast<int>(b->x), 0);
    EXPECT_EQ(static_cast<int>(b->y), 0);
    EXPECT_EQ(static_cast<int>(c->x), 1);
    EXPECT_EQ(static_cast<int>(c->y), 1);
}

}  // namespace
}  // namespace jt::view
