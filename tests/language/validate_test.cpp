// validate_scene: the whole-scene checks, their text and their locations.

#include "jtracer/validate.hpp"

#include "common/scratch_dir.hpp"
#include "test_util.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

namespace jt {
namespace {

using test::brief;

// The validation diagnostics of a scene that parses clean.
std::string validate(std::string_view text) {
    ParseResult r = test::parse_clean(text);
    return brief(validate_scene(r.scene, r.source));
}

constexpr std::string_view kGood =
    "render_settings { width: 40; height: 20; }\n"
    "cameras { perspective_camera { aspect: 2; } }\n"
    "scene { }\n";

TEST(Validate, AGoodSceneHasNoDiagnostics) {
    EXPECT_EQ(validate(kGood), "");
}

TEST(Validate, NoCameraIsAnError) {
    EXPECT_EQ(validate("render_settings { width: 2; height: 2; } scene { }"),
              "0:0: error: every render needs a camera: add cameras { perspective_camera { ... "
              "} }");
}

// The command-line flags that also set them are the front end's to name (cli_test).
TEST(Validate, ZeroWidthOrHeightSaysHowToSetIt) {
    EXPECT_EQ(validate("render_settings {\n  width: 0;\n}\ncameras { perspective_camera { } }\n"
                       "scene { }"),
              "2:10: error: the image width is 0: set 'width' in render_settings\n"
              "1:1: error: the image height is 0: set 'height' in render_settings");
    ParseResult r = parse_scene("cameras { perspective_camera { } } scene { }");
    const std::vector<Diagnostic> found = validate_scene(r.scene, r.source);
    EXPECT_EQ(brief(found),
              "0:0: error: the image width is 0: set 'width' in render_settings\n"
              "0:0: error: the image height is 0: set 'height' in render_settings");
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].setting, "width");
    EXPECT_EQ(found[1].setting, "height");
    EXPECT_TRUE(asks_for_frame_size(found[0]));
    EXPECT_TRUE(asks_for_frame_size(found[1]));
}

TEST(Validate, SeesOverridesAppliedToTheScene) {
    ParseResult r = parse_scene("cameras { perspective_camera { } } scene { }");
    r.scene.settings.width = 8;  // as the CLI's --width/--height would
    r.scene.settings.height = 8;
    EXPECT_EQ(brief(validate_scene(r.scene, r.source)), "");
}

TEST(Validate, ImageTooLargeForABmpIsLocatedAtHeight) {
    EXPECT_EQ(validate("render_settings { width: 65535;\n height: 65535; }\n"
                       "cameras { perspective_camera { } } scene { }"),
              "2:10: error: a 65535 x 65535 image does not fit in a BMP file (4 GiB at most)");
    EXPECT_EQ(bmp_file_size(1, 1), 58u);
    EXPECT_EQ(bmp_file_size(2, 3), 54u + 8 * 3);
}

TEST(Validate, LookAtEqualToPosition) {
    EXPECT_EQ(validate("render_settings { width: 2; height: 2; }\n"
                       "cameras { perspective_camera { name: \"A\";\n position: <1, 2, 3>;\n "
                       "look_at: <1, 2, 3>; } }\nscene { }"),
              "4:11: error: camera \"A\": 'look_at' equals 'position', so the camera looks "
              "nowhere");
}

TEST(Validate, UpParallelToTheViewDirection) {
    EXPECT_EQ(validate("render_settings { width: 2; height: 2; }\n"
                       "cameras { perspective_camera { }\n perspective_camera { look_at: <0, -5, "
                       "0>;\n up: <0, 2, 0>; } }\nscene { }"),
              "4:6: error: camera 2: 'up' <0, 2, 0> is parallel to the view direction <0, -5, "
              "0>");
    // A zero 'up' is no direction at all, whatever the view.
    EXPECT_EQ(validate("render_settings { width: 2; height: 2; }\n"
                       "cameras { perspective_camera { up: <0, 0, 0>; } }\nscene { }"),
              "2:36: error: camera 1: 'up' is <0, 0, 0>, which gives no direction for the top "
              "of the image");
}

TEST(Validate, AspectDifferingFromTheImageByOverOnePercentWarns) {
    EXPECT_EQ(validate("render_settings { width: 640; height: 480; }\n"
                       "cameras { perspective_camera { aspect: 1.5; } }\nscene { }"),
              "2:40: warning: camera 1: 'aspect' 1.5 differs from width/height = "
              "1.3333333333333333 by more than 1%, so the image will look stretched");
    // Within 1%: fine; the manual's own 1.333333333 is fine.
    EXPECT_EQ(validate("render_settings { width: 640; height: 480; }\n"
                       "cameras { perspective_camera { aspect: 1.34; } }\nscene { }"),
              "");
    // The default aspect (1) on a non-square image warns at the camera block.
    EXPECT_EQ(validate("render_settings { width: 640; height: 480; }\n"
                       "cameras {\n  perspective_camera { } }\nscene { }"),
              "3:3: warning: camera 1: 'aspect' 1 differs from width/height = "
              "1.3333333333333333 by more than 1%, so the image will look stretched");
}

TEST(Validate, ActiveCameraNamingNoCameraWarns) {
    EXPECT_EQ(validate("render_settings { width: 2; height: 2;\n active_camera: \"Far\"; }\n"
                       "cameras { perspective_camera { name: \"Near\"; } }\nscene { }"),
              "2:17: warning: no camera is named \"Far\": using the first camera (\"Near\")");
    auto pick = [](std::string_view active) {
        Scene s;
        s.cameras = {test::named_camera("a"), test::named_camera("b")};
        s.settings.active_camera = std::string(active);
        return active_camera_index(s);
    };
    EXPECT_EQ(pick("b"), 1);
    EXPECT_EQ(pick("c"), 0);
    EXPECT_EQ(pick(""), 0);
    EXPECT_EQ(active_camera_index(Scene{}), -1);
}

TEST(Validate, ALensWithOneSampleWarnsAtTheActiveCamerasAperture) {
    const std::string cameras =
        "cameras {\n  perspective_camera { name: \"a\"; aperture: 0.2; }\n"
        "  perspective_camera { name: \"b\"; aperture: 0.5; }\n}\nscene { }";
    const std::string one = "render_settings { width: 2; height: 2; }\n";
    EXPECT_EQ(validate(one + cameras),
              "3:45: warning: camera \"a\": 'aperture' 0.2 blurs nothing while 'samples' is 1 (one "
              "ray a pixel, through the lens centre): set 'samples' to 16 or more");
    EXPECT_EQ(
        validate("render_settings { width: 2; height: 2; active_camera: \"b\"; }\n" + cameras),
        "4:45: warning: camera \"b\": 'aperture' 0.5 blurs nothing while 'samples' is 1 (one "
        "ray a pixel, through the lens centre): set 'samples' to 16 or more");
    EXPECT_EQ(validate("render_settings { width: 2; height: 2; samples: 4; }\n" + cameras), "");
    EXPECT_EQ(validate(one + "cameras { perspective_camera { aperture: 0; } }\nscene { }"), "");
    // The samples the render will use: --samples is applied before validation.
    ParseResult r = test::parse_clean(one + cameras);
    r.scene.settings.samples = 16;
    EXPECT_EQ(brief(validate_scene(r.scene, r.source)), "");
    r.scene.settings.samples = 1;
    const std::vector<Diagnostic> found = validate_scene(r.scene, r.source);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].setting, "samples");       // so the command line can name --samples
    EXPECT_FALSE(asks_for_frame_size(found[0]));  // a setting, but not the frame's size
}

TEST(Validate, ZeroScaleComponentWarnsAtTheScaleOperation) {
    EXPECT_EQ(validate("render_settings { width: 2; height: 2; }\n"
                       "cameras { perspective_camera { } }\n"
                       "scene { cylinder {\n transform { translate: <0, -0.5, 0>; }\n"
                       " transform { zrotate: 45;\n   scale: <2, 0, 0>; } } }"),
              "6:4: warning: 'scale' <2, 0, 0> has a zero component: it flattens the primitive "
              "to nothing; it is left out");
}

TEST(Validate, NoSceneBlockWarns) {
    EXPECT_EQ(validate("render_settings { width: 2; height: 2; }\n"
                       "cameras { perspective_camera { } }"),
              "0:0: warning: no scene block: the image will show only the background");
}

// A sky map must be readable (docs/language.md §14.3); the error is at its
// string, the warning about a background the map hides at `background`.
TEST(Validate, BackgroundMapDiagnosticsAreLocated) {
    const std::string head = "render_settings { width: 40; height: 20;\n";
    const std::string tail = "cameras { perspective_camera { aspect: 2; } }\nscene { }\n";
    EXPECT_EQ(validate(head + " background_map: \"nowhere.png\"; }\n" + tail),
              "2:18: error: background_map: cannot read 'nowhere.png': no such file");
    EXPECT_EQ(validate(head + " background_map: \"\"; }\n" + tail),
              "2:18: error: background_map: the file name is empty (leave 'background_map' out "
              "to show the background colour)");
    EXPECT_EQ(
        validate(head + " background: <0, 0, 1>;\n background_map: \"nowhere.png\"; }\n" + tail),
        "2:14: warning: 'background' and 'background_map' are both set: the background map "
        "wins, so no ray shows this colour\n"
        "3:18: error: background_map: cannot read 'nowhere.png': no such file");
    // A background written alone, or the default map, says nothing.
    EXPECT_EQ(validate(head + " background: <0, 0, 1>; }\n" + tail), "");
}

// Opening a named pipe waits for a writer: a sky map (or any picture or
// model) that names one with none must be an error, not a hang.
TEST(Validate, ABackgroundMapThatIsAnIdlePipeIsAnError) {
    test::ScratchDir scratch("idle_pipe");
    const std::filesystem::path fifo = scratch.path() / "sky.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Should the check wait on the pipe after all, a writer comes after a
    // while and ends it, so that the test fails instead of hanging.
    std::atomic<bool> checked{false};
    std::thread writer([&] {
        for (int i = 0; i < 100 && !checked; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) ::close(fd);
    });
    const std::string found =
        validate("render_settings { width: 40; height: 20;\n background_map: \"" + fifo.string() +
                 "\"; }\ncameras { perspective_camera { aspect: 2; } }\n");
    checked = true;
    writer.join();
    EXPECT_EQ(found, "2:18: error: background_map: cannot read '" + fifo.string() +
                         "': a named pipe (FIFO) with nothing written to it\n"
                         "0:0: warning: no scene block: the image will show only the background");
}

TEST(Validate, CatchesOutOfRangeValuesInScenesBuiltInCode) {
    Scene s;
    s.settings.width = s.settings.height = 4;
    Camera wide;
    wide.fov = 180;
    s.cameras.push_back(wide);
    s.primitives.push_back(Primitive{Sphere{{0, 0, 0}, -1}, Material{}, {}});
    s.primitives.push_back(Primitive{Plane{{0, 0, 0}, 1}, test::reflective(2), {}});
    s.primitives.push_back(Primitive{Cylinder{0, 0},
                                     [] {
                                         Material m;
                                         m.finish.edit().specular_k = 0;
                                         return m;
                                     }(),
                                     {}});
    // The parser's messages (schema.hpp), with the block they are in.
    EXPECT_EQ(
        brief(validate_scene(s, SceneSource{})),
        "0:0: error: camera 1: 'fov' must be between 0 and 180 degrees (exclusive), got "
        "180\n"
        "0:0: error: sphere 1: 'radius' must be greater than 0 and at most 1e+09, got -1\n"
        "0:0: error: plane 2: 'normal' must not be the zero vector, got <0, 0, 0>\n"
        "0:0: error: plane 2: 'reflection' 2 is outside 0..1\n"
        "0:0: error: cylinder 3: 'radius' must be greater than 0 and at most 1e+09, got 0\n"
        "0:0: error: cylinder 3: 'height' must be greater than 0 and at most 1e+09, got 0\n"
        "0:0: error: cylinder 3: 'specular_k' must be greater than 0 and at most 1e+09, got 0");
}

// Chunks run in reverse order, as a pool may finish them.
void run_backwards(std::size_t count, const std::function<void(std::size_t)>& work) {
    for (std::size_t i = count; i-- > 0;) work(i);
}

// Chunks shared by three threads, each taking the next one left.
void run_on_threads(std::size_t count, const std::function<void(std::size_t)>& work) {
    std::atomic<std::size_t> next{0};
    const auto take = [&] {
        for (std::size_t i = next++; i < count; i = next++) work(i);
    };
    std::vector<std::thread> threads;
    for (int t = 0; t < 3; ++t) threads.emplace_back(take);
    for (std::thread& t : threads) t.join();
}

// A large scene with findings of every kind about its primitives, spread over
// many chunks: values out of range (as code may set them), a zero-area
// triangle, a flattening scale, an unreadable image map and model (each file
// read once whichever chunk meets it first).
TEST(Validate, ChunksOnThreadsFindTheSameAsOnePass) {
    constexpr int kinds = 6;
    constexpr int primitives = 40000;
    std::string text =
        "render_settings { width: 40; height: 20; }\n"
        "cameras { perspective_camera { aspect: 2; } }\n"
        "scene {\n";
    for (int i = 0; i < primitives; ++i) {
        switch (i % kinds) {
            case 0:
                text += "sphere { center: <" + std::to_string(i) + ", 0, 0>; radius: 1; }\n";
                break;
            case 1:
                text += "triangle { a: <0, 0, 0>; b: <1, 1, 1>; c: <2, 2, 2>; }\n";
                break;
            case 2:
                text += "cylinder { transform { scale: <1, 0, 1>; } }\n";
                break;
            case 3:
                text += "sphere { material { image_map: \"nowhere.png\"; } }\n";
                break;
            case 4:
                text += "mesh { file: \"nowhere.obj\"; }\n";
                break;
            default:
                text += "plane { normal: <0, 1, 0>; }\n";
        }
    }
    text += "}\n";
    ParseResult r = test::parse_clean(text);
    ASSERT_EQ(r.scene.primitives.size(), std::size_t{primitives});
    for (std::size_t i = 0; i < r.scene.primitives.size(); i += 7) {
        r.scene.primitives[i].material.finish.edit().reflection = 2.0;
        if (auto* sphere = std::get_if<Sphere>(&r.scene.primitives[i].shape)) sphere->radius = -1.0;
    }
    const std::vector<Diagnostic> one_pass = validate_scene(r.scene, r.source);
    ASSERT_GT(one_pass.size(), std::size_t{primitives / 2}) << brief(one_pass).substr(0, 2000);
    const std::string all = brief(one_pass);
    for (const char* finding :
         {"'reflection' 2 is outside", "'radius' must be", "zero area", "flattens the primitive",
          "image_map: cannot read", "mesh 39995: cannot read"})
        EXPECT_NE(all.find(finding), std::string::npos) << finding;
    EXPECT_TRUE(one_pass == validate_scene(r.scene, r.source, {.run_chunks = run_backwards}));
    EXPECT_TRUE(one_pass == validate_scene(r.scene, r.source, {.run_chunks = run_on_threads}));
    // Unlocated, as check_scene validates a scene loaded without its map first.
    EXPECT_TRUE(validate_scene(r.scene, SceneSource{}) ==
                validate_scene(r.scene, SceneSource{}, {.run_chunks = run_on_threads}));
}

// A scene as parsed holds no value out of its range but a default: the checks
// that take it as parsed find what the whole checks find, the mesh left
// without its file among them, at the same places.
TEST(Validate, PrimitivesAsParsedFindTheSame) {
    const std::string text =
        "render_settings { width: 40; height: 20; }\n"
        "cameras { perspective_camera { aspect: 2; } }\n"
        "scene {\n"
        "  sphere { center: <1, 2, 3>; radius: 1e9;\n"
        "    material { pigment: <1, 0, 0.5>; reflection: 1; transmission: 1; ior: 3;\n"
        "      specular_k: 1e9; checker: <0, 0, 0>; checker_size: 0.001; } }\n"
        "  mesh { }\n"
        "  cylinder { radius: 2; height: 3; transform { scale: <1, 0, 1>; xrotate: -720; } }\n"
        "  triangle { a: <0, 0, 0>; b: <1, 1, 1>; c: <2, 2, 2>; uv_a: <1, 1, 0>; }\n"
        "  plane { normal: <0, 0, -1>; distance: -1e9; }\n"
        "  mesh { shading: \"flat\"; }\n"
        "}\n";
    const ParseResult r = test::parse_clean(text);
    const std::vector<Diagnostic> all = validate_scene(r.scene, r.source);
    EXPECT_EQ(brief(all),
              "7:3: error: mesh 2: 'file' must not be empty\n"
              "8:48: warning: 'scale' <1, 0, 1> has a zero component: it flattens the primitive "
              "to nothing; it is left out\n"
              "9:3: warning: triangle 4: its corners <0, 0, 0>, <1, 1, 1>, <2, 2, 2> lie on one "
              "line (zero area): it is left out\n"
              "11:3: error: mesh 6: 'file' must not be empty");
    EXPECT_TRUE(all == validate_scene(r.scene, r.source, {.primitives_as_parsed = true}));
    EXPECT_TRUE(validate_scene(r.scene, SceneSource{}) ==
                validate_scene(r.scene, SceneSource{}, {.primitives_as_parsed = true}));
}

}  // namespace
}  // namespace jt
