// docs/language.md §14.6: the panels edit language 1.2's
// properties (a light's radius and shadow samples, the camera's lens, the sky
// map, a mesh's smooth_angle and materials), each written in place and undone
// in one step; a Ctrl+click on the image focuses the camera on the surface
// under it; the sky map's file is watched like an image map's.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/pick.hpp"
#include "jtracer/png.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/image_layout.hpp"
#include "model/picking.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>

namespace jt::view {
namespace {

using namespace jt::test;
namespace fs = std::filesystem;

// The camera looks straight down -z at a sphere whose front is 5 away.
constexpr const char* kLensScene = R"(render_settings {
    width: 64;
    height: 48;
    background: <0.1, 0.1, 0.2>;
    ambient_light: <0.2, 0.2, 0.2>;
}
cameras {
    perspective_camera {
        position: <0, 1, 6>;
        look_at: <0, 1, 0>;
        aspect: 1.3333333333333333;
        fov: 40;
        aperture: 0.05;
    }
}
scene {
    sphere { center: <0, 1, 0>; radius: 1; material { pigment: <0.9, 0.2, 0.1>; } }
    mesh { file: "tri.obj"; material { pigment: <0.2, 0.9, 0.1>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)";

// One triangle behind the sphere, off to the left.
constexpr const char* kTriangle = "v -4 0 -3\nv -2 0 -3\nv -3 2 -3\nf 1 2 3\n";

Image8 sky_map(std::uint8_t level, int width) {
    Image8 map(width, 2);
    for (std::uint8_t& byte : map.rgb) byte = level;
    return map;
}

class ViewerLensFields : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(viewer.ok()) << viewer.error();
        write_file(dir / "tri.obj", kTriangle);
        ASSERT_TRUE(write_png(dir / "sky.png", sky_map(200, 4)));
        write_file(dir / "scene.jts", kLensScene);
        open_scene(state, dir / "scene.jts");
        ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    }
    void TearDown() override { fs::remove_all(dir); }

    void frames(int n) {
        for (int i = 0; i < n; ++i) viewer.frame(state);
    }
    const Camera& camera() const { return state.doc.scene.cameras[0]; }
    bool has_item(const std::string& label) const {
        return find_item(viewer.ui_items(), label) != nullptr;
    }
    std::string text() const { return document_text(state.doc); }
    // Ctrl+click at the centre of image pixel (x, y).
    void ctrl_click_pixel(int x, int y) {
        const WindowPoint p = image_to_window(viewer.image_rect(), state.render.display.width,
                                              state.render.display.height, {x + 0.5, y + 0.5});
        viewer.drag(state, 0, p.x, p.y, p.x, p.y, kCtrl);
        viewer.frame(state);
    }

    fs::path dir = make_scratch_dir("lens-fields");
    HeadlessViewer viewer{1100, 1000};
    AppState state{test_config()};
};

TEST_F(ViewerLensFields, FocusDistanceShowsWhatItIsUnsetAndATickWritesIt) {
    frames(2);
    EXPECT_TRUE(has_item("aperture")) << "the camera's aperture has a field";
    ASSERT_TRUE(has_item("focus_distance: 6 = |look_at - position|"))
        << "unset, the field shows the distance it takes";
    const std::size_t steps = state.history.undo.size();
    ASSERT_TRUE(viewer.click(state, "focus_distance"));
    frames(1);
    ASSERT_TRUE(camera().focus_distance);
    EXPECT_EQ(*camera().focus_distance, 6.0) << "ticked: the value it took unset";
    EXPECT_NE(text().find("        focus_distance: 6;\n    }"), std::string::npos) << text();
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one undo step";
    viewer.press_key(state, keys::letter('Z'), true);
    frames(1);
    EXPECT_FALSE(camera().focus_distance) << "undone";
    EXPECT_EQ(text(), kLensScene);
    // Written in the file, an untick takes its line out again.
    ASSERT_TRUE(viewer.click(state, "focus_distance"));
    frames(1);
    viewer.press_key(state, keys::letter('S'), true);
    frames(1);
    ASSERT_NE(read_file(dir / "scene.jts").find("focus_distance: 6;"), std::string::npos)
        << state.message;
    ASSERT_TRUE(viewer.click(state, "focus_distance"));
    frames(1);
    EXPECT_FALSE(camera().focus_distance);
    EXPECT_EQ(text(), kLensScene) << "saved in place without the line";
}

TEST_F(ViewerLensFields, ALightsRadiusAndShadowSamplesHaveFields) {
    select(state.view, {Selection::Kind::light, 0});
    frames(4);
    EXPECT_TRUE(has_item("radius"));
    EXPECT_TRUE(has_item("shadow_samples"));
}

TEST_F(ViewerLensFields, AMeshsMaterialsAreChosenInACombo) {
    select(state.view, {Selection::Kind::primitive, 1});
    frames(4);
    EXPECT_TRUE(has_item("smooth_angle: off (corners without a normal in the file are flat)"));
    EXPECT_TRUE(has_item("shading"));
    ASSERT_TRUE(viewer.click(state, "materials"));
    frames(1);
    const std::size_t steps = state.history.undo.size();
    ASSERT_TRUE(viewer.click(state, "file")) << "the combo lists the choices";
    frames(1);
    EXPECT_EQ(shape_as<Mesh>(state.doc.scene.primitives[1].shape).materials, "file");
    EXPECT_NE(text().find("mesh { file: \"tri.obj\"; material { pigment: <0.2, 0.9, 0.1>; } "
                          "materials: \"file\"; }"),
              std::string::npos)
        << text();
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one undo step";

    ASSERT_TRUE(viewer.click(state, "smooth_angle"));
    frames(1);
    EXPECT_EQ(shape_as<Mesh>(state.doc.scene.primitives[1].shape).smooth_angle, 60.0);
    EXPECT_NE(text().find("smooth_angle: 60;"), std::string::npos) << text();
}

TEST_F(ViewerLensFields, TheSkyMapIsNamedInRenderSettingsAndFollowedOnDisk) {
    frames(2);
    ASSERT_TRUE(viewer.click(state, "background_map"));
    for (char c : std::string("sky.png")) ImGui::GetIO().AddInputCharacter(c);
    viewer.frame(state);
    viewer.press_key(state, keys::enter);
    EXPECT_EQ(state.doc.scene.settings.background_map, "sky.png");
    EXPECT_NE(text().find("    background_map: \"sky.png\";\n}"), std::string::npos) << text();
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));

    // Another picture of another size: a new stamp, whatever the clock's grain.
    ASSERT_TRUE(write_png(dir / "sky.png", sky_map(40, 8)));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (state.message.find("changed on disk") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        viewer.frame(state);
    }
    EXPECT_EQ(state.message, "sky.png changed on disk: rendering again");
}

TEST_F(ViewerLensFields, ACtrlClickFocusesOnTheSurfaceUnderTheCursorInOneStep) {
    const std::size_t steps = state.history.undo.size();
    ctrl_click_pixel(32, 24);  // the sphere's front, 5 along the view direction
    ASSERT_TRUE(camera().focus_distance) << state.message;
    EXPECT_NEAR(*camera().focus_distance, 5.0, 2e-3);  // the sphere bulges toward the centre
    // The edit started a render whose preparation may still run on a busy
    // machine (picking has no frame until it is done): let it finish.
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    // Section 5's pixel-centre ray, as the tracer meets the sphere.
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    ASSERT_TRUE(frame);
    const auto ray = camera_ray(*frame, {32.5, 24.5});
    const auto hit = pick_primitive(*frame, 32, 24);
    ASSERT_TRUE(ray && hit);
    const Vec3 point = ray->origin + ray->direction * hit->distance;
    EXPECT_EQ(*camera().focus_distance, 6.0 - point.z) << "dot(hit - position, f)";
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one undo step";
    EXPECT_NE(state.message.find("focus_distance 5"), std::string::npos) << state.message;
    EXPECT_NE(text().find("focus_distance: "), std::string::npos) << text();
    EXPECT_FALSE(state.view.free_camera_active) << "a Ctrl+click does not move the camera";
    EXPECT_FALSE(state.view.render_region) << "nor set a region";

    const double focused = *camera().focus_distance;
    ctrl_click_pixel(32, 46);  // the sky above the sphere
    EXPECT_EQ(camera().focus_distance, focused) << "the background has no depth";
    EXPECT_EQ(state.history.undo.size(), steps + 1);
    EXPECT_NE(state.message.find("Nothing there to focus on"), std::string::npos) << state.message;

    viewer.press_key(state, keys::letter('Z'), true);
    frames(1);
    EXPECT_FALSE(camera().focus_distance) << "one undo takes the focus back";
    EXPECT_EQ(text(), kLensScene);
}

// Typed text with errors is the document: the panels are read-only, and so
// is a Ctrl+click's focus. An edit of the last good scene would be in no
// text (neither saved nor shown), lost when the text parses, and a reload
// of the broken file would clear its undo step while the image kept it.
TEST_F(ViewerLensFields, ACtrlClickWhileTheTextHasErrorsChangesNothing) {
    const std::size_t steps = state.history.undo.size();
    type_text(state, std::string(kLensScene) + "{");
    state.check.checker.wait();
    frames(2);
    ASSERT_TRUE(state.doc.draft.has_value()) << state.message;
    ctrl_click_pixel(32, 24);  // the sphere
    EXPECT_FALSE(camera().focus_distance) << "the last good scene is not edited";
    EXPECT_EQ(state.doc.scene, *state.doc.original);
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "the typing's step alone";
    EXPECT_NE(state.message.find("the text has errors"), std::string::npos) << state.message;
}

TEST_F(ViewerLensFields, CopyToSceneWhileTheTextHasErrorsChangesNothing) {
    type_text(state, std::string(kLensScene) + "{");
    state.check.checker.wait();
    frames(2);
    ASSERT_TRUE(state.doc.draft.has_value()) << state.message;
    EXPECT_FALSE(copy_free_camera_to_scene(state, "copy"));
    EXPECT_EQ(state.doc.scene.cameras.size(), 1u);
    EXPECT_NE(state.message.find("the text has errors"), std::string::npos) << state.message;
}

}  // namespace
}  // namespace jt::view
