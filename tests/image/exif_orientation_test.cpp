// JPEG image maps turned by their EXIF orientation (docs/language.md §13.4):
// for each of the 8 orientations, a picture stored as a camera would store
// it, tagged, reads as the upright picture every image viewer shows; a
// model's texture is read as stored (§14.5).

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/texture.hpp"

#include <gtest/gtest.h>
#include <turbojpeg.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace jt {
namespace {

namespace fs = std::filesystem;

// The upright picture: 3 x 2 blocks of 8 x 8 texels, each a colour of its
// own, so that every turn and mirror shows. Block (bx, by), by = 0 at the top.
constexpr int kBlocks = 3 * 2;
constexpr std::array<std::array<std::uint8_t, 3>, kBlocks> kColours{{
    {255, 0, 0},
    {0, 255, 0},
    {0, 0, 255},  // top row
    {255, 255, 0},
    {0, 255, 255},
    {255, 0, 255},  // bottom row
}};
constexpr int kWidth = 24, kHeight = 16;

const std::array<std::uint8_t, 3>& upright(int x, int y) {
    return kColours[static_cast<std::size_t>(y / 8 * 3 + x / 8)];
}

// Where the stored picture holds the texel shown at (x, y), by the EXIF
// standard's words for each value: which side of the picture as shown its
// stored row 0 and column 0 are ("row 0 at the right, column 0 at the top" is
// 6). Both with y = 0 at the top.
std::array<int, 2> stored_at(int orientation, int x, int y, int width, int height) {
    switch (orientation) {
        case 2:
            return {width - 1 - x, y};  // row 0 top, column 0 right
        case 3:
            return {width - 1 - x, height - 1 - y};  // row 0 bottom, column 0 right
        case 4:
            return {x, height - 1 - y};  // row 0 bottom, column 0 left
        case 5:
            return {y, x};  // row 0 left, column 0 top
        case 6:
            return {y, height - 1 - x};  // row 0 right, column 0 top
        case 7:
            return {width - 1 - y, height - 1 - x};  // row 0 right, column 0 bottom
        case 8:
            return {width - 1 - y, x};  // row 0 left, column 0 bottom
        default:
            return {x, y};  // row 0 top, column 0 left
    }
}

// An APP1 Exif segment whose IFD0 holds only the orientation, in either byte
// order.
std::vector<std::uint8_t> exif_segment(int orientation, bool big_endian) {
    auto u16 = [&](std::vector<std::uint8_t>& out, unsigned v) {
        if (big_endian)
            out.insert(out.end(), {std::uint8_t(v >> 8), std::uint8_t(v)});
        else
            out.insert(out.end(), {std::uint8_t(v), std::uint8_t(v >> 8)});
    };
    std::vector<std::uint8_t> tiff;
    if (big_endian)
        tiff = {'M', 'M'};
    else
        tiff = {'I', 'I'};
    u16(tiff, 42);
    u16(tiff, big_endian ? 0 : 8), u16(tiff, big_endian ? 8 : 0);  // IFD0 at 8
    u16(tiff, 1);                                                  // one entry
    u16(tiff, 0x0112), u16(tiff, 3);                               // orientation, SHORT
    u16(tiff, big_endian ? 0 : 1), u16(tiff, big_endian ? 1 : 0);  // count 1
    u16(tiff, static_cast<unsigned>(orientation)), u16(tiff, 0);
    u16(tiff, 0), u16(tiff, 0);  // no next IFD
    std::vector<std::uint8_t> segment{0xFF, 0xE1, 0, 0, 'E', 'x', 'i', 'f', 0, 0};
    segment.insert(segment.end(), tiff.begin(), tiff.end());
    const std::size_t length = segment.size() - 2;
    segment[2] = static_cast<std::uint8_t>(length >> 8);
    segment[3] = static_cast<std::uint8_t>(length);
    return segment;
}

// The upright picture stored as a camera with `orientation` stores it, as a
// JPEG (4:4:4, quality 100) with the tag after its SOI marker.
std::vector<std::uint8_t> tagged_jpeg(int orientation, bool big_endian) {
    const bool swap = orientation >= 5;
    const int width = swap ? kHeight : kWidth, height = swap ? kWidth : kHeight;
    std::vector<std::uint8_t> stored(static_cast<std::size_t>(width) * height * 3);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const auto [sx, sy] = stored_at(orientation, x, y, width, height);
            const auto& c = upright(x, y);
            std::copy(c.begin(), c.end(), stored.begin() + 3 * (sy * width + sx));
        }
    tjhandle handle = tjInitCompress();
    unsigned char* jpeg = nullptr;
    unsigned long size = 0;
    const int failed = tjCompress2(handle, stored.data(), width, 0, height, TJPF_RGB, &jpeg, &size,
                                   TJSAMP_444, 100, 0);
    tjDestroy(handle);
    if (failed) return {};
    std::vector<std::uint8_t> bytes(jpeg, jpeg + size);
    tjFree(jpeg);
    const std::vector<std::uint8_t> segment = exif_segment(orientation, big_endian);
    bytes.insert(bytes.begin() + 2, segment.begin(), segment.end());
    return bytes;
}

TEST(ExifOrientation, EachOfTheEightReadsAsTheUprightPicture) {
    for (int orientation = 1; orientation <= 8; ++orientation)
        for (const bool big_endian : {true, false}) {
            SCOPED_TRACE("orientation " + std::to_string(orientation) +
                         (big_endian ? ", big-endian" : ", little-endian"));
            const std::vector<std::uint8_t> bytes = tagged_jpeg(orientation, big_endian);
            ASSERT_FALSE(bytes.empty());
            const Expected<Texture> t = decode_texture(bytes);
            ASSERT_TRUE(t) << t.error().message;
            ASSERT_EQ(t->width, kWidth);
            ASSERT_EQ(t->height, kHeight);
            // Each block's centre, within what JPEG's rounding moves a flat block.
            for (int by = 0; by < 2; ++by)
                for (int bx = 0; bx < 3; ++bx) {
                    const int x = 8 * bx + 4, y = 8 * by + 4;
                    const Colour c = texel(*t, x, kHeight - 1 - y);  // row 0 at the bottom
                    const auto& want = upright(x, y);
                    EXPECT_NEAR(c.x * 255.0f, want[0], 4.0f) << "block " << bx << ", " << by;
                    EXPECT_NEAR(c.y * 255.0f, want[1], 4.0f) << "block " << bx << ", " << by;
                    EXPECT_NEAR(c.z * 255.0f, want[2], 4.0f) << "block " << bx << ", " << by;
                }
            if (const char* keep = std::getenv("JT_KEEP_EXIF_JPEGS"))
                test::write_file(std::string(keep) + "/o" + std::to_string(orientation) +
                                     (big_endian ? "m" : "i") + ".jpg",
                                 {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
        }
}

TEST(ExifOrientation, ADamagedOrMissingTagLeavesThePictureAsStored) {
    std::vector<std::uint8_t> bytes = tagged_jpeg(1, true);
    ASSERT_FALSE(bytes.empty());
    // Orientation 9 does not exist; a viewer shows the picture as stored.
    bytes[2 + 10 + 8 + 2 + 8] = 0, bytes[2 + 10 + 8 + 2 + 9] = 9;
    Expected<Texture> t = decode_texture(bytes);
    ASSERT_TRUE(t) << t.error().message;
    EXPECT_EQ(t->width, kWidth);
    EXPECT_NEAR(texel(*t, 4, kHeight - 1 - 4).x, 1.0f, 4.0f / 255.0f);  // red top left
    // An IFD offset past the segment's end.
    bytes = tagged_jpeg(6, false);
    bytes[2 + 10 + 4] = 0xF0;
    t = decode_texture(bytes);
    ASSERT_TRUE(t) << t.error().message;
    EXPECT_EQ(t->width, kHeight);  // as stored: 16 wide
}

// Whether `t` holds the upright picture as a camera with `orientation` stores
// it: each block's centre, found where stored_at puts it.
void expect_stored(const Texture& t, int orientation) {
    const bool swap = orientation >= 5;
    const int width = swap ? kHeight : kWidth, height = swap ? kWidth : kHeight;
    ASSERT_EQ(t.width, width);
    ASSERT_EQ(t.height, height);
    for (int by = 0; by < 2; ++by)
        for (int bx = 0; bx < 3; ++bx) {
            const int x = 8 * bx + 4, y = 8 * by + 4;
            const auto [sx, sy] = stored_at(orientation, x, y, width, height);
            const Colour c = texel(t, sx, height - 1 - sy);  // row 0 at the bottom
            const auto& want = upright(x, y);
            EXPECT_NEAR(c.x * 255.0f, want[0], 4.0f) << "block " << bx << ", " << by;
            EXPECT_NEAR(c.y * 255.0f, want[1], 4.0f) << "block " << bx << ", " << by;
            EXPECT_NEAR(c.z * 255.0f, want[2], 4.0f) << "block " << bx << ", " << by;
        }
}

// A model's UVs were made against its texture's stored texels, and 3D tools
// ignore the tag: the model reads the texture as stored, while the same file
// as an image map (load_texture's default) is turned, whichever is read
// first into the one cache.
TEST(ExifOrientation, AModelsTextureIsReadAsStoredAndAnImageMapTurned) {
    const std::vector<std::uint8_t> bytes = tagged_jpeg(6, false);
    ASSERT_FALSE(bytes.empty());
    for (const bool map_first : {true, false}) {
        SCOPED_TRACE(map_first ? "image map first" : "model first");
        test::ScratchDir dir;
        const fs::path photo = dir.path() / "photo.jpg";
        test::write_file(photo, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
        test::write_file(dir.path() / "m.obj",
                         "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                         "usemtl photo\nf 1/1 2/2 3/3\n");
        test::write_file(dir.path() / "m.mtl", "newmtl photo\nmap_Kd photo.jpg\n");

        Expected<std::shared_ptr<const Texture>> map = Error{"not read"};
        if (map_first) map = load_texture(photo);
        const Expected<Model> model = read_model(dir.path() / "m.obj", dir.path(), true);
        if (!map_first) map = load_texture(photo);
        ASSERT_TRUE(map) << map.error().message;
        ASSERT_TRUE(model) << model.error().message;
        ASSERT_EQ(model->parts.size(), 1u);
        ASSERT_NE(model->parts[0].texture, nullptr);
        {
            SCOPED_TRACE("image map");
            expect_stored(**map, 1);  // upright: as a picture stored unturned
        }
        {
            SCOPED_TRACE("model texture");
            expect_stored(*model->parts[0].texture, 6);
        }
        // Each use finds its own copy held.
        const Expected<std::shared_ptr<const Texture>> again = load_texture(photo);
        ASSERT_TRUE(again) << again.error().message;
        EXPECT_EQ(again->get(), map->get());
        const Expected<std::shared_ptr<const Texture>> stored =
            load_texture(photo, TextureLayout::as_stored);
        ASSERT_TRUE(stored) << stored.error().message;
        EXPECT_EQ(stored->get(), model->parts[0].texture.get());
    }
    // A texture inside a model file (a .glb's) is decoded as stored too.
    const Expected<Texture> embedded = decode_texture(bytes, TextureLayout::as_stored);
    ASSERT_TRUE(embedded) << embedded.error().message;
    SCOPED_TRACE("embedded");
    expect_stored(*embedded, 6);
}

// A picture no orientation turns is the same for both uses: held once.
TEST(ExifOrientation, APictureNotTurnedIsHeldOnceForBothUses) {
    test::ScratchDir dir;
    const std::vector<std::uint8_t> bytes = tagged_jpeg(1, true);
    ASSERT_FALSE(bytes.empty());
    test::write_file(dir.path() / "flat.jpg",
                     {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    const Expected<std::shared_ptr<const Texture>> stored =
        load_texture(dir.path() / "flat.jpg", TextureLayout::as_stored);
    ASSERT_TRUE(stored) << stored.error().message;
    const Expected<std::shared_ptr<const Texture>> shown = load_texture(dir.path() / "flat.jpg");
    ASSERT_TRUE(shown) << shown.error().message;
    EXPECT_EQ(shown->get(), stored->get());
    expect_stored(**shown, 1);
}

}  // namespace
}  // namespace jt
