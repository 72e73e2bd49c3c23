// docs/language.md §14.6: with soft shadows, a lens and a sky map
// the viewer's progressive render may show hard shadows and a sharp image
// first, but the image it finishes is jtracer-cli's, byte for byte; its status
// line says what the passes refine.
//
// Needs the render side of language 1.2 (branches lang12-lights and
// lang12-sky): until a light's radius, the lens and the sky map are rendered,
// the checks that each of them changes the image fail.

#include "app/headless.hpp"
#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/png.hpp"
#include "model/app_actions.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt::view {
namespace {

using namespace jt::test;
namespace fs = std::filesystem;

constexpr const char* kScene = R"(render_settings {
    width: 96;
    height: 64;
    samples: 8;
    ambient_light: <0.2, 0.2, 0.2>;
    background_map: "sky.png";
}
cameras {
    perspective_camera {
        position: <0, 1.5, 6>;
        look_at: <0, 0.8, 0>;
        aspect: 1.5;
        fov: 40;
        aperture: 0.15;
        focus_distance: 5;
    }
}
scene {
    plane { material { pigment: <0.7, 0.7, 0.7>; diffuse: <0.8, 0.8, 0.8>; } }
    sphere { center: <0, 1, 0>; radius: 1; material { pigment: <0.9, 0.2, 0.1>; diffuse: <0.8, 0.8, 0.8>; } }
    sphere { center: <1.8, 0.5, -2.5>; radius: 0.5; material { pigment: <0.2, 0.4, 0.9>; diffuse: <0.8, 0.8, 0.8>; } }
    point_light { position: <2, 5, 3>; intensity: <1, 1, 1>; radius: 0.6; shadow_samples: 12; }
}
)";

// A sky from dark blue at the bottom to light at the top, a hue per column.
Image8 sky_map() {
    Image8 map(32, 16);
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            std::uint8_t* p = map.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(40 + 6 * x);
            p[1] = static_cast<std::uint8_t>(60 + 10 * y);
            p[2] = static_cast<std::uint8_t>(120 + 8 * y);
        }
    return map;
}

class ViewerLensIdentity : public ScratchTest {
  protected:
    // jtracer-cli's image of `text` (written as scene.jts in `dir`).
    Image8 cli_image(const std::string& text, const std::string& name) {
        write_file(dir / (name + ".jts"), text);
        const ProgramRun cli =
            run_shell("'" JT_CLI_EXE "' " + name + ".jts -q -o " + name + ".png");
        EXPECT_EQ(cli.code, 0) << cli.err;
        Expected<Image8> image = read_png(dir / (name + ".png"));
        EXPECT_TRUE(image) << name;
        return image ? *image : Image8{};
    }
    // kScene with `from` replaced by `to`.
    static std::string without(const std::string& from, const std::string& to) {
        std::string text = kScene;
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
        return text;
    }
};

TEST_F(ViewerLensIdentity, TheFinishedImageIsTheClisAndTheStatusSaysWhatConverges) {
    ASSERT_TRUE(write_png(dir / "sky.png", sky_map()));
    const Image8 expected = cli_image(kScene, "scene");
    ASSERT_EQ(expected.width, 96);
    // Each feature is rendered (these fail until the render side has landed).
    EXPECT_FALSE(cli_image(without(" radius: 0.6;", ""), "hard") == expected)
        << "a light's radius softens the shadow";
    EXPECT_FALSE(cli_image(without("aperture: 0.15;", ""), "pinhole") == expected)
        << "the lens blurs what is off the focus plane";
    EXPECT_FALSE(cli_image(without("background_map: \"sky.png\";", ""), "nosky") == expected)
        << "the sky map shows behind the scene";

    HeadlessViewer viewer(960, 640);
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    AppState state{test_config()};
    open_scene(state, dir / "scene.jts");
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_TRUE(state.render.display == expected) << "jtracer-view's finished image differs";
    EXPECT_EQ(state.render.converging, "soft shadows and lens");
    RenderProgress pass;
    pass.pass_name = "4 samples";
    EXPECT_EQ(pass_label(pass, 8, state.render.converging), "soft shadows and lens: sample 4 of 8");
}

}  // namespace
}  // namespace jt::view
