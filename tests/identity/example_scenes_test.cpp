// The example scenes of languages 1.1 (meshes, glass, image maps) and 1.2 (soft
// shadows, a lens, a sky map) at a small size: jtracer-view's render and
// jtracer-mpi's image on two ranks are jtracer-cli's, byte for byte.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/png.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt {
namespace {

namespace fs = std::filesystem;
using test::ProgramRun;

const fs::path kScenes = fs::path(JT_SOURCE_DIR) / "scenes";

class ExampleScenes : public test::ScratchTest, public ::testing::WithParamInterface<const char*> {
  protected:
    // The scene at 160x90 in `dir`, beside links to the models and maps it names.
    std::string small_copy() {
        std::string text = test::read_file(kScenes / (std::string(GetParam()) + ".jts"));
        const std::string size = "    width: 800;\n    height: 450;\n";
        const std::size_t at = text.find(size);
        EXPECT_NE(at, std::string::npos) << "the scene's size moved";
        if (at != std::string::npos)
            text.replace(at, size.size(), "    width: 160;\n    height: 90;\n");
        test::write_file(dir / "scene.jts", text);
        for (const char* folder : {"models", "maps"})
            fs::create_directory_symlink(kScenes / folder, dir / folder);
        return "scene.jts";
    }

    static Image8 pixels(const fs::path& png) {
        Expected<Image8> image = read_png(png);
        EXPECT_TRUE(image) << png << ": " << image.error().message;
        return image ? *image : Image8{};
    }
};

TEST_P(ExampleScenes, TheViewerAndTheFarmRenderTheClisBytes) {
    const std::string scene = small_copy();
    ProgramRun cli = run_shell("'" JT_CLI "' " + scene + " -q -o cli.png");
    ASSERT_EQ(cli.code, 0) << cli.err;
    const Image8 expected = pixels(dir / "cli.png");
    ASSERT_EQ(expected.width, 160);
    ASSERT_EQ(expected.height, 90);

    ProgramRun view = run_shell("'" JT_VIEWER_EXE "' " + scene +
                                " --screenshot window.png --size 640x400 --save-render view.png"
                                " --timeout 120");
    ASSERT_EQ(view.code, 0) << view.err;
    EXPECT_TRUE(pixels(dir / "view.png") == expected) << "jtracer-view's render differs";

#ifdef JT_MPI
    ProgramRun mpi = run_shell("env ASAN_OPTIONS=detect_leaks=0 '" JT_MPIEXEC
                               "' --oversubscribe --allow-run-as-root -np 2 '" JT_MPI "' " +
                               scene + " --tile-size 16 -q -o mpi.png");
    ASSERT_EQ(mpi.code, 0) << mpi.err;
    EXPECT_EQ(test::read_file(dir / "mpi.png"), test::read_file(dir / "cli.png"))
        << "two ranks must give jtracer-cli's bytes";
#endif
}

INSTANTIATE_TEST_SUITE_P(Language11, ExampleScenes, ::testing::Values("mesh", "glass", "globe"));
INSTANTIATE_TEST_SUITE_P(Language12, ExampleScenes, ::testing::Values("soft_focus", "sky"));

// A model read with materials "file" (docs/language.md §14.5): two usemtl
// parts, one textured, faces before any usemtl and vertex colours; the
// viewer's finished image is jtracer-cli's.
using FileMaterials = test::ScratchTest;

TEST_F(FileMaterials, TheViewerRendersTheClisBytes) {
    fs::copy_file(kScenes / "maps/tiles.png", dir / "tiles.png");
    test::write_file(dir / "m.mtl",
                     "newmtl red\nKd 0.9 0.2 0.1\n"
                     "newmtl tiled\nKd 0.8 1 0.9\nmap_Kd -s 2 2 1 tiles.png\n");
    test::write_file(dir / "m.obj",
                     "mtllib m.mtl\n"
                     "v -2 -1 0 1 1 0\nv 0 -1 0 0 1 1\nv 0 1 0 1 0 1\nv -2 1 0\n"
                     "v 2 -1 0\nv 2 1 0\nvt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n"
                     "f 1 2 3\nusemtl red\nf 1 3 4\n"
                     "usemtl tiled\nf 2/1 5/2 6/3 3/4\n");
    test::write_file(dir / "scene.jts", R"(render_settings { width: 160; height: 90; }
cameras { perspective_camera { position: <0.5, 1, 5>; look_at: <0, 0, 0>; aspect: 1.7777777777777777; } }
scene {
    mesh { file: "m.obj"; materials: "file";
           material { ambient: <0.3, 0.3, 0.3>; diffuse: <0.8, 0.8, 0.8>; reflection: 0.2; } }
    plane { material { pigment: <1, 1, 1>; diffuse: <0.5, 0.5, 0.5>; } distance: -1.5; }
    point_light { position: <2, 4, 6>; intensity: <1, 1, 1>; }
}
)");
    ProgramRun cli = run_shell("'" JT_CLI "' scene.jts -q -o cli.png");
    ASSERT_EQ(cli.code, 0) << cli.err;
    ProgramRun view = run_shell("'" JT_VIEWER_EXE
                                "' scene.jts --screenshot window.png"
                                " --size 640x400 --save-render view.png --timeout 120");
    ASSERT_EQ(view.code, 0) << view.err;
    const Expected<Image8> expected = read_png(dir / "cli.png"), shown = read_png(dir / "view.png");
    ASSERT_TRUE(expected && shown);
    EXPECT_EQ(expected->width, 160);
    EXPECT_TRUE(*shown == *expected) << "jtracer-view's render differs";
}

}  // namespace
}  // namespace jt
