// Regions as users type them, their conversion to image coordinates (the one
// row flip), region files, crop and paste with their contracts, and
// RenderJob::region_image against a full render.

#include "jtracer/region.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/check.hpp"
#include "jtracer/image.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/region_file.hpp"
#include "jtracer/render_job.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

namespace jt {
namespace {

TEST(Region, ParsesFourBounds) {
    const Expected<FrameRegion> r = parse_frame_region("10,20,110,70");
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(*r, (FrameRegion{10, 20, 110, 70}));
    EXPECT_EQ(format_frame_region(*r), "10,20,110,70");
}

TEST(Region, RefusesMalformedText) {
    for (const char* text : {"", "1,2,3", "1,2,3,4,5", "a,2,3,4", "1,,3,4", "1.5,2,3,4", "1,2,3,4,",
                             " 1,2,3,4", "99999999999,0,1,1"}) {
        const Expected<FrameRegion> r = parse_frame_region(text);
        ASSERT_FALSE(r) << text;
        EXPECT_NE(r.error().message.find("X0,Y0,X1,Y1"), std::string::npos)
            << text << ": " << r.error().message;
    }
}

TEST(Region, RefusesEmptyAndNegativeRegions) {
    const Expected<FrameRegion> empty = parse_frame_region("5,0,5,10");
    ASSERT_FALSE(empty);
    EXPECT_NE(empty.error().message.find("empty"), std::string::npos) << empty.error().message;
    EXPECT_FALSE(parse_frame_region("0,10,5,3"));
    const Expected<FrameRegion> negative = parse_frame_region("-1,0,5,3");
    ASSERT_FALSE(negative);
    EXPECT_NE(negative.error().message.find("negative"), std::string::npos)
        << negative.error().message;
}

TEST(Region, ChecksBoundsAgainstTheFrame) {
    EXPECT_TRUE(check_region_in_frame({0, 0, 200, 100}, 200, 100));
    const Expected<void> right = check_region_in_frame({0, 0, 201, 100}, 200, 100);
    ASSERT_FALSE(right);
    EXPECT_NE(right.error().message.find("right edge of the 200x100 image (X1 may be at most 200)"),
              std::string::npos)
        << right.error().message;
    const Expected<void> bottom = check_region_in_frame({0, 50, 10, 101}, 200, 100);
    ASSERT_FALSE(bottom);
    EXPECT_NE(bottom.error().message.find("bottom edge"), std::string::npos)
        << bottom.error().message;
}

TEST(Region, TopLeftOriginFlipsToImageRows) {
    // The top 10 rows of a 100-row frame are Image8 rows 90..99.
    EXPECT_EQ(to_image_rect({5, 0, 15, 10}, 100), (PixelRect{5, 90, 15, 100}));
    EXPECT_EQ(to_frame_region({5, 90, 15, 100}, 100), (FrameRegion{5, 0, 15, 10}));
}

TEST(Region, CropAndPasteAreInverse) {
    Image8 image(7, 5);
    for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i);
    Image8 part = crop_image(image, {2, 1, 6, 4});
    ASSERT_EQ(part.width, 4);
    ASSERT_EQ(part.height, 3);
    EXPECT_EQ(part.pixel(0, 0)[0], image.pixel(2, 1)[0]);
    EXPECT_EQ(part.pixel(3, 2)[2], image.pixel(5, 3)[2]);
    Image8 frame(7, 5);
    paste_image(frame, part, 2, 1);
    EXPECT_EQ(crop_image(frame, {2, 1, 6, 4}), part);
    EXPECT_EQ(frame.pixel(1, 1)[0], 0);
}

class RegionFile : public test::ScratchTest {
  protected:
    const std::filesystem::path path = dir / "region.bmp";
};

TEST_F(RegionFile, RoundTripsPixelsAndPlacement) {
    Image8 part(3, 2);
    for (std::size_t i = 0; i < part.rgb.size(); ++i)
        part.rgb[i] = static_cast<std::uint8_t>(40 * i);
    RegionPlacement placement{640, 480, {100, 200, 103, 202}};
    const Expected<void> written = write_region_bmp(path, part, placement);
    ASSERT_TRUE(written) << written.error().message;
    const Expected<RegionPart> read = read_region_bmp(path);
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_EQ(read->name, path.string());
    EXPECT_EQ(read->pixels, part);
    EXPECT_EQ(read->placement, placement);
    // Still an ordinary BMP for every other reader.
    const Expected<Image8> plain = read_bmp(path);
    ASSERT_TRUE(plain) << plain.error().message;
    EXPECT_EQ(*plain, part);
}

TEST_F(RegionFile, RoundTripsTheFingerprint) {
    Image8 part(2, 2);
    RegionPlacement placement{64, 48, {0, 0, 2, 2}};
    placement.fingerprint =
        RenderFingerprint{{}, 16, 2, "a camera name longer than 32 bytes!", 0.25};
    for (std::size_t i = 0; i < 16; ++i)
        placement.fingerprint->scene[i] = static_cast<std::uint8_t>(17 * i);
    ASSERT_TRUE(write_region_bmp(path, part, placement));
    const Expected<RegionPart> read = read_region_bmp(path);
    ASSERT_TRUE(read) << read.error().message;
    ASSERT_TRUE(read->placement.fingerprint);
    // The name is kept for messages only: its first 32 bytes.
    placement.fingerprint->camera_name.resize(32);
    EXPECT_EQ(read->placement.fingerprint->camera_name, "a camera name longer than 32 byt");
    EXPECT_EQ(read->placement, placement);
    const Expected<Image8> plain = read_bmp(path);
    ASSERT_TRUE(plain) << plain.error().message;
    EXPECT_EQ(*plain, part);
}

TEST_F(RegionFile, PlainBmpHasNoRecord) {
    ASSERT_TRUE(write_bmp(path, Image8(4, 4)));
    const Expected<RegionPart> part = read_region_bmp(path);
    ASSERT_FALSE(part);
    EXPECT_NE(part.error().message.find("carries no region record"), std::string::npos)
        << part.error().message;
}

// A region job keeps only the region and gives exactly the full render's pixels.
TEST(RegionImage, EqualsTheFullRenderCroppedForEverySampleCount) {
    ParseResult parsed = parse_scene(R"(
render_settings { width: 75; height: 41; recurse_depth: 3; }
cameras { perspective_camera { position: <0, 1.2, 5>; look_at: <0, 0.5, 0>; aspect: 1.83; } }
scene {
    plane { material { pigment: <0.8, 0.8, 0.8>; diffuse: <1, 1, 1>; reflection: 0.4; } }
    sphere { center: <-0.6, 0.7, 0>; radius: 0.7;
             material { pigment: <1, 0.2, 0.1>; diffuse: <1, 1, 1>; specular: <1, 1, 1>; } }
    cylinder { radius: 0.3; height: 1.2; transform { xrotate: 30; translate: <1.2, 0, 0>; }
               material { pigment: <0.2, 0.4, 1>; diffuse: <1, 1, 1>; reflection: 0.5; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)");
    ASSERT_TRUE(parsed.ok());
    auto prepared = prepare_scene(parsed.scene).value();
    for (int samples : {1, 3, 8}) {
        RenderOptions o;
        o.width = 75;
        o.height = 41;
        o.samples = samples;
        Image8 full = render_image(prepared, o);
        for (PixelRect rect : {PixelRect{0, 0, 75, 41}, PixelRect{33, 0, 75, 17},
                               PixelRect{1, 30, 2, 41}, PixelRect{40, 9, 71, 38}}) {
            o.region = rect;
            o.previews = samples == 3;  // previews must not change the final pixels
            RenderJob job(prepared, o);
            job.run();
            EXPECT_EQ(job.region_image(), crop_image(full, rect))
                << samples << " samples, x " << rect.x0 << ".." << rect.x1 << ", y " << rect.y0
                << ".." << rect.y1;
            Image8 whole = job.image();
            ASSERT_EQ(whole.width, 75);
            EXPECT_EQ(crop_image(whole, rect), crop_image(full, rect));
        }
    }
}

// The viewer's path: fetch_updates fills a full-size display from a region job.
TEST(RegionImage, FetchUpdatesPlacesTheRegionInTheFullImage) {
    ParseResult parsed = parse_scene(R"(
render_settings { width: 40; height: 30; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1.3333; } }
scene {
    sphere { radius: 1.5; material { pigment: <1, 0.5, 0.2>; diffuse: <1, 1, 1>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)");
    ASSERT_TRUE(parsed.ok());
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    o.samples = 2;
    o.region = PixelRect{5, 3, 29, 21};
    RenderJob job(prepare_scene(parsed.scene).value(), o);
    Image8 display;
    ASSERT_TRUE(job.fetch_updates(display));
    EXPECT_EQ(display.width, 40);
    job.run();
    auto changed = job.fetch_updates(display);
    ASSERT_TRUE(changed);
    EXPECT_EQ(*changed, (PixelRect{5, 3, 29, 21}));
    EXPECT_EQ(display, job.image());
    EXPECT_EQ(crop_image(display, *o.region), job.region_image());
    int lit = 0;
    for (std::uint8_t c : job.region_image().rgb) lit += c > 0;
    EXPECT_GT(lit, 0) << "the sphere shows in the region";
}

// Every region of small frames, to image rows and back: the rows a region
// names from the top are the image's rows flipped_row maps them to.
TEST(Region, EveryRegionFlipsThroughFlippedRowAndBack) {
    for (int h = 1; h <= 5; ++h)
        for (int top = 0; top < h; ++top)
            for (int bottom = top + 1; bottom <= h; ++bottom) {
                const FrameRegion region{1, top, 3, bottom};
                const PixelRect rect = to_image_rect(region, h);
                EXPECT_EQ(rect.height(), region.height());
                EXPECT_EQ(rect.y1 - 1, flipped_row(top, h)) << "the region's top row";
                EXPECT_EQ(rect.y0, flipped_row(bottom - 1, h)) << "the region's bottom row";
                EXPECT_EQ(to_frame_region(rect, h), region);
            }
    EXPECT_EQ(flipped_row(0, 4), 3);
    EXPECT_EQ(flipped_row(3, 4), 0);
}

// The contracts of crop_image and paste_image (JT_DCHECK): checked in debug
// and sanitizer builds, where breaking one stops the program and says which.
TEST(RegionContracts, CropAndPasteOutsideTheImageStop) {
    if (!kContractsChecked) GTEST_SKIP() << "contracts are compiled out of this build";
    testing::FLAGS_gtest_death_test_style = "threadsafe";
    Image8 frame(4, 4);
    const Image8 part(3, 3);
    EXPECT_DEATH(paste_image(frame, part, 2, 2), "contract broken: the part fits inside the frame");
    EXPECT_DEATH(crop_image(frame, {0, 0, 5, 4}),
                 "contract broken: the rectangle lies inside the image");
}

// A release build compiles the check out: its condition is not evaluated.
TEST(RegionContracts, OnlyCheckedBuildsEvaluateTheCondition) {
    int evaluated = 0;
    JT_DCHECK(++evaluated > 0, "counts its evaluations");
    EXPECT_EQ(evaluated, kContractsChecked ? 1 : 0);
}

}  // namespace
}  // namespace jt
