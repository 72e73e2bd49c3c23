// Picking through the frame code: a click on the image selects the primitive
// under it, outlines it over the image (never in it), opens it in the Objects
// panel; the background clears; the list stays a few rows with 100,000 objects.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "common/files.hpp"
#include "jtracer/render_job.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace jt::view {
namespace {

using namespace jt::test;
using Kind = Selection::Kind;

class ViewerPicking : public ViewerFixture {
  protected:
    void SetUp() override { open_rendered(kScene); }
    void click_pixel(int x, int y) {
        const WindowPoint p = window_point({x + 0.5, y + 0.5});
        viewer.drag(state, 0, p.x, p.y, p.x, p.y);
        viewer.frame(state);  // the frame after the click shows what it selected
    }
};

TEST_F(ViewerPicking, AClickSelectsOutlinesOverTheImageAndOpensTheObject) {
    const Image8 before = state.render.display;
    click_pixel(32, 20);  // the sphere, in the middle of the 64x48 image
    ASSERT_EQ(state.view.selection, (Selection{Kind::primitive, 1})) << state.message;
    EXPECT_FALSE(state.view.free_camera_active) << "a click does not move the camera";
    // The sidebar scrolls to the list in the frame that reveals it; its rows
    // are drawn once the list is in view.
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "sphere 2"), nullptr) << "listed in the open panel";
    // The outline comes once the ids are computed off the UI thread.
    const auto deadline = std::chrono::steady_clock::now() + kTimeout;
    while (viewer.overlay().outlined_pixels() == 0 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        viewer.frame(state);
    }
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    int sphere_pixels = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            if (const auto pick = pick_primitive(*frame, x, y); pick && pick->primitive == 1)
                ++sphere_pixels;
    EXPECT_EQ(viewer.overlay().outlined_pixels(), sphere_pixels);
    EXPECT_EQ(state.render.display, before) << "the outline is drawn over the image, not into it";

    click_pixel(32, 46);  // the sky above the sphere
    EXPECT_EQ(state.view.selection.kind, Kind::none);
    viewer.frame(state);
    EXPECT_EQ(viewer.overlay().outlined_pixels(), 0);
}

TEST_F(ViewerPicking, HoveringThePictureInspectsThePixelUnderTheMouse) {
    const WindowPoint p = window_point({32.5, 20.5});
    viewer.move_mouse(state, p.x, p.y);
    const std::uint8_t* rgb = state.render.display.pixel(32, 20);
    char expected[64];
    std::snprintf(expected, sizeof expected, "x 32, y 27   RGB %d %d %d", rgb[0], rgb[1], rgb[2]);
    EXPECT_EQ(state.view.inspected.rfind(expected, 0), 0u) << state.view.inspected;
    EXPECT_NE(state.view.inspected.find("sphere 2 at distance"), std::string::npos)
        << state.view.inspected;
    viewer.move_mouse(state, 20, 20);  // over the panel
    EXPECT_TRUE(state.view.inspected.empty());
}

// The inspector's box sat at the mouse, on the object just
// picked, and hid its outline. It goes to the image's bottom corner away
// from the mouse, clear of the picked sphere.
TEST_F(ViewerPicking, TheInspectorBoxKeepsClearOfThePickedObject) {
    const WindowPoint p = window_point({32.5, 30.5});
    viewer.drag(state, 0, p.x, p.y, p.x, p.y);
    ASSERT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, 1}));
    viewer.move_mouse(state, p.x, p.y);
    viewer.move_mouse(state, p.x, p.y);
    ASSERT_FALSE(state.view.inspected.empty());
    const UiItem* box = find_item(viewer.ui_items(), "pixel inspector");
    ASSERT_NE(box, nullptr);
    // The sphere (radius 1 at 6 units, fov 40) is about a third of the image high.
    const float clear = viewer.image_rect().height() * 0.2f;
    const ScreenRect around{p.x - clear, p.y - clear, p.x + clear, p.y + clear};
    EXPECT_TRUE(box->rect.x1 <= around.x0 || box->rect.x0 >= around.x1 ||
                box->rect.y1 <= around.y0 || box->rect.y0 >= around.y1)
        << "the box overlaps the sphere around the mouse";
}

// An object deleted and another added while the scene is not rendered (too
// large) leave as many objects: the red sphere's pixel is still of the scene
// before, not of the cylinder added in its place.
TEST_F(ViewerPicking, TheInspectorOfAnEarlierSceneWithAsManyObjects) {
    const WindowPoint p = window_point({32.5, 20.5});  // the sphere
    viewer.move_mouse(state, p.x, p.y);
    ASSERT_NE(state.view.inspected.find("sphere 2"), std::string::npos) << state.view.inspected;
    edit_scene(state, [](Scene& s) { s.settings.width = s.settings.height = 5000; });
    ASSERT_TRUE(delete_block(state, BlockRef{BlockKind::primitive, 1})) << state.message;
    ASSERT_TRUE(add_object(state, ShapeKind::cylinder)) << state.message;
    ASSERT_EQ(state.doc.scene.primitives.size(), 2u);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    ASSERT_NE(state.render.render_note.find("too large"), std::string::npos)
        << state.render.render_note;
    viewer.move_mouse(state, p.x + 1, p.y);
    EXPECT_EQ(state.view.inspected.find("cylinder"), std::string::npos) << state.view.inspected;
    EXPECT_NE(state.view.inspected.find("earlier"), std::string::npos) << state.view.inspected;
}

// While the scene as edited is not rendered (its image too large, say) and
// its objects are no longer those of the image shown, the pixel inspector
// has no frame to pick in: it says so, never "background" over an object.
TEST_F(ViewerPicking, TheInspectorNeverCallsAPixelOfAnEarlierSceneBackground) {
    const WindowPoint p = window_point({32.5, 20.5});  // the sphere
    viewer.move_mouse(state, p.x, p.y);
    EXPECT_NE(state.view.inspected.find("sphere 2"), std::string::npos) << state.view.inspected;
    edit_scene(state, [](Scene& s) { s.settings.width = s.settings.height = 5000; });
    ASSERT_TRUE(delete_block(state, BlockRef{BlockKind::primitive, 1})) << state.message;
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    ASSERT_NE(state.render.render_note.find("too large"), std::string::npos)
        << state.render.render_note;
    viewer.move_mouse(state, p.x + 1, p.y);
    EXPECT_EQ(state.view.inspected.find("background"), std::string::npos) << state.view.inspected;
    EXPECT_NE(state.view.inspected.find("earlier"), std::string::npos) << state.view.inspected;
}

// Zoomed to 4 and panned with the mouse as a user would: the image is larger
// than the window's image area, so the pan moves it.
class ViewerZoomedPicking : public ViewerPicking {
  protected:
    void SetUp() override {
        ViewerPicking::SetUp();
        edit_scene(state, [](Scene& s) {
            s.settings.width = 256;
            s.settings.height = 192;
        });
        ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
        const ScreenRect area = viewer.image_area();
        const float cx = (area.x0 + area.x1) * 0.5f, cy = (area.y0 + area.y1) * 0.5f;
        viewer.move_mouse(state, cx, cy);
        viewer.press_key(state, keys::digit('1'));  // 1:1
        EXPECT_FLOAT_EQ(state.view.image_view.zoom, 1.0f);
        viewer.press_key(state, keys::equal);
        viewer.press_key(state, keys::equal);
        ASSERT_FLOAT_EQ(state.view.image_view.zoom, 4.0f);
        viewer.drag(state, 2, cx, cy, cx - 150, cy + 90);  // middle: pan the image
        ASSERT_FALSE(state.view.free_camera_active) << "the pan moves the image, not the camera";
        ASSERT_FLOAT_EQ(viewer.image_rect().width(), 1024.0f);
        ASSERT_NE(state.view.image_view.pan_x, 0.0f);
        ASSERT_NE(state.view.image_view.pan_y, 0.0f);
    }
    // The window point of the centre of image pixel (x, y) as the last frame drew it.
    WindowPoint zoomed_point(int x, int y) const {
        return image_to_window(viewer.image_rect(), 256, 192, {x + 0.5, y + 0.5});
    }
    // The point shows the image: inside the image's area, not under its toolbar.
    bool shows_image(WindowPoint p) const {
        const UiItem* toolbar = find_item(viewer.ui_items(), "image toolbar");
        return viewer.image_area().contains(p.x, p.y) &&
               !(toolbar && toolbar->rect.contains(p.x, p.y));
    }
};

TEST_F(ViewerZoomedPicking, AClickSelectsWhatTheUnzoomedPixelShows) {
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    ASSERT_TRUE(frame);
    int checked = 0, hits = 0;
    for (int y = 0; y < 192; y += 21)
        for (int x = 0; x < 256; x += 23) {
            const WindowPoint p = zoomed_point(x, y);
            if (!shows_image(p)) continue;  // panned out of view
            viewer.drag(state, 0, p.x, p.y, p.x, p.y);
            const std::optional<PickedPrimitive> pick = pick_primitive(*frame, x, y);
            const Selection expected =
                pick ? Selection{Kind::primitive, pick->primitive} : Selection{};
            if (state.view.selection.kind == Kind::light) continue;  // a marker is in front
            EXPECT_EQ(state.view.selection, expected) << "pixel " << x << ", " << y;
            ++checked;
            hits += pick.has_value();
        }
    EXPECT_GT(checked, 20);
    EXPECT_GT(hits, 5);
    EXPECT_FALSE(state.view.free_camera_active);
}

TEST_F(ViewerZoomedPicking, TheInspectorReportsThePixelUnderTheMouse) {
    int checked = 0;
    for (int y = 0; y < 192; y += 23)
        for (int x = 0; x < 256; x += 29) {
            const WindowPoint p = zoomed_point(x, y);
            if (!shows_image(p)) continue;
            viewer.move_mouse(state, p.x, p.y);
            const std::uint8_t* rgb = state.render.display.pixel(x, y);
            char expected[64];
            std::snprintf(expected, sizeof expected, "x %d, y %d   RGB %d %d %d", x, 191 - y,
                          rgb[0], rgb[1], rgb[2]);
            EXPECT_EQ(state.view.inspected.rfind(expected, 0), 0u)
                << state.view.inspected << " at " << p.x << ", " << p.y << " expected " << expected;
            ++checked;
        }
    EXPECT_GT(checked, 10);
    // Off the area (the image reaches past it under the panel): nothing.
    const ScreenRect r = viewer.image_rect();
    if (r.x0 < viewer.image_area().x0) {
        viewer.move_mouse(state, viewer.image_area().x0 - 5, (r.y0 + r.y1) * 0.5f);
        EXPECT_TRUE(state.view.inspected.empty()) << state.view.inspected;
    }
}

// The wheel through the window's event queue (key_taps.hpp), turned fast
// within one slow frame after a click, with Ctrl pressed between: Ctrl
// waits for the frame after the click, and the turns with it, so that they
// zoom the image rather than dolly the camera.
TEST_F(ViewerZoomedPicking, CtrlWheelTurnedWithinAFrameAfterAClickZooms) {
    const WindowPoint p = zoomed_point(120, 100);
    const float zoom = state.view.image_view.zoom;
    const std::vector<KeyEvent> events = {
        mouse_button_event(0, kKeyPress, p.x, p.y),
        mouse_button_event(0, kKeyRelease, p.x, p.y),
        KeyEvent{keys::left_ctrl, 0, kKeyPress, 0},
        wheel_event(0.0f, 1.0f, p.x, p.y),
        wheel_event(0.0f, 1.0f, p.x, p.y),
        KeyEvent{keys::left_ctrl, 0, kKeyRelease, 0x0002},
    };
    viewer.key_events(state, events, 1.0, 50.0);
    EXPECT_NEAR(state.view.image_view.zoom, zoom * 1.25f * 1.25f, 1e-4f);
    EXPECT_FALSE(state.view.free_camera_active) << "Ctrl+wheel zooms the image, not the camera";
}

TEST_F(ViewerZoomedPicking, CtrlWheelZoomsAboutTheMouseAndFitShowsItAll) {
    const WindowPoint p = zoomed_point(120, 100);
    viewer.scroll(state, p.x, p.y, 2, /*ctrl=*/true);
    EXPECT_NEAR(state.view.image_view.zoom, 4.0f * 1.25f * 1.25f, 1e-4f);
    EXPECT_FALSE(state.view.free_camera_active) << "Ctrl+wheel zooms the image, not the camera";
    const WindowPoint after = zoomed_point(120, 100);
    EXPECT_NEAR(after.x, p.x, 6.25f) << "the pixel under the mouse stays under it";
    EXPECT_NEAR(after.y, p.y, 6.25f);
    viewer.press_key(state, keys::letter('F'));
    EXPECT_TRUE(state.view.image_view.fit);
    const ScreenRect r = viewer.image_rect(), area = viewer.image_area();
    EXPECT_GE(r.x0, area.x0 - 1);
    EXPECT_LE(r.x1, area.x1 + 1);
    EXPECT_GE(r.y0, area.y0 - 1);
    EXPECT_LE(r.y1, area.y1 + 1);
}

TEST_F(ViewerPicking, TheObjectsListDrawsOnlyTheRowsInViewOfAHundredThousand) {
    edit_scene(state, [](Scene& s) {
        for (int i = 0; i < 100000; ++i)
            s.primitives.push_back(Primitive{Sphere{Vec3(i * 0.01, -5, -20), 0.001}, {}, {}});
    });
    // Render settings and Camera closed first, so that the list is inside the window.
    ASSERT_TRUE(viewer.click(state, "Camera"));  // first: its fields may hide the next header
    ASSERT_TRUE(viewer.click(state, "Render settings"));
    ASSERT_TRUE(viewer.click(state, "Objects"));
    viewer.frame(state);
    const auto rows = [&] {
        int n = 0;
        for (const UiItem& item : viewer.ui_items()) n += item.label.rfind("sphere ", 0) == 0;
        return n;
    };
    EXPECT_GT(rows(), 0);
    EXPECT_LT(rows(), 40) << "only the rows in view are drawn";
    select(state.view, {Kind::primitive, 60000});
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "sphere 60001"), nullptr) << "scrolled to the selection";
    state.fields.object_filter = "sphere 99999";
    viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "sphere 99999"), nullptr);
    EXPECT_EQ(rows(), 1 + (find_item(viewer.ui_items(), "sphere 60001") ? 1 : 0))
        << "the filter lists only what matches";
}

// A light added from its panel opens there (its fields shown), as a picked one does.
// After Add object the panel scrolled the list to the top
// of the window, so the next click hit another field. The list was in view:
// what the user clicks next stays where it was.
TEST_F(ViewerPicking, AddObjectKeepsThePanelWhereItWas) {
    // Render settings and Camera closed: the Objects panel in the middle of the sidebar.
    ASSERT_TRUE(viewer.click(state, "Camera"));  // first: its fields may hide the next header
    ASSERT_TRUE(viewer.click(state, "Render settings"));
    if (!find_item(viewer.ui_items(), "Add object")) {
        ASSERT_TRUE(viewer.click(state, "Objects"));
    }
    viewer.frame(state);
    const UiItem* add = find_item(viewer.ui_items(), "Add object");
    ASSERT_NE(add, nullptr);
    const float before = add->rect.y0;
    ASSERT_TRUE(viewer.click(state, "Add object"));
    ASSERT_TRUE(viewer.click(state, "sphere"));
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    ASSERT_EQ(state.doc.scene.primitives.size(), 3u) << state.message;
    add = find_item(viewer.ui_items(), "Add object");
    ASSERT_NE(add, nullptr);
    EXPECT_EQ(add->rect.y0, before) << "the panel did not scroll";
}

TEST_F(ViewerPicking, AddPointLightOpensTheNewLightInItsPanel) {
    ASSERT_TRUE(viewer.click(state, "Camera"));  // first: its fields may hide the next header
    ASSERT_TRUE(viewer.click(state, "Render settings"));
    ASSERT_TRUE(viewer.click(state, "Lights"));
    viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "intensity"), nullptr) << "no light is open yet";
    ASSERT_TRUE(viewer.click(state, "Add point light"));
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    EXPECT_EQ(state.view.selection.kind, Kind::light);
    EXPECT_NE(find_item(viewer.ui_items(), "intensity"), nullptr) << "the new light's fields";
}

// A selected mesh shows what jtracer-cli info prints of it: its
// triangles, its bounds and size in world units, its file.
TEST(ViewerMeshFigures, TheObjectsPanelShowsTheSelectedMeshsTrianglesBoundsAndSize) {
    const std::filesystem::path dir = make_scratch_dir("mesh-figures");
    // A unit cube about the origin: 12 triangles, its 8 corners read as 24
    // vertices (one a face corner, as Assimp reads OBJ faces).
    std::string cube;
    for (int i = 0; i < 8; ++i)
        cube += "v " + std::to_string(i & 1 ? 0.5 : -0.5) + " " +
                std::to_string(i & 2 ? 0.5 : -0.5) + " " + std::to_string(i & 4 ? 0.5 : -0.5) +
                "\n";
    cube += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    write_file(dir / "cube.obj", cube);
    write_file(dir / "scene.jts", R"(render_settings { width: 48; height: 32; }
cameras { perspective_camera { position: <10, 3, 12>; look_at: <10, 0, 0>; aspect: 1.5; } }
scene {
    sphere { center: <0, 0, 0>; radius: 1; }
    mesh { file: "cube.obj"; transform { scale: <2, 4, 2>; translate: <10, 0, 0>; } }
    point_light { position: <5, 5, 5>; intensity: <1, 1, 1>; }
}
)");
    HeadlessViewer viewer(960, 900);
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    AppState state{test_config()};
    open_scene(state, dir / "scene.jts");
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const std::vector<std::string> figures = {
        "12 triangles, 24 vertices, normals none (shaded flat)", "bounds <9, -2, -1> to <11, 2, 1>",
        "size <2, 4, 2>"};
    select(state.view, {Kind::primitive, 0});  // the sphere: no figures
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    for (const std::string& line : figures) EXPECT_EQ(find_item(viewer.ui_items(), line), nullptr);
    select(state.view, {Kind::primitive, 1});
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    for (const std::string& line : figures)
        EXPECT_NE(find_item(viewer.ui_items(), line), nullptr) << line;
    // The figures follow an edit of the mesh's transforms.
    edit_scene(state,
               [](Scene& scene) { scene.primitives[1].transforms.back().vector = Vec3(20, 0, 0); });
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "bounds <19, -2, -1> to <21, 2, 1>"), nullptr);
    // With materials "file", its parts (docs/language.md §14.5).
    EXPECT_EQ(find_item(viewer.ui_items(), "(no material): 12 triangles"), nullptr);
    edit_scene(state, [](Scene& scene) {
        shape_as<Mesh>(scene.primitives[1].shape).materials = std::string(kFileMaterials);
    });
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "(no material): 12 triangles"), nullptr);
    std::filesystem::remove_all(dir);
}

// Each part of a model read with materials "file" is listed with its colour.
TEST(ViewerMeshFigures, TheObjectsPanelListsTheFilesPartsWithTheirColours) {
    const std::filesystem::path dir = make_scratch_dir("mesh-parts");
    write_file(dir / "m.obj",
               "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
               "usemtl red\nf 1 2 3\nusemtl blue\nf 2 4 3\n");
    write_file(dir / "m.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
    write_file(dir / "scene.jts", R"(render_settings { width: 32; height: 32; }
cameras { perspective_camera { position: <0.5, 0.5, 4>; look_at: <0.5, 0.5, 0>; } }
scene {
    mesh { file: "m.obj"; materials: "file"; }
}
)");
    HeadlessViewer viewer(960, 900);
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    AppState state{test_config()};
    open_scene(state, dir / "scene.jts");
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    select(state.view, {Kind::primitive, 0});
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "red: 1 triangles, base <1, 0, 0>"), nullptr);
    EXPECT_NE(find_item(viewer.ui_items(), "blue: 1 triangles, base <0, 0, 1>"), nullptr);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace jt::view
