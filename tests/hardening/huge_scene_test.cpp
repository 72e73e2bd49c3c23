// Ten million primitives through the CLI: the render completes, or stops with
// a clear out-of-memory message; never a crash. About a minute and 6 GB in a
// release build, so it is left out of sanitizer builds (CMakeLists.txt).

#include "cli_sandbox.hpp"

#include "jtracer/bmp.hpp"

#include <fstream>

namespace jt::test {
namespace {

constexpr int primitive_count = 10'000'000;

// A 1000 x 100 x 100 grid of small spheres in front of the camera, ~400 MB of text.
// Without a material they are black, against a blue background.
void write_huge_scene(const std::filesystem::path& path) {
    std::ofstream out(path, std::ios::binary);
    out << "render_settings { width: 64; height: 36; background: <0, 0, 1>; }\n"
           "cameras { perspective_camera { position: <0, 0, 300>; look_at: <0, 0, 0>; "
           "aspect: 1.7778; } }\n"
           "scene {\n  point_light { position: <0, 100, 400>; intensity: <1, 1, 1>; }\n";
    std::string line;
    for (int i = 0; i < primitive_count; ++i) {
        line = "sphere{center:<" + std::to_string(i % 1000 - 500) + "," +
               std::to_string(i / 1000 % 100 - 50) + "," + std::to_string(-(i / 100000)) +
               ">;radius:0.4;}\n";
        out << line;
    }
    out << "}\n";
}

using HugeScene = CliSandbox;

TEST_F(HugeScene, TenMillionPrimitivesRenderOrFailClearly) {
    write_huge_scene(dir / "huge.jts");
    ProgramRun r = run({"huge.jts", "-o", "huge.bmp"});
    std::filesystem::remove(dir / "huge.jts");
    EXPECT_EQ(r.signal, 0) << r.err;
    if (r.code == 3) {
        EXPECT_NE(r.err.find("out of memory"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "huge.bmp"));
        return;
    }
    ASSERT_EQ(r.code, 0) << r.err;
    const Expected<Image8> read = read_bmp(dir / "huge.bmp");
    ASSERT_TRUE(read) << read.error().message;
    const Image8& image = *read;
    EXPECT_EQ(image.width, 64);
    // Spheres without a material are black; the background is blue: both must show.
    int spheres = 0, background = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            spheres += p[0] == 0 && p[1] == 0 && p[2] == 0;
            background += p[0] == 0 && p[1] == 0 && p[2] == 255;
        }
    EXPECT_GT(spheres, 0);
    EXPECT_GT(background, 0);
    EXPECT_EQ(spheres + background, image.width * image.height);
}

}  // namespace
}  // namespace jt::test
