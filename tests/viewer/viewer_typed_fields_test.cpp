// A number typed into a field (Ctrl+click or double-click puts it in ImGui's
// typing mode) is applied when the typing ends: Enter, Tab or a click
// elsewhere; Escape leaves the value as it was. Typing "60" into the fov
// never renders the scene at 6 on the way. Dragging still applies as it goes.
// The keys come through the window's event queue, one frame apart, as a user
// types them.

#include "app/keys.hpp"
#include "common/files.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace jt::view {
namespace {

using namespace jt::test;

constexpr int kCtrlMod = 0x0002;

KeyEvent key(int code, int action, int mods = 0) {
    return KeyEvent{code, 0, action, mods, 0};
}

class ViewerTypedFields : public ViewerFixture {
  protected:
    ViewerTypedFields() : ViewerFixture(1100, 900) {}

    void SetUp() override {
        open_rendered_copy("typed-fields");
        ASSERT_FALSE(HasFatalFailure());
        frames(4);
        steps = state.history.undo.size();
    }
    void frames(int n) {
        for (int i = 0; i < n; ++i) viewer.frame(state);
    }
    // The point `dx` window units into the field `label` from its left edge
    // (a vector's or colour's first component), at mid height.
    bool field_point(const std::string& label, float dx, float& x, float& y) {
        const UiItem* field = find_item(viewer.ui_items(), label);
        if (!field) return false;
        x = field->rect.x0 + dx;
        y = (field->rect.y0 + field->rect.y1) * 0.5f;
        return true;
    }
    // Ctrl+click at (x, y), through the event queue.
    void ctrl_click(float x, float y) {
        const std::vector<KeyEvent> events = {
            key(keys::left_ctrl, kKeyPress, kCtrlMod),
            mouse_button_event(0, kKeyPress, x, y),
            mouse_button_event(0, kKeyRelease, x, y),
            key(keys::left_ctrl, kKeyRelease, 0),
        };
        viewer.key_events(state, events, 40.0, 16.0);
    }
    // One character typed as a keyboard sends it.
    void type(char c) {
        const std::vector<KeyEvent> events = {key(c, kKeyPress), typed_character(c),
                                              key(c, kKeyRelease)};
        viewer.key_events(state, events, 40.0, 16.0);
    }
    void tap(int code) {
        viewer.key_events(state, {key(code, kKeyPress), key(code, kKeyRelease)}, 40.0, 16.0);
    }
    const Camera& camera() const { return state.doc.scene.cameras[0]; }

    std::size_t steps = 0;
};

TEST_F(ViewerTypedFields, TheFovTypedIsAppliedWhenEnterIsPressedNotPerKey) {
    ASSERT_EQ(camera().fov, 40.0);
    float x = 0, y = 0;
    ASSERT_TRUE(field_point("fov", 30.0f, x, y));
    ctrl_click(x, y);
    type('6');
    EXPECT_EQ(camera().fov, 40.0) << "the 6 of 60 is not applied while typing";
    EXPECT_EQ(state.history.undo.size(), steps);
    type('0');
    EXPECT_EQ(camera().fov, 40.0) << "nor the 60 before Enter";
    tap(keys::enter);
    frames(2);
    EXPECT_EQ(camera().fov, 60.0) << "Enter applies the value typed";
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "in one undo step";
    EXPECT_NE(document_text(state.doc).find("fov: 60;"), std::string::npos);
    viewer.press_key(state, keys::letter('Z'), true);
    frames(1);
    EXPECT_EQ(camera().fov, 40.0) << "one Ctrl+Z undoes it";
}

TEST_F(ViewerTypedFields, TabAppliesTheValueTypedAndEscapeLeavesItAsItWas) {
    float x = 0, y = 0;
    ASSERT_TRUE(field_point("fov", 30.0f, x, y));
    ctrl_click(x, y);
    type('7');
    type('5');
    tap(keys::escape);
    frames(2);
    EXPECT_EQ(camera().fov, 40.0) << "Escape: the value typed is dropped";
    EXPECT_EQ(state.history.undo.size(), steps) << "and nothing was recorded";
    ctrl_click(x, y);
    type('5');
    type('5');
    EXPECT_EQ(camera().fov, 40.0);
    tap(keys::tab);
    frames(2);
    EXPECT_EQ(camera().fov, 55.0) << "Tab applies it";
    // Tab went on to type into the next field; Escape leaves that one as it was.
    tap(keys::escape);
    frames(2);
    EXPECT_EQ(camera().fov, 55.0);
    EXPECT_EQ(camera().aspect, 1.3333333333333333);
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one step";
}

TEST_F(ViewerTypedFields, AVectorsComponentIsAppliedWhenTheFieldIsClickedAway) {
    float x = 0, y = 0;
    ASSERT_TRUE(field_point("position", 20.0f, x, y));  // its x component
    ctrl_click(x, y);
    type('2');
    type('5');
    EXPECT_EQ(camera().position.x, 0.0) << "not applied while typing";
    // A click on the panel's empty space below everything ends the typing.
    const std::vector<KeyEvent> away = {mouse_button_event(0, kKeyPress, x, 880.0f),
                                        mouse_button_event(0, kKeyRelease, x, 880.0f)};
    viewer.key_events(state, away, 40.0, 16.0);
    frames(2);
    EXPECT_EQ(camera().position.x, 25.0) << "the click away applies it";
    EXPECT_EQ(camera().position.y, 1.0) << "the other components stay";
    EXPECT_EQ(state.history.undo.size(), steps + 1);
}

TEST_F(ViewerTypedFields, WholeNumbersAndColoursWaitForTheTypingToEndToo) {
    float x = 0, y = 0;
    ASSERT_TRUE(field_point("recurse_depth", 30.0f, x, y));
    ctrl_click(x, y);
    type('1');
    type('2');
    EXPECT_EQ(state.doc.scene.settings.recurse_depth, 2) << "not 1 on the way to 12";
    tap(keys::enter);
    frames(2);
    EXPECT_EQ(state.doc.scene.settings.recurse_depth, 12);

    ASSERT_TRUE(field_point("background", 20.0f, x, y));  // its red component
    ctrl_click(x, y);
    type('0');
    type('.');
    type('5');
    EXPECT_EQ(state.doc.scene.settings.background.x, 0.1) << "not 0 on the way to 0.5";
    tap(keys::enter);
    frames(2);
    EXPECT_EQ(state.doc.scene.settings.background.x, 0.5);
    EXPECT_EQ(state.doc.scene.settings.background.y, 0.1);
    EXPECT_EQ(state.history.undo.size(), steps + 2);
}

TEST_F(ViewerTypedFields, DraggingAFieldStillAppliesAsItGoes) {
    float x = 0, y = 0;
    ASSERT_TRUE(field_point("fov", 30.0f, x, y));
    viewer.press_mouse(state, 0, x, y);
    viewer.move_mouse(state, x + 20.0f, y);
    viewer.move_mouse(state, x + 40.0f, y);
    EXPECT_GT(camera().fov, 40.0) << "applied while the button is still down";
    viewer.release_mouse(state, 0);
}

// Found in the real window: "70" typed into the fov, then Ctrl+Q, and the
// viewer quit at once, the 70 lost without a word; Ctrl+S did nothing at
// all. Both end the typing first, as a click away does: the value is an
// edit, which Ctrl+Q asks about and Ctrl+S writes.
TEST_F(ViewerTypedFields, CtrlQAndCtrlSTakeTheValueBeingTyped) {
    float x = 0, y = 0;
    ASSERT_TRUE(field_point("fov", 30.0f, x, y));
    ctrl_click(x, y);
    type('7');
    type('0');
    ASSERT_EQ(camera().fov, 40.0);
    viewer.press_key(state, keys::letter('Q'), true);
    frames(2);
    EXPECT_FALSE(state.quit) << "not with the typed value unsaved";
    EXPECT_EQ(camera().fov, 70.0) << "the value typed is taken";
    ASSERT_TRUE(state.files.unsaved_prompt) << "and Ctrl+Q asks about it";
    ASSERT_TRUE(viewer.click(state, "Cancel"));
    frames(2);
    ASSERT_FALSE(state.quit);

    ctrl_click(x, y);
    type('5');
    type('0');
    ASSERT_EQ(camera().fov, 70.0);
    viewer.press_key(state, keys::letter('S'), true);
    frames(2);
    EXPECT_EQ(camera().fov, 50.0);
    EXPECT_FALSE(has_unsaved_work(state)) << state.message;
    EXPECT_NE(read_file(state.doc.path).find("fov: 50;"), std::string::npos);
}

}  // namespace
}  // namespace jt::view
