// render_tile: tiles of one prepared frame give exactly the pixels of a whole
// render, and the frame builds its view table once for all of them.

#include "jtracer/render_tile.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/region.hpp"

#include "render/camera_rays.hpp"
#include "render/prepared_frame.hpp"
#include "render/trace.hpp"

#include <gtest/gtest.h>

namespace jt {
namespace {

Scene tile_scene() {
    ParseResult parsed = parse_scene(R"(
render_settings { width: 75; height: 41; recurse_depth: 3; }
cameras { perspective_camera { position: <0, 1.2, 5>; look_at: <0, 0.5, 0>; aspect: 1.83; } }
scene {
    plane { normal: <0, 1, 0>; distance: -1; material { pigment: <0.8, 0.8, 0.8>; diffuse: <1, 1, 1>; } }
    sphere { center: <-1, 0.3, 0>; radius: 0.8;
             material { pigment: <1, 0.2, 0.1>; diffuse: <1, 1, 1>; specular: <1, 1, 1>; } }
    cylinder { radius: 0.3; height: 1.2; transform { xrotate: 30; translate: <1.2, 0, 0>; }
               material { pigment: <0.2, 0.4, 1>; diffuse: <1, 1, 1>; reflection: 0.5; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)");
    EXPECT_TRUE(parsed.ok());
    return parsed.scene;
}

TEST(RenderTile, TilesOfOneFrameMakeTheWholeRenderForEverySampleCount) {
    const Scene scene = tile_scene();
    auto prepared = prepare_scene(scene).value();
    for (int samples : {1, 3, 8}) {
        RenderOptions options = render_options_for(scene);
        options.samples = samples;
        options.previews = false;
        const Image8 whole = render_image(prepared, options);
        const auto frame = prepare_frame(prepared, options);
        // Uneven tiles that straddle the renderer's own 32-pixel pieces.
        Image8 assembled(75, 41);
        for (PixelRect tile :
             {PixelRect{0, 0, 40, 41}, PixelRect{40, 0, 75, 17}, PixelRect{40, 17, 75, 41}}) {
            const RenderedTile rendered = render_tile(*frame, tile);
            ASSERT_EQ(rendered.pixels.width, tile.width());
            ASSERT_EQ(rendered.pixels.height, tile.height());
            EXPECT_GE(rendered.rays, static_cast<std::uint64_t>(tile.width()) * tile.height() *
                                         static_cast<std::uint64_t>(samples));
            paste_image(assembled, rendered.pixels, tile.x0, tile.y0);
        }
        EXPECT_EQ(assembled, whole) << samples << " samples";
    }
}

TEST(RenderTile, ATileReachingOutOfTheFrameIsClipped) {
    const Scene scene = tile_scene();
    auto prepared = prepare_scene(scene).value();
    RenderOptions options = render_options_for(scene);
    const Image8 whole = render_image(prepared, options);
    const RenderedTile rendered = render_tile(*prepare_frame(prepared, options), {64, 32, 128, 64});
    EXPECT_EQ(rendered.pixels, crop_image(whole, {64, 32, 75, 41}));
    EXPECT_EQ(render_tile(*prepare_frame(prepared, options), {80, 0, 90, 10}).pixels, Image8());
}

TEST(RenderTile, TheViewTableIsBuiltOncePerFrame) {
    const Scene scene = tile_scene();
    const auto frame = prepare_frame(prepare_scene(scene).value(), render_options_for(scene));
    static_cast<void>(render_tile(*frame, {0, 0, 32, 32}));
    const ViewTable& table = frame->view_table();
    ASSERT_TRUE(table.built) << "the tiles traced through a view table";
    const ViewBand* lists = table.bands.data();
    static_cast<void>(render_tile(*frame, {32, 0, 64, 32}));
    EXPECT_EQ(&frame->view_table(), &table);
    EXPECT_EQ(frame->view_table().bands.data(), lists) << "later tiles reuse the same table";
}

TEST(RenderTile, BlocksThatMeetNothingAreTheBackgroundAsARayWouldFindIt) {
    // No plane and no sky map: most blocks of the view table list no shape,
    // and their pixels are written as the background without a ray. Each
    // pixel and the count of rays must be what tracing every pixel's ray
    // without the table gives, with a background that quantizing clamps.
    ParseResult parsed = parse_scene(R"(
render_settings { width: 67; height: 45; background: <0.3, 1.7, -0.2>; }
cameras { perspective_camera { position: <0, 0, 9>; look_at: <0, 0, 0>; aspect: 1.49; } }
scene {
    sphere { center: <-2, 0.5, 0>; radius: 0.6; material { pigment: <1, 0.2, 0.1>; diffuse: <1, 1, 1>; } }
    sphere { center: <1.5, -1, -1>; radius: 0.4; material { pigment: <0.2, 0.9, 0.1>; diffuse: <1, 1, 1>; } }
    sphere { center: <2.2, 1.4, 1>; radius: 0.3; material { pigment: <0.2, 0.3, 1>; diffuse: <1, 1, 1>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)");
    ASSERT_TRUE(parsed.ok());
    auto prepared = prepare_scene(parsed.scene).value();
    RenderOptions options = render_options_for(parsed.scene);
    options.previews = false;
    const auto frame = prepare_frame(prepared, options);
    const RenderedTile rendered = render_tile(*frame, {0, 0, 67, 45});
    ASSERT_TRUE(frame->view_table().built);
    std::uint64_t rays = 0;
    int background = 0;
    for (int y = 0; y < 45; ++y)
        for (int x = 0; x < 67; ++x) {
            const Vec3 d = camera_direction(frame->camera, x + 0.5, y + 0.5);
            const Colour c =
                trace_ray(*prepared, frame->camera.position, d, 0.0,
                          {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 0}, rays);
            const std::uint8_t* p = rendered.pixels.pixel(x, y);
            const std::uint8_t expected[3] = {quantize_channel(c.x), quantize_channel(c.y),
                                              quantize_channel(c.z)};
            ASSERT_TRUE(std::equal(p, p + 3, expected)) << "pixel " << x << ", " << y;
            background += p[0] == 77 && p[1] == 255 && p[2] == 0;
        }
    EXPECT_EQ(rendered.rays, rays);
    EXPECT_GT(background, 67 * 45 / 2) << "most of the image is the background";
}

}  // namespace
}  // namespace jt
