// CMYK JPEGs as image maps (docs/language.md §13.4): what print work and
// Photoshop save reads as the RGB picture browsers, Pillow and GIMP show,
// whether its inks are stored inverted (Adobe's APP14 segment) or not.

#include "jtracer/texture.hpp"

#include <gtest/gtest.h>

#include <jpeglib.h>
#include <cstdio>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <vector>

// Its own namespace: the image tests are built as one unit (unity build).
namespace jt::cmyk_test {
namespace {

struct Block {
    std::array<std::uint8_t, 4> ink;  // C, M, Y, K: 255 is full ink
    std::array<int, 3> rgb;           // what a viewer shows
};

// One row of 8 x 8 blocks, one ink each.
const std::array<Block, 6> kBlocks{{
    {{0, 0, 0, 0}, {255, 255, 255}},    // paper
    {{255, 0, 0, 0}, {0, 255, 255}},    // cyan
    {{0, 255, 0, 0}, {255, 0, 255}},    // magenta
    {{0, 0, 255, 0}, {255, 255, 0}},    // yellow
    {{0, 0, 0, 128}, {127, 127, 127}},  // half black
    {{255, 255, 0, 0}, {0, 0, 255}},    // cyan over magenta
}};
constexpr int kWidth = 8 * static_cast<int>(kBlocks.size()), kHeight = 8;

// A JPEG of the blocks in `space` (JCS_CMYK or JCS_YCCK), with or without
// Adobe's segment; with it, the samples are stored inverted as Adobe's
// programs store them.
std::vector<std::uint8_t> cmyk_jpeg(J_COLOR_SPACE space, bool adobe) {
    std::vector<std::uint8_t> samples;
    for (int x = 0; x < kWidth; ++x)
        for (std::uint8_t ink : kBlocks[static_cast<std::size_t>(x / 8)].ink)
            samples.push_back(adobe ? static_cast<std::uint8_t>(255 - ink) : ink);
    jpeg_compress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);
    jpeg_create_compress(&info);
    unsigned char* out = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &out, &size);
    info.image_width = kWidth;
    info.image_height = kHeight;
    info.input_components = 4;
    info.in_color_space = JCS_CMYK;
    jpeg_set_defaults(&info);
    jpeg_set_colorspace(&info, space);
    jpeg_set_quality(&info, 100, TRUE);
    for (int c = 0; c < 4; ++c)
        info.comp_info[c].h_samp_factor = info.comp_info[c].v_samp_factor = 1;
    info.write_Adobe_marker = adobe ? TRUE : FALSE;
    jpeg_start_compress(&info, TRUE);
    for (int y = 0; y < kHeight; ++y) {
        JSAMPROW row = samples.data();  // every row alike
        jpeg_write_scanlines(&info, &row, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::vector<std::uint8_t> bytes(out, out + size);
    std::free(out);
    return bytes;
}

void expect_blocks(const std::vector<std::uint8_t>& bytes) {
    const Expected<Texture> t = decode_texture(bytes);
    ASSERT_TRUE(t) << t.error().message;
    ASSERT_EQ(t->width, kWidth);
    ASSERT_EQ(t->height, kHeight);
    EXPECT_EQ(t->rgb8.size(), static_cast<std::size_t>(kWidth) * kHeight * 3);
    for (std::size_t b = 0; b < kBlocks.size(); ++b) {
        const Colour c = texel(*t, 8 * static_cast<int>(b) + 4, 4);
        const std::array<int, 3>& want = kBlocks[b].rgb;
        EXPECT_NEAR(c.x * 255.0f, want[0], 3.0f) << "block " << b;
        EXPECT_NEAR(c.y * 255.0f, want[1], 3.0f) << "block " << b;
        EXPECT_NEAR(c.z * 255.0f, want[2], 3.0f) << "block " << b;
    }
}

TEST(CmykJpeg, PhotoshopsYcckReadsAsTheColoursItsInksMake) {
    const std::vector<std::uint8_t> bytes = cmyk_jpeg(JCS_YCCK, true);
    ASSERT_FALSE(bytes.empty());
    expect_blocks(bytes);
}

TEST(CmykJpeg, InvertedCmykWithAdobesSegmentReadsAsItsInks) {
    expect_blocks(cmyk_jpeg(JCS_CMYK, true));
}

TEST(CmykJpeg, CmykWithoutAdobesSegmentReadsItsSamplesAsInkAmounts) {
    expect_blocks(cmyk_jpeg(JCS_CMYK, false));
}

}  // namespace
}  // namespace jt::cmyk_test
