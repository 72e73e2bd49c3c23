// The keys a user of Blender or any editor expects, and the
// text editor following the selection; through the OSMesa frame code.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "model/pixel_inspector.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <glm/geometric.hpp>

namespace jt::view {
namespace {

using namespace jt::test;

class ViewerSelectionKeys : public ViewerFixture {
  protected:
    void SetUp() override { open_rendered(kScene); }
    // A click on the image at image point (x, y).
    void click_image(double x, double y) {
        const WindowPoint p = window_point({x, y});
        viewer.drag(state, 0, p.x, p.y, p.x, p.y);
    }
    // A click picks in the frame the image was rendered from: after a change
    // of the objects (a delete, its undo) that frame is prepared anew, so the
    // click waits for the render, however long a loaded machine takes.
    void select_sphere() {
        ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
        click_image(32, 30);
        ASSERT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, 1}))
            << state.message;
    }
};

TEST_F(ViewerSelectionKeys, DeleteAndXDeleteCtrlDAndShiftDDuplicate) {
    const std::size_t count = state.doc.scene.primitives.size();
    select_sphere();
    viewer.press_key(state, keys::del);
    EXPECT_EQ(state.doc.scene.primitives.size(), count - 1) << state.message;
    EXPECT_EQ(state.view.selection.kind, Selection::Kind::none);
    viewer.press_key(state, keys::letter('Z'), true);
    ASSERT_EQ(state.doc.scene.primitives.size(), count) << "one undo step";

    select_sphere();
    viewer.press_key(state, keys::letter('D'), true);
    ASSERT_EQ(state.doc.scene.primitives.size(), count + 1) << state.message;
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, 2})) << "the copy";
    EXPECT_EQ(state.doc.scene.primitives[2], state.doc.scene.primitives[1]);
    viewer.press_key(state, keys::letter('D'), false, true);
    EXPECT_EQ(state.doc.scene.primitives.size(), count + 2) << "Shift+D too";
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, 3})) << "its copy";
    viewer.press_key(state, keys::letter('X'));
    EXPECT_EQ(state.doc.scene.primitives.size(), count + 1) << "X deletes too";
    EXPECT_EQ(state.view.selection.kind, Selection::Kind::none);
    viewer.press_key(state, keys::letter('X'));
    EXPECT_EQ(state.doc.scene.primitives.size(), count + 1) << "nothing selected: nothing deleted";
}

TEST_F(ViewerSelectionKeys, PeriodFramesTheSelection) {
    select_sphere();
    viewer.press_key(state, keys::period);
    ASSERT_TRUE(state.view.free_camera_active) << state.message;
    const Sphere& sphere = shape_as<Sphere>(state.doc.scene.primitives[1].shape);
    EXPECT_EQ(state.view.free_camera.look_at, sphere.center);
    const double distance = glm::length(state.view.free_camera.position - sphere.center);
    EXPECT_GT(distance, sphere.radius * 2.0);
    EXPECT_LT(distance, sphere.radius * 12.0);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const std::optional<PixelReport> centre = inspect_pixel(state, 32, 24);
    ASSERT_TRUE(centre && centre->hit);
    EXPECT_EQ(centre->hit->primitive, 1) << "the sphere fills the middle of the view";
}

TEST_F(ViewerSelectionKeys, APickScrollsTheTextToItsBlockAndAClickInABlockSelectsIt) {
    viewer.press_key(state, keys::letter('T'));
    TextEditorState& editor = viewer.text_editor();
    ASSERT_TRUE(editor.open);
    const std::string& text = state.doc.text;
    const auto line_of = [&](const char* part) {
        return 1 + static_cast<int>(std::count(text.begin(), text.begin() + text.find(part), '\n'));
    };
    // On the text's part of the editor window (its last frame), above the error list.
    const auto shown = [&](int line) {
        const UiItem* area = find_item(viewer.ui_items(), "text editor");
        const float y = editor.line1_y + static_cast<float>(line - 1) * editor.line_height;
        return area && y >= area->rect.y0 && y + editor.line_height <= area->rect.y1 - 100.0f;
    };
    const int light_line = line_of("point_light");
    ASSERT_FALSE(shown(light_line)) << "below the view at first";

    // A pick in the image scrolls the text to the picked block.
    select_sphere();
    viewer.frame(state);  // the editor asks to scroll
    viewer.frame(state);  // and shows it scrolled
    EXPECT_TRUE(shown(line_of("sphere {")));
    ASSERT_TRUE(shown(light_line)) << "and the light's block below it";

    // A click in the light's block (its line) selects the light.
    const float y = editor.line1_y + (static_cast<float>(light_line) - 0.5f) * editor.line_height;
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(editor.line1_x + editor.line_height * 4.0f, y);
    viewer.frame(state);
    io.MouseDown[0] = true;
    viewer.frame(state);
    io.MouseDown[0] = false;
    viewer.frame(state);
    viewer.frame(state);
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::light, 0})) << state.message;
}

}  // namespace
}  // namespace jt::view
