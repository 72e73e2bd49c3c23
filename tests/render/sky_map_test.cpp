// Sky maps, worked out by hand from docs/language.md §14.3: the direction's
// place on the map, rows clamped at the poles and columns wrapped at the seam,
// and every ray that meets nothing (camera, reflected, refracted) showing it
// while shadows and the ambient term do not.

#include "render/sky_map.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"
#include "jtracer/scene_file.hpp"
#include "render/prepared_scene.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

constexpr int map_width = 9;   // odd: straight down -z is the centre of column 4
constexpr int map_height = 5;  // odd: the horizon is the centre of row 2

// Texel (i, j) of the test map, each one a different colour; red is not
// linear in i, so that no blend of two columns looks like a third.
Rgb map_texel(int i, int j) {
    return {3 * i * i + 10, 40 * j + 20, 200 - 12 * i - 15 * j};
}

Image8 sky_picture() {
    Image8 image(map_width, map_height);
    for (int j = 0; j < map_height; ++j)
        for (int i = 0; i < map_width; ++i) {
            const Rgb c = map_texel(i, j);
            std::uint8_t* p = image.pixel(i, j);
            p[0] = static_cast<std::uint8_t>(c.r);
            p[1] = static_cast<std::uint8_t>(c.g);
            p[2] = static_cast<std::uint8_t>(c.b);
        }
    return image;
}

// A scratch folder holding the map as sky.png and as sky.bmp.
class SkyMap : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("jtracer_sky_map_test_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
               std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        ASSERT_TRUE(write_png(dir / "sky.png", sky_picture()));
        ASSERT_TRUE(write_bmp(dir / "sky.bmp", sky_picture()));
    }
    void TearDown() override { fs::remove_all(dir); }

    // A 1 x 1 image from the origin along `look`, the map behind everything.
    Scene looking(const Vec3& look, const Vec3& up = {0, 1, 0},
                  const std::string& map = "sky.png") const {
        Scene s = scene_with_camera(camera_at({0, 0, 0}, look, up));
        s.asset_folder = dir.string();
        s.settings.background = {1, 0, 1};  // never seen while the map is
        s.settings.background_map = map;
        return s;
    }

    fs::path dir;
};

void expect_uv(Uv uv, double u, double v) {
    EXPECT_EQ(uv.u, u);
    EXPECT_EQ(uv.v, v);
}

TEST(SkyUv, MinusZIsTheCentreAndVRunsFromStraightDownToStraightUp) {
    expect_uv(sky_uv({0, 0, -1}), 0.5, 0.5);
    expect_uv(sky_uv({1, 0, 0}), 0.75, 0.5);
    expect_uv(sky_uv({-1, 0, 0}), 0.25, 0.5);
    expect_uv(sky_uv({0, 0, 1}), 1.0, 0.5);  // the seam faces +z: 1 wraps to 0
    EXPECT_EQ(sky_uv({0, 1, 0}).v, 1.0);
    EXPECT_EQ(sky_uv({0, -1, 0}).v, 0.0);
    // A unit vector may round to a y just past 1: clamped before asin.
    EXPECT_EQ(sky_uv({0, 1.0000000000000002, 0}).v, 1.0);
    EXPECT_NEAR(sky_uv(glm::normalize(Vec3(0, 1, -1))).v, 0.75, 1e-15);
}

TEST_F(SkyMap, StraightDownMinusZShowsTheCentreTexel) {
    for (const char* map : {"sky.png", "sky.bmp"}) {
        SCOPED_TRACE(map);
        EXPECT_EQ(at(render(looking({0, 0, -1}, {0, 1, 0}, map)), 0, 0), map_texel(4, 2));
    }
}

// Written in a .jts file: found beside it, checked clean, rendered.
TEST_F(SkyMap, AScenesMapIsFoundBesideItAndChecksClean) {
    std::ofstream(dir / "scene.jts") << "render_settings { width: 1; height: 1;\n"
                                        "    background_map: \"sky.png\"; }\n"
                                        "cameras { perspective_camera { } }\nscene { }\n";
    Expected<LoadedScene> loaded = load_scene_file(dir / "scene.jts");
    ASSERT_TRUE(loaded) << loaded.error().message;
    EXPECT_EQ(format_diagnostics(check_scene(*loaded), loaded->path, loaded->text), "");
    EXPECT_EQ(at(render(loaded->parsed.scene), 0, 0), map_texel(4, 2));
}

// Straight up is the top row and straight down the bottom one, whatever the
// column; near the pole the row is not blended with the other pole's, as a
// wrapped v would be.
TEST_F(SkyMap, RowsAreClampedAtThePoles) {
    Image8 banded(map_width, map_height);  // each row one colour
    for (int j = 0; j < map_height; ++j)
        for (int i = 0; i < map_width; ++i)
            for (int c = 0; c < 3; ++c)
                banded.pixel(i, j)[c] = static_cast<std::uint8_t>(40 * j + 30 + 10 * c);
    ASSERT_TRUE(write_png(dir / "banded.png", banded));
    auto row = [](int j) { return Rgb{40 * j + 30, 40 * j + 40, 40 * j + 50}; };
    EXPECT_EQ(at(render(looking({0, 1, 0}, {0, 0, -1}, "banded.png")), 0, 0), row(4));
    EXPECT_EQ(at(render(looking({0, -1, 0}, {0, 0, -1}, "banded.png")), 0, 0), row(0));
    // 85 degrees up: v = 0.5 + 85/180 = 0.972, past the top row's centre (0.9).
    const double up = 85.0 * M_PI / 180.0;
    EXPECT_EQ(at(render(looking({std::cos(up), std::sin(up), 0}, {0, 0, -1}, "banded.png")), 0, 0),
              row(4));
    EXPECT_EQ(at(render(looking({std::cos(up), -std::sin(up), 0}, {0, 0, -1}, "banded.png")), 0, 0),
              row(0));
    // 9 degrees up: v = 0.55, a quarter of the way from row 2's centre (0.5)
    // to row 3's (0.7): 3/4 of (110, 120, 130) and 1/4 of (150, 160, 170).
    const Scene between = looking({1, std::tan(9.0 * M_PI / 180.0), 0}, {0, 1, 0}, "banded.png");
    EXPECT_EQ(at(render(between), 0, 0), (Rgb{120, 130, 140}));
}

// Across the seam (+z) the colour is continuous: both sides blend the last
// column with the first, as an image map wraps.
TEST_F(SkyMap, ColumnsWrapAtTheSeam) {
    const Expected<std::shared_ptr<const Texture>> map = load_texture(dir / "sky.png");
    ASSERT_TRUE(map) << map.error().message;
    const Texture& t = **map;
    const Colour seam = 0.5 * texel(t, 8, 2) + 0.5 * texel(t, 0, 2);
    for (double side : {1e-9, -1e-9}) {
        const Colour c = sky_colour(t, glm::normalize(Vec3(side, 0, 1)));
        EXPECT_NEAR(c.x, seam.x, 1e-6) << side;
        EXPECT_NEAR(c.y, seam.y, 1e-6) << side;
        EXPECT_NEAR(c.z, seam.z, 1e-6) << side;
    }
    // Half of column 8 (202, 100, 74), half of column 0 (10, 100, 170).
    EXPECT_EQ(expected(seam), (Rgb{106, 100, 122}));
    EXPECT_EQ(at(render(looking({0, 0, 1})), 0, 0), expected(seam));
    // On the horizon to +x, u = 0.75: 3/4 of column 6 (118, 100, 98), 1/4 of
    // column 7 (157, 100, 86).
    EXPECT_EQ(at(render(looking({1, 0, 0})), 0, 0), (Rgb{128, 100, 95}));
}

// A mirror facing the camera sends the ray back along -z: it shows the centre
// texel, scaled by its reflection.
TEST_F(SkyMap, AMirrorSphereReflectsTheMap) {
    Scene s = looking({0, 0, 1});
    s.settings.recurse_depth = 1;
    Material mirror;  // black: only the reflection shows
    mirror.finish.edit().reflection = 1.0;
    s.primitives = {sphere({0, 0, 3}, 1.0, mirror)};
    EXPECT_EQ(at(render(s), 0, 0), map_texel(4, 2));
    s.primitives[0].material.finish.edit().reflection = 0.5;
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{29, 50, 61}));  // half of (58, 100, 122)
    // Without a bounce the mirror is black, not the map.
    s.settings.recurse_depth = 0;
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));
}

// Straight through the centre of a glass sphere, the ray leaves along -z.
TEST_F(SkyMap, RefractedRaysSeeTheMap) {
    Scene s = scene_with_camera(camera_at({0, 0, 5}, {0, 0, 0}));
    s.asset_folder = dir.string();
    s.settings.background_map = "sky.png";
    s.settings.recurse_depth = 2;  // in and out
    Material glass;
    glass.finish.edit().transmission = 1.0;
    glass.finish.edit().ior = 1.5;
    s.primitives = {sphere({0, 0, 0}, 1.0, glass)};
    EXPECT_EQ(at(render(s), 0, 0), map_texel(4, 2));
    s.settings.recurse_depth = 1;  // still inside: black
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));
}

// A floor filling the view, lit from the side past a sphere: the floor and
// the sphere are the same bytes with and without a white map, which no shadow
// ray or ambient term looks at. In the shadow only the ambient term is left.
TEST_F(SkyMap, ShadowsAndTheAmbientTermDoNotUseIt) {
    Image8 white(4, 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            for (int c = 0; c < 3; ++c) white.pixel(i, j)[c] = 255;
    ASSERT_TRUE(write_png(dir / "white.png", white));
    // Looking down -y with -z up: world +x is to the right, z = 0 the middle row.
    Scene s = scene_with_camera(camera_at({0, 8, 0}, {0, 0, 0}, {0, 0, -1}), 24, 24);
    s.asset_folder = dir.string();
    s.settings.ambient_light = {0.2, 0.2, 0.2};
    Material floor = matte({0.8, 0.7, 0.6});
    floor.finish.edit().ambient = Colour(1.0);
    s.primitives = {plane({0, 1, 0}, 0.0, floor), sphere({0, 1, 0}, 0.5, matte({1, 1, 1}))};
    // The sphere's shadow is centred at (1.2, 0, 0): pixel column 16.
    s.lights = {{{-6, 6, 0}, Colour(0.7)}};
    const Image8 without = render(s);
    EXPECT_EQ(at(without, 16, 12), expected(0.2 * Colour(0.8, 0.7, 0.6)));
    EXPECT_NE(at(without, 8, 12), at(without, 16, 12));  // lit, left of the sphere
    s.settings.background_map = "white.png";
    EXPECT_EQ(render(s), without);
    // The map is in use: looking up, the camera sees it.
    s.cameras[0] = camera_at({0, 8, 0}, {0, 16, 0}, {0, 0, -1});
    EXPECT_EQ(at(render(s), 12, 12), (Rgb{255, 255, 255}));
}

// Without a map a ray that meets nothing is `background` (docs/language.md §8.4).
TEST_F(SkyMap, WithoutAMapMissesAreTheBackground) {
    Scene s = looking({0, 0, -1});
    s.settings.background_map.clear();
    s.settings.background = {0.2, 0.4, 0.6};
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{51, 102, 153}));
    const auto prepared = prepare_scene(s);
    ASSERT_TRUE(prepared) << prepared.error().message;
    EXPECT_EQ((*prepared)->background_map, nullptr);
}

// The shortcut for rays that can meet nothing (no plane, no triangle, no
// shape in the block) returns what trace_ray does: a plane behind the camera,
// which no ray reaches, turns the shortcut off and changes no byte, whatever
// the threads.
TEST_F(SkyMap, EveryPathOfAMissGivesTheSameBytes) {
    Scene s = looking({0, 0, -1});
    // Every ray within 70 degrees of -z.
    s.cameras[0] = camera_at({0, 0, 0}, {0.3, 0.2, -1}, {0, 1, 0}, 60.0, 1.5);
    s.settings.width = 60;
    s.settings.height = 40;
    s.primitives = {sphere({0.5, 0, -4}, 1.0, matte({1, 1, 1}))};
    const Image8 shortcut = render(s, 1, 1);
    EXPECT_EQ(render(s, 1, 3), shortcut);
    Scene planed = s;
    planed.primitives.push_back(plane({0, 0, 1}, 100.0, matte({1, 0, 0})));
    EXPECT_EQ(render(planed, 1, 2), shortcut);
    // Reflections and samples, on one thread or three.
    s.settings.recurse_depth = 2;
    s.primitives[0].material.finish.edit().reflection = 0.9;
    EXPECT_EQ(render(s, 4, 1), render(s, 4, 3));
    EXPECT_NE(render(s, 1, 1), shortcut);
}

// The check's decoded picture is the render's, shared with an image map of
// the same file, and kept from the previous prepared scene while unchanged.
TEST_F(SkyMap, TheMapIsDecodedOnceAndShared) {
    Scene s = looking({0, 0, -1});
    Material m = glowing({1, 1, 1});
    m.finish.edit().image_map = "sky.png";
    s.primitives = {sphere({0, 0, -5}, 1.0, m)};
    const Expected<std::shared_ptr<const Texture>> held = load_texture(dir / "sky.png");
    ASSERT_TRUE(held);
    const auto prepared = prepare_scene(s);
    ASSERT_TRUE(prepared) << prepared.error().message;
    EXPECT_EQ((*prepared)->background_map.get(), held->get());
    EXPECT_EQ((*prepared)->textures[0].get(), held->get());
    s.primitives.clear();
    fs::remove(dir / "sky.png");  // gone for the moment, as while an editor saves it
    const auto again = prepare_scene(s, *prepared);
    ASSERT_TRUE(again) << again.error().message;
    EXPECT_EQ((*again)->background_map.get(), held->get());
}

// check_scene's one finding on a scene whose map is `name`.
Diagnostic check_one(const fs::path& dir, const std::string& name) {
    std::ofstream(dir / "scene.jts") << "render_settings { width: 1; height: 1;\n"
                                        "    background_map: \"" +
                                            name +
                                            "\"; }\n"
                                            "cameras { perspective_camera { } }\nscene { }\n";
    Expected<LoadedScene> loaded = load_scene_file(dir / "scene.jts");
    EXPECT_TRUE(loaded);
    if (!loaded) return {};
    const std::vector<Diagnostic> found = check_scene(*loaded);
    EXPECT_EQ(found.size(), 1u) << format_diagnostics(found, loaded->path, loaded->text);
    if (found.size() != 1) return {};
    EXPECT_EQ(found[0].severity, Severity::error);
    EXPECT_EQ(found[0].pos.line, 2);
    EXPECT_EQ(found[0].pos.column, 21);
    // The render refuses it too, for scenes that skip the checks, in the same words.
    const auto prepared = prepare_scene(loaded->parsed.scene);
    EXPECT_FALSE(prepared);
    if (!prepared) {
        EXPECT_EQ(prepared.error().message, found[0].message);
    }
    return found[0];
}

TEST_F(SkyMap, AMissingMapIsALocatedErrorWithTheRendersWords) {
    const Diagnostic d = check_one(dir, "nowhere.png");
    EXPECT_EQ(d.message, "background_map: cannot read '" + (dir / "nowhere.png").string() +
                             "': no such file");
}

TEST_F(SkyMap, ACorruptMapIsALocatedErrorWithTheRendersWords) {
    std::ofstream(dir / "junk.png") << "not a picture at all";
    const Diagnostic d = check_one(dir, "junk.png");
    EXPECT_EQ(d.message.rfind("background_map: '" + (dir / "junk.png").string() +
                                  "': not a readable PNG, JPEG or BMP image",
                              0),
              0u)
        << d.message;
}

TEST_F(SkyMap, ADirectoryIsNotAMap) {
    fs::create_directory(dir / "folder.png");
    const Diagnostic d = check_one(dir, "folder.png");
    EXPECT_EQ(d.message, "background_map: cannot read '" + (dir / "folder.png").string() +
                             "': it is a directory, not a file");
}

// "" is the model's "no map", so only the check, which sees it written, refuses it.
TEST_F(SkyMap, AnEmptyNameIsALocatedError) {
    std::ofstream(dir / "scene.jts") << "render_settings { width: 1; height: 1;\n"
                                        "    background_map: \"\"; }\n"
                                        "cameras { perspective_camera { } }\nscene { }\n";
    Expected<LoadedScene> loaded = load_scene_file(dir / "scene.jts");
    ASSERT_TRUE(loaded);
    EXPECT_EQ(format_diagnostics(check_scene(*loaded), "scene.jts", loaded->text),
              "scene.jts:2:21: error: background_map: the file name is empty (leave "
              "'background_map' out to show the background colour)\n"
              "        background_map: \"\"; }\n"
              "                        ^\n");
}

TEST_F(SkyMap, AMapAndABackgroundBothWrittenWarnThatTheMapWins) {
    std::ofstream(dir / "scene.jts") << "render_settings { width: 1; height: 1;\n"
                                        "    background: <0, 0, 0>;\n"
                                        "    background_map: \"sky.png\"; }\n"
                                        "cameras { perspective_camera { } }\nscene { }\n";
    Expected<LoadedScene> loaded = load_scene_file(dir / "scene.jts");
    ASSERT_TRUE(loaded);
    const std::vector<Diagnostic> found = check_scene(*loaded);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].severity, Severity::warning);
    EXPECT_EQ(found[0].pos.line, 2);
    EXPECT_EQ(found[0].pos.column, 17);
    EXPECT_EQ(found[0].message,
              "'background' and 'background_map' are both set: the background map wins, so no "
              "ray shows this colour");
    EXPECT_EQ(at(render(loaded->parsed.scene), 0, 0), map_texel(4, 2));
}

}  // namespace
}  // namespace jt::test
