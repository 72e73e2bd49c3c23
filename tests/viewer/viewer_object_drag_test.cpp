// Moving an object through the frame code: a click selects the sphere, an
// Alt+drag moves it by the camera's own geometry (the translate worked out
// here from the camera), the core's pick under the cursor is still the sphere
// and the outline follows it; undo gives the file's bytes back and redo the
// moved ones (Ctrl+Shift+Z or Ctrl+Y); Esc during the drag cancels it; Shift
// keeps one axis.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "common/files.hpp"
#include "jtracer/value_text.hpp"
#include "model/app_actions.hpp"
#include "model/picking.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>
#include <imgui.h>
#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <numbers>
#include <thread>

namespace jt::view {
namespace {

using namespace jt::test;
using Kind = Selection::Kind;

class ViewerObjectDrag : public ViewerFixture {
  protected:
    void SetUp() override {
        path = scene_copy("viewer_object_drag");
        original = read_file(path);
        open_rendered(path);
        if (HasFatalFailure()) return;
        frame = shown_frame(state);
        ASSERT_TRUE(frame);
        const std::optional<ImagePoint> centre = project_to_image(*frame, {0, 1, 0});
        ASSERT_TRUE(centre);
        sphere_pixel = {std::floor(centre->x) + 0.5, std::floor(centre->y) + 0.5};
    }
    // Window units per image pixel.
    double scale() const { return viewer.image_rect().width() / state.render.display.width; }
    std::string text() const { return document_text(state.doc); }
    // The move the camera makes of the point grabbed at `from` for a cursor
    // moved to `to`: on the plane facing the camera at that point's depth D,
    // the rays through them (forward + sx right + sy up, scaled) are D times
    // as far apart as their sx and sy (docs/language.md §7).
    Vec3 expected_move(ImagePoint from, ImagePoint to) const {
        const Camera& c = state.doc.scene.cameras[0];
        const Vec3 forward = glm::normalize(c.look_at - c.position);
        const Vec3 right = glm::normalize(glm::cross(forward, c.up));
        const Vec3 up = glm::cross(right, forward);
        const double t = std::tan(c.fov / 2 * std::numbers::pi / 180);
        const auto pick =
            pick_primitive(*frame, static_cast<int>(from.x), static_cast<int>(from.y));
        const CameraRay ray = *camera_ray(*frame, from);
        const double depth = glm::dot(ray.direction * pick->distance, forward);
        const double w = state.render.display.width, h = state.render.display.height;
        return depth *
               (2 * (to.x - from.x) / w * t * c.aspect * right + 2 * (to.y - from.y) / h * t * up);
    }

    std::filesystem::path path;
    std::string original;
    std::shared_ptr<const PreparedFrame> frame;
    ImagePoint sphere_pixel;
};

TEST_F(ViewerObjectDrag, AltDragMovesTheSelectedSphereUnderTheCursorAndUndoGivesTheBytesBack) {
    const WindowPoint at = window_point(sphere_pixel);
    viewer.drag(state, 0, at.x, at.y, at.x, at.y);  // a click selects
    ASSERT_EQ(state.view.selection, (Selection{Kind::primitive, 1})) << state.message;
    const std::size_t steps = state.history.undo.size();

    constexpr float kRight = 60, kUp = 30;  // window units
    viewer.drag(state, 0, at.x, at.y, at.x + kRight, at.y - kUp, kAlt);
    EXPECT_FALSE(state.view.free_camera_active) << "Alt+drag moves the object, not the camera";
    EXPECT_EQ(state.view.selection, (Selection{Kind::primitive, 1}));
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one drag, one undo step";
    const ImagePoint to{sphere_pixel.x + kRight / scale(), sphere_pixel.y + kUp / scale()};
    const Vec3 want = expected_move(sphere_pixel, to);
    const auto& ops = state.doc.scene.primitives[1].transforms;
    ASSERT_EQ(ops.size(), 1u) << text();
    ASSERT_EQ(ops[0].kind, TransformKind::translate);
    // The numbers are rounded to a power of ten below a tenth of a pixel.
    const double pixel = glm::length(expected_move(sphere_pixel, {to.x, to.y + 1}) - want);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(ops[0].vector[i], want[i], pixel / 20) << i;
    const std::string moved = text();
    EXPECT_NE(moved.find("translate: " + vector_text(ops[0].vector) + ";"), std::string::npos)
        << moved;
    EXPECT_TRUE(has_unsaved_edits(state.doc));

    // Once the moved scene is rendered, the cursor is on the sphere still and
    // the outline is around its new pixels.
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const std::shared_ptr<const PreparedFrame> now = shown_frame(state);
    const auto pick = pick_primitive(*now, static_cast<int>(to.x), static_cast<int>(to.y));
    ASSERT_TRUE(pick);
    EXPECT_EQ(pick->primitive, 1);
    int sphere_pixels = 0;
    for (int y = 0; y < state.render.display.height; ++y)
        for (int x = 0; x < state.render.display.width; ++x)
            if (const auto p = pick_primitive(*now, x, y); p && p->primitive == 1) ++sphere_pixels;
    const auto deadline = std::chrono::steady_clock::now() + kTimeout;
    while (viewer.overlay().outlined_pixels() != sphere_pixels &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        viewer.frame(state);
    }
    EXPECT_EQ(viewer.overlay().outlined_pixels(), sphere_pixels);

    viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true);
    EXPECT_EQ(text(), original) << "undo gives the file's bytes back";
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true, /*shift=*/true);
    EXPECT_EQ(text(), moved);
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(path), moved);
}

// Found in the real window: Ctrl+Y redid only inside the text editor; over
// the image it did nothing, and a move undone with Ctrl+Z stayed undone.
TEST_F(ViewerObjectDrag, CtrlYOverTheImageRedoesAMoveUndone) {
    const WindowPoint at = window_point(sphere_pixel);
    viewer.drag(state, 0, at.x, at.y, at.x, at.y);
    ASSERT_EQ(state.view.selection, (Selection{Kind::primitive, 1})) << state.message;
    viewer.drag(state, 0, at.x, at.y, at.x + 40, at.y, kAlt);
    const std::string moved = text();
    ASSERT_NE(moved, original) << state.message;
    viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true);
    ASSERT_EQ(text(), original);
    viewer.press_key(state, keys::letter('Y'), /*ctrl=*/true);
    EXPECT_EQ(text(), moved) << "Ctrl+Y redoes the move: " << state.message;
    EXPECT_TRUE(has_unsaved_edits(state.doc));
}

TEST_F(ViewerObjectDrag, EscDuringTheDragPutsTheObjectBackAndQuitsNothing) {
    const WindowPoint at = window_point(sphere_pixel);
    viewer.press_mouse(state, 0, at.x, at.y, kAlt);
    viewer.move_mouse(state, at.x + 50, at.y + 10);
    viewer.move_mouse(state, at.x + 60, at.y + 10);
    EXPECT_EQ(state.view.selection, (Selection{Kind::primitive, 1}))
        << "taken from under the cursor";
    EXPECT_NE(text(), original) << "the text follows the drag";
    viewer.press_key(state, keys::escape);
    EXPECT_EQ(text(), original);
    viewer.move_mouse(state, at.x + 80, at.y + 10);
    viewer.release_mouse(state, 0);
    EXPECT_EQ(text(), original) << "a cancelled drag stays cancelled";
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    EXPECT_FALSE(state.history.undo.can_undo());
    EXPECT_FALSE(state.quit);
    EXPECT_FALSE(state.files.unsaved_prompt);
    EXPECT_EQ(state.message, "Move cancelled");
}

TEST_F(ViewerObjectDrag, ShiftKeepsTheMoveOnOneAxis) {
    const WindowPoint at = window_point(sphere_pixel);
    viewer.drag(state, 0, at.x, at.y, at.x - 70, at.y + 20, kAlt | kShift);
    const auto& ops = state.doc.scene.primitives[1].transforms;
    ASSERT_EQ(ops.size(), 1u) << state.message;
    const ImagePoint to{sphere_pixel.x - 70 / scale(), sphere_pixel.y - 20 / scale()};
    const Vec3 want = expected_move(sphere_pixel, to);
    EXPECT_NEAR(ops[0].vector.x, want.x, std::abs(want.x) * 0.01);
    EXPECT_LT(ops[0].vector.x, 0.0);
    EXPECT_EQ(ops[0].vector.y, 0.0) << "Shift: x alone, no drift in y";
    EXPECT_EQ(ops[0].vector.z, 0.0);
}

// A slow frame takes in the button and the keys let go together: the move
// ends as it was shown, on one axis.
TEST_F(ViewerObjectDrag, ShiftLetGoWithTheButtonKeepsTheAxisShown) {
    const WindowPoint at = window_point(sphere_pixel);
    viewer.press_mouse(state, 0, at.x, at.y, kAlt | kShift);
    for (int i = 1; i <= 4; ++i) viewer.move_mouse(state, at.x - 17.5f * i, at.y + 5.0f * i);
    ImGui::GetIO().KeyShift = ImGui::GetIO().KeyAlt = false;
    viewer.release_mouse(state, 0);
    const auto& ops = state.doc.scene.primitives[1].transforms;
    ASSERT_EQ(ops.size(), 1u) << state.message;
    EXPECT_LT(ops[0].vector.x, 0.0);
    EXPECT_EQ(ops[0].vector.y, 0.0) << "the axis shown while dragging";
    EXPECT_EQ(ops[0].vector.z, 0.0);
}

}  // namespace
}  // namespace jt::view
