// Image maps, worked out by hand from docs/language.md §13.4: texture
// coordinates of each shape, the bilinear blend, and files found beside the scene.

#include "common/image_header.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"
#include "jtracer/scene_file.hpp"
#include "render/pattern.hpp"
#include "render/prepared_scene.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

void expect_uv(Uv uv, double u, double v) {
    EXPECT_NEAR(uv.u, u, 1e-12);
    EXPECT_NEAR(uv.v, v, 1e-12);
}

TEST(ImageMap, SphereUvIsLatitudeLongitudeWithTheSeamAtMinusZ) {
    const Sphere s{{1, 2, 3}, 2.0};
    expect_uv(sphere_uv(s, Vec3(1, 2, 5)), 0.5, 0.5);   // +z: the middle
    expect_uv(sphere_uv(s, Vec3(3, 2, 3)), 0.75, 0.5);  // +x
    expect_uv(sphere_uv(s, Vec3(-1, 2, 3)), 0.25, 0.5);
    expect_uv(sphere_uv(s, Vec3(1, 4, 3)), 0.5, 1.0);  // the north pole
    expect_uv(sphere_uv(s, Vec3(1, 0, 3)), 0.5, 0.0);
    // 45 degrees up from +z: v = 0.5 + (pi/4) / pi.
    expect_uv(sphere_uv(s, Vec3(1, 2 + std::sqrt(2.0), 3 + std::sqrt(2.0))), 0.5, 0.75);
}

TEST(ImageMap, CylinderUvOnTheSideAndTheCaps) {
    const Cylinder c{0.5, 4.0};
    expect_uv(cylinder_uv(c, Vec3(0, 2, 0.5)), 0.5, 0.5);
    expect_uv(cylinder_uv(c, Vec3(0.5, 1, 0)), 0.75, 0.25);
    expect_uv(cylinder_uv(c, Vec3(0.25, 4, 0)), 0.75, 0.5);   // top cap
    expect_uv(cylinder_uv(c, Vec3(0, 0, -0.25)), 0.5, 0.25);  // bottom cap
}

TEST(ImageMap, PlaneUvFollowsItsAxes) {
    // Facing +z: e1 = +y, e2 = cross(z, y) = -x.
    expect_uv(plane_uv(Plane{{0, 0, 1}, 0}, 2.0, Vec3(-2, 3, 0)), 1.5, 1.0);
    // Facing +y: e1 = normalize(cross(y, z)) = +x, e2 = cross(y, x) = -z.
    expect_uv(plane_uv(Plane{{0, 5, 0}, 0}, 1.0, Vec3(0.25, 0, -0.75)), 0.25, 0.75);
    // Facing +x: e1 = cross(x, z) = -y, e2 = cross(x, -y) = -z.
    expect_uv(plane_uv(Plane{{1, 0, 0}, 0}, 1.0, Vec3(0, -0.5, -0.25)), 0.5, 0.25);
}

// A 2 x 2 picture, red only: bottom row 0 and 1, top row 0.5 and 0.25 (16-bit
// samples, where 0.5 and 0.25 are 32768 and 16384 / 65535 away from exact:
// the blend below is checked against the texels as they are).
Texture two_by_two() {
    Texture t{2, 2, {}, std::vector<std::uint16_t>(12, 0)};
    t.rgb16[0] = 0, t.rgb16[3] = 65535, t.rgb16[6] = 32768, t.rgb16[9] = 16384;
    return t;
}

TEST(ImageMap, BilinearBlendOfTheNearestTexelCentres) {
    const Texture t = two_by_two();
    const double half = 32768.0f / 65535.0f, quarter = 16384.0f / 65535.0f;
    EXPECT_EQ(texel(t, 0, 1).x, half);                       // value / 65535 in single precision
    EXPECT_EQ(sample_bilinear(t, {0.25, 0.25}).x, 0.0);      // texel (0, 0)'s centre
    EXPECT_EQ(sample_bilinear(t, {0.75, 0.25}).x, 1.0);      // texel (1, 0)
    EXPECT_EQ(sample_bilinear(t, {0.75, 0.75}).x, quarter);  // texel (1, 1)
    EXPECT_EQ(sample_bilinear(t, {0.5, 0.25}).x, 0.5);       // between (0, 0) and (1, 0)
    EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.5, 0.5}).x, (0 + 1 + half + quarter) / 4);
    // 3/8 of the way from (0, 0) to (1, 0), half-way up.
    EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.4375, 0.5}).x,
                     0.5 * (0.625 * 0.0 + 0.375 * 1.0) + 0.5 * (0.625 * half + 0.375 * quarter));
    // Past the left edge the blend wraps to the right column.
    EXPECT_EQ(sample_bilinear(t, {0.0, 0.25}).x, 0.5);
    EXPECT_EQ(sample_bilinear(t, {1.0, 0.25}).x, 0.5);    // u = 1 wraps to 0
    EXPECT_EQ(sample_bilinear(t, {-0.25, 0.25}).x, 1.0);  // tiled
}

fs::path scratch_dir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() /
                   ("jtracer_image_map_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// A 2 x 2 image with four distinct colours; pixel (0, 0) is the bottom left.
Image8 four_colours() {
    Image8 image(2, 2);
    const std::uint8_t colours[4][3] = {{51, 0, 0}, {0, 102, 0}, {0, 0, 153}, {255, 255, 0}};
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) image.pixel(k % 2, k / 2)[c] = colours[k][c];
    return image;
}

TEST(ImageMap, DecodesPngAndBmpToBytesOver255) {
    for (const auto& bytes : {encode_png(four_colours()), encode_bmp(four_colours())}) {
        Expected<Texture> t = decode_texture(bytes);
        ASSERT_TRUE(t) << t.error().message;
        ASSERT_EQ(t->width, 2);
        ASSERT_EQ(t->height, 2);
        // Kept as decoded, a byte a channel.
        EXPECT_EQ(t->rgb8.size(), 12u);
        EXPECT_TRUE(t->rgb16.empty());
        EXPECT_EQ(texel(*t, 0, 0).x, 51.0f / 255.0f);   // bottom left, red
        EXPECT_EQ(texel(*t, 1, 0).y, 102.0f / 255.0f);  // bottom right, green
        EXPECT_EQ(texel(*t, 0, 1).z, 153.0f / 255.0f);  // top left, blue
        EXPECT_EQ(texel(*t, 1, 1).x, 1.0f);
    }
    const std::vector<std::uint8_t> junk{'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'g'};
    EXPECT_FALSE(decode_texture(junk));
}

// A 1x1 RGB PNG whose image data is a zlib stream of one block of the
// reserved type 3 (stb_image failed on it without giving a reason).
std::vector<std::uint8_t> png_with_a_reserved_zlib_block() {
    std::vector<std::uint8_t> bytes = test::png_signature();
    auto chunk = [&](const char* type, const std::vector<std::uint8_t>& data) {
        test::append_png_chunk(bytes, type, data);
    };
    chunk("IHDR", {0, 0, 0, 1, 0, 0, 0, 1, 8, 2, 0, 0, 0});
    chunk("IDAT", {0x78, 0x01, 0x07});  // a zlib header, then a final block of type 3
    chunk("IEND", {});
    return bytes;
}

TEST(ImageMap, APngOfAReservedDeflateBlockIsAnErrorNotACrash) {
    // A model file's embedded texture like this one crashed the model fuzzer:
    // the message was built from stb_image's null reason.
    const std::vector<std::uint8_t> bytes = png_with_a_reserved_zlib_block();
    const Expected<Texture> texture = decode_texture(bytes);
    ASSERT_FALSE(texture);
    EXPECT_EQ(texture.error().message,
              "cannot decode the image: its data is damaged (IDAT: invalid block type)");
    const Expected<Image8> image = decode_png(bytes);
    ASSERT_FALSE(image);
    EXPECT_EQ(image.error().message,
              "not a readable PNG: its data is damaged (IDAT: invalid block type)");
}

TEST(ImageMap, APngCutAfterAWholeChunkSaysItsDataEndsEarly) {
    // A 64 x 64 picture of noise, its image data split over two IDAT chunks
    // and the file cut after the first: every chunk it has is whole.
    Image8 image(64, 64);
    std::uint32_t state = 7;
    for (std::uint8_t& byte : image.rgb) {
        state = state * 1664525u + 1013904223u;
        byte = static_cast<std::uint8_t>(state >> 24);
    }
    const std::vector<std::uint8_t> whole = encode_png(image);
    const auto idat =
        std::search(whole.begin(), whole.end(), std::begin("IDAT"), std::begin("IDAT") + 4);
    ASSERT_NE(idat, whole.end());
    const std::size_t length = std::size_t{idat[-4]} << 24 | std::size_t{idat[-3]} << 16 |
                               std::size_t{idat[-2]} << 8 | std::size_t{idat[-1]};
    const std::size_t half = length / 2;
    std::vector<std::uint8_t> cut(whole.begin(), idat - 4);  // the signature and IHDR
    for (int shift : {24, 16, 8, 0}) cut.push_back(static_cast<std::uint8_t>(half >> shift));
    cut.insert(cut.end(), idat, idat + 4 + static_cast<std::ptrdiff_t>(half));
    cut.insert(cut.end(), 4, 0);  // the CRC, which is not checked
    const Expected<Texture> texture = decode_texture(cut);
    ASSERT_FALSE(texture);
    // stb_image gave no reason here: the message ended in ": ".
    EXPECT_EQ(texture.error().message,
              "cannot decode the image: its data ends early (the file is truncated or damaged)");
}

// encode_bmp's bottom-up file of `image` stored top-down instead: the height
// negated and the rows in the opposite order (each padded to 4 bytes).
std::vector<std::uint8_t> top_down_bmp(const Image8& image) {
    std::vector<std::uint8_t> bytes = encode_bmp(image);
    const std::uint32_t height = ~static_cast<std::uint32_t>(image.height) + 1;
    for (int k = 0; k < 4; ++k) bytes[22 + k] = static_cast<std::uint8_t>(height >> (8 * k));
    const std::size_t offset = 54, stride = (static_cast<std::size_t>(image.width) * 3 + 3) & ~3u;
    std::vector<std::uint8_t> rows(bytes.begin() + offset, bytes.end());
    for (int j = 0; j < image.height; ++j)
        std::copy_n(rows.begin() + stride * (image.height - 1 - j), stride,
                    bytes.begin() + offset + stride * j);
    return bytes;
}

// 5 x 3 texels of distinct colours: rows of 15 bytes, padded to 16 in a BMP.
Image8 five_by_three() {
    Image8 image(5, 3);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) {
            std::uint8_t* p = image.pixel(i, j);
            p[0] = static_cast<std::uint8_t>(40 * i + 10);
            p[1] = static_cast<std::uint8_t>(80 * j + 20);
            p[2] = static_cast<std::uint8_t>(200 - 30 * i - 20 * j);
        }
    return image;
}

TEST(ImageMap, ATopDownBmpReadsAsTheSameBottomUpOne) {
    const Image8 image = five_by_three();
    const Expected<Texture> bottom_up = decode_texture(encode_bmp(image));
    const Expected<Texture> top_down = decode_texture(top_down_bmp(image));
    ASSERT_TRUE(bottom_up) << bottom_up.error().message;
    ASSERT_TRUE(top_down) << top_down.error().message;
    EXPECT_EQ(top_down->width, 5);
    EXPECT_EQ(top_down->height, 3);
    EXPECT_EQ(top_down->rgb8, bottom_up->rgb8);
    EXPECT_EQ(texel(*bottom_up, 4, 2).y, 180.0f / 255.0f);  // the top row

    // And a sphere mapped with each renders the same bytes, which show the map.
    const fs::path dir = scratch_dir("top_down");
    std::ofstream(dir / "bottom_up.bmp", std::ios::binary)
        .write(reinterpret_cast<const char*>(encode_bmp(image).data()),
               static_cast<std::streamsize>(encode_bmp(image).size()));
    const std::vector<std::uint8_t> flipped = top_down_bmp(image);
    std::ofstream(dir / "top_down.bmp", std::ios::binary)
        .write(reinterpret_cast<const char*>(flipped.data()),
               static_cast<std::streamsize>(flipped.size()));
    Scene s = scene_with_camera(camera_at({0, 0, 5}, {0, 0, 0}), 24, 24);
    s.asset_folder = dir.string();
    s.settings.ambient_light = Colour(1.0);
    Material m = glowing({1, 1, 1});
    m.finish.edit().image_map = "bottom_up.bmp";
    s.primitives = {sphere({0, 0, 0}, 1.5, m)};
    const Image8 from_bottom_up = render(s);
    s.primitives[0].material.finish.edit().image_map = "top_down.bmp";
    const Image8 from_top_down = render(s);
    EXPECT_EQ(from_top_down, from_bottom_up);
    EXPECT_NE(at(from_bottom_up, 12, 4), at(from_bottom_up, 12, 20));  // the map's rows differ
    fs::remove_all(dir);
}

// BMPs stb_image does not read say what they are, not "unknown image type".
TEST(ImageMap, AnUnsupportedBmpSaysWhatIsNotSupported) {
    auto with = [](std::size_t at, std::uint32_t value, int bytes) {
        std::vector<std::uint8_t> bmp = encode_bmp(five_by_three());
        for (int k = 0; k < bytes; ++k) bmp[at + k] = static_cast<std::uint8_t>(value >> (8 * k));
        return bmp;
    };
    const struct {
        std::vector<std::uint8_t> bytes;
        const char* problem;
    } cases[] = {
        {with(30, 1, 4), "RLE-compressed BMP is not supported"},
        {with(30, 2, 4), "RLE-compressed BMP is not supported"},
        {with(30, 4, 4), "JPEG-compressed BMP is not supported"},
        {with(30, 5, 4), "PNG-compressed BMP is not supported"},
        {with(30, 9, 4), "BMP compression type 9 is not supported"},
        {with(28, 2, 2), "a BMP of 2 bits a pixel is not supported (only 1, 4, 8, 16, 24 and 32)"},
        {with(14, 64, 4),
         "a BMP whose info header is 64 bytes long is not supported (only 12, 40, 56, 108 and "
         "124)"},
        {with(30, 3, 4), "a BMP with bit-field masks must have 16 or 32 bits a pixel, not 24"},
    };
    for (const auto& c : cases) {
        const Expected<Texture> t = decode_texture(c.bytes);
        ASSERT_FALSE(t) << c.problem;
        EXPECT_EQ(t.error().message, c.problem);
    }
}

// scenes/maps/label.jpg (4:2:0, quality 92): a cream label with red bands at
// rows 40-70 and 186-216 from the top; lossy, so within a few levels.
TEST(ImageMap, DecodesJpegThroughLibjpegTurbo) {
    std::ifstream in(fs::path(JT_SOURCE_DIR) / "scenes/maps/label.jpg", std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
    Expected<Texture> t = decode_texture(bytes);
    ASSERT_TRUE(t) << t.error().message;
    ASSERT_EQ(t->width, 512);
    ASSERT_EQ(t->height, 256);
    auto expect_texel = [&](int x, int row_from_top, int r, int g, int b) {
        const Colour c = texel(*t, x, 255 - row_from_top);
        EXPECT_NEAR(c.x * 255.0, r, 4.0) << x << "," << row_from_top;
        EXPECT_NEAR(c.y * 255.0, g, 4.0) << x << "," << row_from_top;
        EXPECT_NEAR(c.z * 255.0, b, 4.0) << x << "," << row_from_top;
    };
    expect_texel(20, 10, 0xf4, 0xef, 0xe4);    // cream
    expect_texel(20, 55, 0xb3, 0x26, 0x1e);    // the upper red band
    expect_texel(480, 200, 0xb3, 0x26, 0x1e);  // the lower one
    expect_texel(480, 240, 0xf4, 0xef, 0xe4);

    std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + bytes.size() / 2);
    const Expected<Texture> half = decode_texture(cut);
    ASSERT_FALSE(half);
    EXPECT_EQ(half.error().message.rfind("cannot read the JPEG: ", 0), 0u) << half.error().message;
}

// A plane facing +z at z = 0, image-mapped, seen head-on at the texel centre
// (i + 0.5) / 2, (j + 0.5) / 2: on it u = y and v = -x.
std::string plane_scene(const std::string& image, double x, double y) {
    const std::string at = "<" + std::to_string(x) + ", " + std::to_string(y);
    return "render_settings { width: 1; height: 1; ambient_light: <1, 1, 1>; }\n"
           "cameras { perspective_camera { position: " +
           at + ", 5>; look_at: " + at +
           ", 0>; } }\n"
           "scene { plane { normal: <0, 0, 1>; material { ambient: <1, 1, 1>;\n"
           "    image_map: \"" +
           image + "\"; } } }\n";
}

Image8 render_loaded(const fs::path& file) {
    Expected<LoadedScene> loaded = load_scene_file(file);
    EXPECT_TRUE(loaded);
    EXPECT_EQ(format_diagnostics(check_scene(*loaded), loaded->path, loaded->text), "");
    return render(loaded->parsed.scene);
}

TEST(ImageMap, APlaneShowsItsTexelsFoundBesideTheScene) {
    const fs::path dir = scratch_dir("plane");
    fs::create_directories(dir / "maps");
    ASSERT_TRUE(write_png(dir / "maps" / "four.png", four_colours()));
    // (u, v) = (0.25, 0.25): texel (0, 0); (0.75, 0.25): texel (1, 0); (0.25, 0.75): (0, 1).
    const struct {
        double x, y;
        Rgb colour;
    } cases[] = {{-0.25, 0.25, {51, 0, 0}}, {-0.25, 0.75, {0, 102, 0}}, {-0.75, 0.25, {0, 0, 153}}};
    for (const auto& c : cases) {
        std::ofstream(dir / "scene.jts") << plane_scene("maps/four.png", c.x, c.y);
        EXPECT_EQ(at(render_loaded(dir / "scene.jts"), 0, 0), c.colour) << c.x << ", " << c.y;
    }
    fs::remove_all(dir);
}

// check_scene's finding on a plane_scene whose map cannot be read: one error,
// at the opening quote of the image map's name.
Diagnostic map_error(const LoadedScene& loaded) {
    const std::vector<Diagnostic> found = check_scene(loaded);
    EXPECT_EQ(found.size(), 1u);
    if (found.empty()) return {};
    EXPECT_EQ(found[0].severity, Severity::error);
    EXPECT_EQ(found[0].pos.line, 4);
    EXPECT_EQ(found[0].pos.column, 16);
    return found[0];
}

TEST(ImageMap, AMissingImageIsALocatedError) {
    const fs::path dir = scratch_dir("missing");
    std::ofstream(dir / "scene.jts") << plane_scene("nowhere.png", 0, 0);
    Expected<LoadedScene> loaded = load_scene_file(dir / "scene.jts");
    ASSERT_TRUE(loaded);
    const Diagnostic error = map_error(*loaded);
    EXPECT_NE(error.message.find("image_map: cannot read"), std::string::npos) << error.message;
    EXPECT_NE(error.message.find("nowhere.png"), std::string::npos) << error.message;
    // prepare_scene refuses it too, for scenes that skip the checks.
    EXPECT_FALSE(prepare_scene(loaded->parsed.scene));
    fs::remove_all(dir);
}

// A JPEG cut short has a sound header: the check decodes it as the render
// would, and refuses it at its string with the render's own words.
TEST(ImageMap, ATruncatedJpegFailsTheCheckWithTheRendersError) {
    const fs::path dir = scratch_dir("truncated");
    std::ifstream in(fs::path(JT_SOURCE_DIR) / "scenes/maps/label.jpg", std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
    std::ofstream(dir / "cut.jpg", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size() * 2 / 3));
    std::ofstream(dir / "scene.jts") << plane_scene("cut.jpg", 0, 0);
    Expected<LoadedScene> loaded = load_scene_file(dir / "scene.jts");
    ASSERT_TRUE(loaded);
    const Diagnostic error = map_error(*loaded);
    const auto prepared = prepare_scene(loaded->parsed.scene);
    ASSERT_FALSE(prepared);
    EXPECT_EQ(error.message, prepared.error().message);
    EXPECT_NE(error.message.find("cut.jpg': cannot read the JPEG: "), std::string::npos)
        << error.message;
    fs::remove_all(dir);
}

// The check's decoded picture is the one the render uses: decoded once.
TEST(ImageMap, TheRenderUsesThePictureTheCheckDecoded) {
    const fs::path dir = scratch_dir("decoded_once");
    ASSERT_TRUE(write_png(dir / "four.png", four_colours()));
    std::ofstream(dir / "scene.jts") << plane_scene("four.png", 0, 0);
    Expected<LoadedScene> loaded = load_scene_file(dir / "scene.jts");
    ASSERT_TRUE(loaded);
    EXPECT_TRUE(check_scene(*loaded).empty());
    const Expected<std::shared_ptr<const Texture>> held = load_texture(dir / "four.png");
    ASSERT_TRUE(held);
    const auto prepared = prepare_scene(loaded->parsed.scene);
    ASSERT_TRUE(prepared) << prepared.error().message;
    EXPECT_EQ((*prepared)->textures[0].get(), held->get());
    fs::remove_all(dir);
}

TEST(ImageMap, OneFileIsLoadedOnceForEveryMaterialThatNamesIt) {
    const fs::path dir = scratch_dir("shared");
    ASSERT_TRUE(write_png(dir / "four.png", four_colours()));
    Scene s = scene_with_camera(camera_at({0, 0, 5}, {0, 0, 0}));
    s.asset_folder = dir.string();
    Material a = glowing({1, 0, 0}), b = glowing({0, 1, 0});
    a.finish.edit().image_map = b.finish.edit().image_map = "four.png";
    s.primitives = {sphere({0, 0, 0}, 1, a), sphere({3, 0, 0}, 1, b)};
    auto prepared = prepare_scene(s);
    ASSERT_TRUE(prepared) << prepared.error().message;
    const PreparedScene& p = **prepared;
    ASSERT_EQ(p.materials.size(), 2u);
    ASSERT_TRUE(p.textures[0]);
    EXPECT_EQ(p.textures[0].get(), p.textures[1].get());
    // And again from the previous prepared scene, without reading the file.
    fs::remove_all(dir);
    auto again = prepare_scene(s, *prepared);
    ASSERT_TRUE(again) << again.error().message;
    EXPECT_EQ((*again)->textures[0].get(), p.textures[0].get());
}

}  // namespace
}  // namespace jt::test
