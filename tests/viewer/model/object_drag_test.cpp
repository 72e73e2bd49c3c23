// Moving an object by dragging it (no GL): the plane facing the camera and
// the move a cursor position makes, against the camera's formulas worked out
// here (docs/language.md §7); the Shift constraint; the numbers written; the
// translate in the text with every byte outside the object's block kept; one
// undo step per drag, Esc and a drag let go where it started changing nothing.

#include "model/object_drag.hpp"
#include "common/files.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/value_text.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/drag_geometry.hpp"
#include "model/picking.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace jt::view {
namespace {

using namespace jt::test;
using Kind = Selection::Kind;
using Clock = std::chrono::steady_clock;

// The test scene's "front" camera and image, as the file gives them.
constexpr double kWidth = 64, kHeight = 48, kAspect = 1.3333333333333333, kFov = 40;
const Vec3 kEye{0, 1, 6}, kLookAt{0, 0.8, 0}, kUp{0, 1, 0};

struct CameraAxes {
    Vec3 forward, right, up;
    double tan_half_fov;
};

CameraAxes camera_axes() {
    CameraAxes c;
    c.forward = glm::normalize(kLookAt - kEye);
    c.right = glm::normalize(glm::cross(c.forward, kUp));
    c.up = glm::cross(c.right, c.forward);
    c.tan_half_fov = std::tan(kFov / 2 * std::numbers::pi / 180);
    return c;
}

// The move, in the plane facing the camera at `depth` along its forward
// direction, that takes the point under image point `from` to the one under
// `to`: the rays through them are forward + sx right + sy up (scaled), so on
// that plane they are depth times as far apart as their sx and sy.
Vec3 expected_move(double depth, ImagePoint from, ImagePoint to) {
    const CameraAxes c = camera_axes();
    const double dsx = 2 * (to.x - from.x) / kWidth * c.tan_half_fov * kAspect;
    const double dsy = 2 * (to.y - from.y) / kHeight * c.tan_half_fov;
    return depth * (dsx * c.right + dsy * c.up);
}

void expect_near(const Vec3& got, const Vec3& want, double tolerance, const char* what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], tolerance) << what << " axis " << i;
}

// The step moved_value rounds to for pixels of `pixel_size`.
double step_for(double pixel_size) {
    return std::pow(10.0, std::floor(std::log10(pixel_size)) - 1.0);
}

class ObjectDragTest : public ::testing::Test {
  protected:
    void SetUp() override {
        path = scene_copy(
            "object_drag_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        original = read_file(path);
        open_scene(state, path);
        ASSERT_TRUE(model.run_until_complete(state));
        frame = shown_frame(state);
        ASSERT_TRUE(frame);
        // The sphere's centre (0, 1, 0) is at the centre of pixel `press`.
        const std::optional<ImagePoint> centre = project_to_image(*frame, {0, 1, 0});
        ASSERT_TRUE(centre);
        press = {std::floor(centre->x) + 0.5, std::floor(centre->y) + 0.5};
    }
    // Where the press grabs the sphere: its first hit along the press's ray.
    Vec3 grabbed() const {
        const auto pick =
            pick_primitive(*frame, static_cast<int>(press.x), static_cast<int>(press.y));
        EXPECT_TRUE(pick && pick->primitive == 1);
        const CameraRay ray = *camera_ray(*frame, press);
        return ray.origin + ray.direction * pick->distance;
    }
    double depth_of(const Vec3& p) const { return glm::dot(p - kEye, camera_axes().forward); }
    // One whole drag of the selection from `press` to `to`.
    void drag_to(ImagePoint to, bool one_axis = false) {
        ASSERT_TRUE(start_object_drag(state, press, 0.0)) << state.message;
        drag_object_to(state, to, one_axis);
        finish_object_drag(state, to, one_axis);
    }
    std::string text() const { return document_text(state.doc); }

    std::filesystem::path path;
    std::string original;
    ModelLoop model;
    AppState state{test_config()};
    std::shared_ptr<const PreparedFrame> frame;
    ImagePoint press;
};

TEST_F(ObjectDragTest, ThePlaneFacesTheCameraAndTheMoveIsTheCamerasOwn) {
    const Vec3 grab = grabbed();
    const std::optional<DragPlane> plane = plane_facing_camera(*frame, grab);
    ASSERT_TRUE(plane);
    expect_near(plane->normal, camera_axes().forward, 1e-12, "normal");
    const double depth = depth_of(grab);
    for (const ImagePoint to : {ImagePoint{press.x + 10, press.y}, ImagePoint{press.x, press.y - 7},
                                ImagePoint{press.x - 13.25, press.y + 4.5},
                                ImagePoint{-20.0, 70.0}}) {  // past the image's corner
        const std::optional<Vec3> delta = drag_delta(*frame, *plane, press, to);
        ASSERT_TRUE(delta);
        expect_near(*delta, expected_move(depth, press, to), 1e-9, "move");
        EXPECT_NEAR(glm::dot(*delta, plane->normal), 0.0, 1e-12) << "within the plane";
    }
    // One pixel up on the plane: depth * 2 tan(fov / 2) / height.
    const std::optional<double> pixel = pixel_size_on(*frame, *plane, press);
    ASSERT_TRUE(pixel);
    EXPECT_NEAR(*pixel, depth * 2 * camera_axes().tan_half_fov / kHeight, 1e-12);
    // A plane behind the camera is met by no ray.
    const std::optional<DragPlane> behind = plane_facing_camera(*frame, kEye + Vec3{0, 0, 1});
    ASSERT_TRUE(behind);
    EXPECT_FALSE(drag_delta(*frame, *behind, press, {press.x + 1, press.y}));
}

TEST(DragGeometry, ShiftKeepsTheLargestAxisAndNumbersAreShort) {
    EXPECT_EQ(along_largest_axis({0.3, -0.5, 0.1}), Vec3(0, -0.5, 0));
    EXPECT_EQ(along_largest_axis({0.2, 0.1, -0.15}), Vec3(0.2, 0, 0));
    EXPECT_EQ(along_largest_axis({0.1, 0.1, 0.0}), Vec3(0.1, 0, 0)) << "the first of equals";
    EXPECT_EQ(along({1, 2, 3}, {0, 1, 0}), Vec3(0, 2, 0));
    // A pixel 0.017 across: steps of 0.001. Noise and moves under half a step
    // keep the start's exact value; a moved coordinate lands on the step.
    const Vec3 moved = moved_value({1.23456789, 2, -3}, {0.12345, 1e-17, -0.0004}, 0.017);
    EXPECT_EQ(moved, Vec3(1.358, 2, -3));
    EXPECT_EQ(vector_text(moved), "<1.358, 2, -3>");
    EXPECT_EQ(vector_text(moved_value({0, 0, 0}, {-0.0711111, 0.3333333, 0}, 0.08)),
              "<-0.071, 0.333, 0>");
    EXPECT_EQ(vector_text(moved_value({10, 0, 0}, {123.456, 0, 0}, 2.5)), "<133.5, 0, 0>");
}

TEST(DragGeometry, AnObjectsCentreIsWhereItsShapeIsAfterItsTransform) {
    const Scene scene;
    const std::vector<TransformOp> up_two{{TransformKind::zrotate, {}, 90},
                                          {TransformKind::translate, {0, 2, 0}, 0}};
    // The cylinder's axis turned from +y to -x, then moved up.
    const Primitive cylinder{Cylinder{0.5, 4.0}, {}, up_two};
    expect_near(*object_centre(scene, cylinder), Vec3(-2, 2, 0), 1e-12, "cylinder");
    const Primitive triangle{Triangle{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}}, {}, {}};
    expect_near(*object_centre(scene, triangle), Vec3(1, 1, 0), 1e-12, "triangle");
    const Primitive plane{Plane{{0, 2, 0}, 1.5}, {}, {}};
    expect_near(*object_centre(scene, plane), Vec3(0, 1.5, 0), 1e-12, "plane");
    const Primitive flat{Sphere{}, {}, {{TransformKind::scale, {1, 0, 1}, 0}}};
    EXPECT_FALSE(object_centre(scene, flat)) << "left out of the render";
}

TEST_F(ObjectDragTest, ADragWritesATranslateOfTheMoveAndKeepsEveryOtherByte) {
    select(state.view, {Kind::primitive, 1});
    const Vec3 grab = grabbed();
    const ImagePoint to{press.x + 9, press.y - 4};
    const std::size_t steps = state.history.undo.size();
    drag_to(to);
    EXPECT_EQ(state.view.selection, (Selection{Kind::primitive, 1})) << "the selection stays";
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one drag, one undo step";

    const Vec3 want = expected_move(depth_of(grab), press, to);
    const double pixel = depth_of(grab) * 2 * camera_axes().tan_half_fov / kHeight;
    const auto& ops = state.doc.scene.primitives[1].transforms;
    ASSERT_EQ(ops.size(), 1u);
    EXPECT_EQ(ops[0].kind, TransformKind::translate);
    expect_near(ops[0].vector, want, step_for(pixel) / 2 + 1e-12, "translate");
    EXPECT_EQ(ops[0].vector, moved_value(Vec3{0.0}, want, pixel)) << "written rounded";

    // The text: a transform block with that translate, inside the sphere's
    // block, and nothing else changed.
    const std::string after = text();
    const std::string translate = "translate: " + vector_text(ops[0].vector);
    ASSERT_NE(after.find(translate), std::string::npos) << after;
    std::size_t head = 0;
    while (head < original.size() && original[head] == after[head]) ++head;
    std::size_t tail = 0;
    while (tail < original.size() - head &&
           original[original.size() - 1 - tail] == after[after.size() - 1 - tail])
        ++tail;
    EXPECT_EQ(head + tail, original.size()) << "only an insertion";
    const std::string inserted = after.substr(head, after.size() - head - tail);
    EXPECT_NE(inserted.find("transform"), std::string::npos) << inserted;
    EXPECT_NE(inserted.find(translate), std::string::npos) << inserted;
    EXPECT_GT(head, original.find("    sphere {"));
    EXPECT_LT(head, original.find("    point_light")) << "inside the sphere's block";
    ParseResult parsed = parse_scene(after);
    ASSERT_TRUE(parsed.ok());
    EXPECT_TRUE(parsed.scene == state.doc.scene);

    // The point grabbed stays under the cursor (within the rounding), so the
    // core's pick there is the sphere once the render of the moved scene is shown.
    ASSERT_TRUE(model.run_until_complete(state));
    const std::shared_ptr<const PreparedFrame> moved = shown_frame(state);
    ASSERT_TRUE(moved && moved != frame);
    const std::optional<ImagePoint> now = project_to_image(*moved, grab + ops[0].vector);
    ASSERT_TRUE(now);
    EXPECT_NEAR(now->x, to.x, 0.1);
    EXPECT_NEAR(now->y, to.y, 0.1);
    const auto pick = pick_primitive(*moved, static_cast<int>(to.x), static_cast<int>(to.y));
    ASSERT_TRUE(pick);
    EXPECT_EQ(pick->primitive, 1);

    undo(state);
    EXPECT_EQ(text(), original) << "undo gives the file's bytes back";
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    redo(state);
    EXPECT_EQ(text(), after);
}

TEST_F(ObjectDragTest, ALaterDragUpdatesTheTrailingTranslateInsteadOfStackingOne) {
    select(state.view, {Kind::primitive, 1});
    drag_to({press.x + 6, press.y});
    const Vec3 first = state.doc.scene.primitives[1].transforms.back().vector;
    ASSERT_TRUE(model.run_until_complete(state));
    frame = shown_frame(state);
    // The second drag starts where the sphere now is, under its old press + 6.
    press.x += 6;
    drag_to({press.x + 5, press.y + 3});
    const auto& ops = state.doc.scene.primitives[1].transforms;
    ASSERT_EQ(ops.size(), 1u) << "one translate, updated";
    EXPECT_GT(ops[0].vector.x, first.x);
    EXPECT_GT(ops[0].vector.y, first.y);
    EXPECT_EQ(state.history.undo.size(), 2u);
    undo(state);
    EXPECT_EQ(state.doc.scene.primitives[1].transforms.back().vector, first);
}

TEST_F(ObjectDragTest, ATranslateAfterARotationIsAddedLastSoTheMoveIsInWorldSpace) {
    // Written in the text as the panels write it: a translate, then a turn.
    ASSERT_TRUE(add_transform_op(state, 1, TransformKind::translate));
    ASSERT_TRUE(add_transform_op(state, 1, TransformKind::yrotate));
    edit_scene(state, [](Scene& s) { s.primitives[1].transforms[1].degrees = 90; });
    ASSERT_TRUE(model.run_until_complete(state));
    frame = shown_frame(state);
    select(state.view, {Kind::primitive, 1});
    const Vec3 centre = *object_centre(state.doc.scene, state.doc.scene.primitives[1]);
    drag_to({press.x + 8, press.y}, /*one_axis=*/true);
    const auto& ops = state.doc.scene.primitives[1].transforms;
    ASSERT_EQ(ops.size(), 3u) << "added after the rotation";
    EXPECT_EQ(ops[2].kind, TransformKind::translate);
    EXPECT_GT(ops[2].vector.x, 0.0);
    EXPECT_EQ(ops[2].vector.y, 0.0) << "Shift: along x alone";
    EXPECT_EQ(ops[2].vector.z, 0.0);
    const Vec3 moved = *object_centre(state.doc.scene, state.doc.scene.primitives[1]);
    expect_near(moved - centre, ops[2].vector, 1e-12, "the centre moves by the translate");
}

TEST_F(ObjectDragTest, EscAndADragLetGoWhereItStartedChangeNothing) {
    select(state.view, {Kind::primitive, 1});
    const std::size_t steps = state.history.undo.size();
    ASSERT_TRUE(start_object_drag(state, press, 0.0));
    drag_object_to(state, {press.x + 10, press.y + 2}, false);
    EXPECT_NE(text(), original) << "the text follows the drag";
    cancel_object_drag(state);
    EXPECT_EQ(text(), original);
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    EXPECT_EQ(state.history.undo.size(), steps);

    // Moved away and back: the translate added on the way goes again.
    ASSERT_TRUE(start_object_drag(state, press, 0.0));
    drag_object_to(state, {press.x + 10, press.y}, false);
    EXPECT_NE(text(), original);
    finish_object_drag(state, press, false);
    EXPECT_EQ(text(), original);
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    EXPECT_EQ(state.history.undo.size(), steps);

    // Undo during the drag is the drag's own undo: nothing older goes.
    edit_scene(state, [](Scene& s) { s.settings.samples = 2; });
    const std::string edited = text();
    ASSERT_TRUE(start_object_drag(state, press, 0.0));
    drag_object_to(state, {press.x + 10, press.y}, false);
    undo(state);
    EXPECT_FALSE(state.drags.object);
    EXPECT_EQ(text(), edited);
}

TEST_F(ObjectDragTest, TheTextFollowsAtMostEveryIntervalAndTheLatestPositionWins) {
    select(state.view, {Kind::primitive, 1});
    ASSERT_TRUE(start_object_drag(state, press, 0.0));
    const Clock::time_point t0 = Clock::now();
    drag_object_to(state, {press.x + 4, press.y}, false, t0);
    const Vec3 first = state.doc.scene.primitives[1].transforms.back().vector;
    EXPECT_GT(first.x, 0.0) << "the first move is written at once";
    drag_object_to(state, {press.x + 8, press.y}, false, t0 + kDragWriteInterval / 2);
    EXPECT_EQ(state.doc.scene.primitives[1].transforms.back().vector, first) << "held back";
    drag_object_to(state, {press.x + 12, press.y}, false, t0 + kDragWriteInterval);
    const Vec3 latest = state.doc.scene.primitives[1].transforms.back().vector;
    EXPECT_NEAR(latest.x, 3 * first.x, 0.02) << "the latest position, not the one held back";
    finish_object_drag(state, {press.x + 12, press.y}, false);
    EXPECT_EQ(state.history.undo.size(), 1u);
}

TEST_F(ObjectDragTest, ALightMovesItsPositionAndAPlaneAlongItsNormal) {
    const Vec3 light = state.doc.scene.lights[0].position;
    const std::optional<ImagePoint> marker = project_to_image(*frame, light);
    ASSERT_TRUE(marker);
    select(state.view, {Kind::light, 0});
    press = *marker;
    drag_to({press.x - 5, press.y});
    const Vec3 moved = state.doc.scene.lights[0].position;
    const Vec3 want = expected_move(depth_of(light), *marker, {marker->x - 5, marker->y});
    const double pixel = depth_of(light) * 2 * camera_axes().tan_half_fov / kHeight;
    expect_near(moved - light, want, step_for(pixel) / 2 + 1e-12, "light");
    EXPECT_NE(text().find("position: " + vector_text(moved)), std::string::npos) << text();
    EXPECT_TRUE(state.doc.scene.primitives[1].transforms.empty()) << "a light has no transform";
    undo(state);
    EXPECT_EQ(text(), original);

    // The floor (normal +y): dragged down in the image it moves down, in y alone.
    select(state.view, {Kind::primitive, 0});
    press = {32.5, 6.5};
    ASSERT_EQ(pick_primitive(*frame, 32, 6)->primitive, 0);
    drag_to({32.5, 2.5});
    const auto& ops = state.doc.scene.primitives[0].transforms;
    ASSERT_EQ(ops.size(), 1u);
    EXPECT_LT(ops[0].vector.y, 0.0);
    EXPECT_EQ(ops[0].vector.x, 0.0);
    EXPECT_EQ(ops[0].vector.z, 0.0);
}

TEST_F(ObjectDragTest, WithNothingSelectedTheDragTakesWhatIsUnderTheCursor) {
    ASSERT_EQ(state.view.selection.kind, Kind::none);
    ASSERT_TRUE(start_object_drag(state, press, 0.0)) << state.message;
    EXPECT_EQ(state.view.selection, (Selection{Kind::primitive, 1}));
    cancel_object_drag(state);
    select(state.view, {});
    EXPECT_FALSE(start_object_drag(state, {32.5, 46.5}, 0.0)) << "the sky";
    EXPECT_NE(state.message.find("Nothing to move"), std::string::npos) << state.message;
    // Selected, a press off the object grabs it at its centre's depth.
    select(state.view, {Kind::primitive, 1});
    ASSERT_TRUE(start_object_drag(state, {32.5, 46.5}, 0.0));
    EXPECT_NEAR(glm::dot(state.drags.object->plane.point - Vec3(0, 1, 0), camera_axes().forward),
                0.0, 1e-12);
    cancel_object_drag(state);
}

// Found in the real window: an object whose last translate is written as an
// expression (`translate: <r * 1.5, 0, 0>;`) moved by a drag changed that
// translate's value, said "Save scene to keep it", and Save then refused:
// the value is written as an expression. The move is a translate of its own
// after it, and the expression stays; a light whose position is a name is
// not moved, and the status line says why.
TEST_F(ObjectDragTest, AComputedTranslateOrPositionIsNeverChangedByADrag) {
    std::string named = "define d = 0;\ndefine lp = <3, 5, 4>;\n" + original;
    const auto replace = [&](const std::string& from, const std::string& to) {
        const std::size_t at = named.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        named.replace(at, from.size(), to);
    };
    replace("        radius: 1;\n",
            "        radius: 1;\n        transform { translate: <d * 2, 0, 0>; }\n");
    replace("point_light { position: <3, 5, 4>;", "point_light { position: lp;");
    const auto open_named = [&] {
        write_file(path, named);
        open_scene(state, path);
        ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
        ASSERT_TRUE(model.run_until_complete(state));
        frame = shown_frame(state);
        ASSERT_TRUE(frame);
    };
    ASSERT_NO_FATAL_FAILURE(open_named());

    select(state.view, {Kind::primitive, 1});
    drag_to({press.x + 10, press.y});
    const auto& ops = state.doc.scene.primitives[1].transforms;
    ASSERT_EQ(ops.size(), 2u) << "a translate of its own: " << state.message;
    EXPECT_EQ(ops[0].vector, Vec3(0, 0, 0)) << "the expression's value stays";
    EXPECT_GT(ops[1].vector.x, 0.0);
    const auto saved = save_scene_in_place(state.doc);
    ASSERT_TRUE(saved) << saved.error().message;
    EXPECT_NE(read_file(path).find("translate: <d * 2, 0, 0>;"), std::string::npos)
        << read_file(path);

    const Vec3 light = state.doc.scene.lights[0].position;
    const std::optional<ImagePoint> marker = project_to_image(*frame, light);
    ASSERT_TRUE(marker);
    select(state.view, {Kind::light, 0});
    EXPECT_FALSE(start_object_drag(state, *marker, 0.0));
    // Found in the real window: the refusal said "is written as lp", not
    // that lp is a name, where it is defined, nor how to make the light movable.
    EXPECT_EQ(state.message,
              "Not moved: point_light 1's position is the name lp, defined at scene.jts:2. To "
              "drag the light, write a position <x, y, z> in its place in the text editor (T), "
              "or change lp where it is set");
    EXPECT_EQ(state.doc.scene.lights[0].position, light);

    // A position computed from an expression says so; there is no name to change.
    replace("point_light { position: lp;", "point_light { position: lp * 1;");
    ASSERT_NO_FATAL_FAILURE(open_named());
    select(state.view, {Kind::light, 0});
    EXPECT_FALSE(start_object_drag(state, *marker, 0.0));
    EXPECT_EQ(state.message,
              "Not moved: point_light 1's position is computed from the expression `lp * 1`. To "
              "drag the light, write a position <x, y, z> in its place in the text editor (T)");
}

}  // namespace
}  // namespace jt::view
