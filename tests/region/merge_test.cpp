// merge_regions: what makes one frame out of parts, and what it refuses.

#include "jtracer/merge_regions.hpp"

#include <gtest/gtest.h>

namespace jt {
namespace {

// A part of a 6x4 frame whose pixels encode their frame position.
RegionPart part(const std::string& name, FrameRegion region, int frame_w = 6, int frame_h = 4) {
    RegionPart p;
    p.name = name;
    p.placement = {frame_w, frame_h, region};
    p.pixels = Image8(region.width(), region.height());
    for (int y = 0; y < region.height(); ++y)
        for (int x = 0; x < region.width(); ++x) {
            // Image8 row y of the part is frame row (top-left origin) bottom - 1 - y.
            p.pixels.pixel(x, y)[0] = static_cast<std::uint8_t>(region.left + x);
            p.pixels.pixel(x, y)[1] = static_cast<std::uint8_t>(region.bottom - 1 - y);
        }
    return p;
}

// Why merge_regions refuses `parts`; empty when it accepts them.
std::string refusal(const std::vector<RegionPart>& parts) {
    const Expected<Image8> frame = merge_regions(parts);
    return frame ? std::string() : frame.error().message;
}

TEST(Merge, AssemblesPartsInAnyOrder) {
    std::vector<RegionPart> parts = {part("b", {0, 2, 6, 4}), part("c", {4, 0, 6, 2}),
                                     part("a", {0, 0, 4, 2})};
    const Expected<Image8> merged = merge_regions(parts);
    ASSERT_TRUE(merged) << merged.error().message;
    const Image8& frame = *merged;
    ASSERT_EQ(frame.width, 6);
    ASSERT_EQ(frame.height, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) {
            EXPECT_EQ(frame.pixel(x, y)[0], x);
            EXPECT_EQ(frame.pixel(x, y)[1], 3 - y) << "top-left origin: Image8 row 0 is the bottom";
        }
}

TEST(Merge, RefusesOverlap) {
    EXPECT_EQ(refusal({part("a", {0, 0, 4, 4}), part("b", {3, 0, 6, 4})}),
              "a (region 0,0,4,4) overlaps b (region 3,0,6,4)");
}

TEST(Merge, RefusesAPartGivenTwice) {
    EXPECT_EQ(refusal({part("a", {0, 0, 6, 4}), part("a", {0, 0, 6, 4})}), "a is given twice");
}

TEST(Merge, RefusesGapsNamingAnUncoveredPixel) {
    const std::string error = refusal({part("a", {0, 0, 6, 2}), part("b", {0, 2, 5, 4})});
    EXPECT_NE(error.find("gap: no part covers pixel 5,2"), std::string::npos) << error;
}

TEST(Merge, RefusesPartsOfDifferentFrames) {
    EXPECT_EQ(refusal({part("a", {0, 0, 6, 2}), part("b", {0, 2, 6, 4}, 6, 5)}),
              "b is a part of a 6x5 frame, but a of a 6x4 one");
}

TEST(Merge, RefusesPixelsThatDoNotMatchTheDeclaredRegion) {
    RegionPart bad = part("b", {0, 2, 6, 4});
    bad.pixels = Image8(6, 1);
    EXPECT_EQ(refusal({part("a", {0, 0, 6, 2}), bad}),
              "b holds 6x1 pixels, but declares the 6x2 region 0,2,6,4");
}

TEST(Merge, RefusesPartsOutOfTheFrame) {
    RegionPart out = part("b", {0, 2, 6, 5});
    const std::string error = refusal({part("a", {0, 0, 6, 2}), out});
    EXPECT_NE(error.find("b: region 0,2,6,5 reaches past the bottom edge"), std::string::npos)
        << error;
}

TEST(Merge, RefusesNoParts) {
    EXPECT_EQ(refusal({}), "no parts to merge");
}

}  // namespace
}  // namespace jt
