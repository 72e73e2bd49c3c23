// The material panel edits a checker's colour and an image
// map's file, which the showcase's backdrop and the globe use; through the
// OSMesa frame code, into the text as Save scene writes it. And every field
// refuses a value past the language's limits, saying why.

#include "app/keys.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <string>

namespace jt::view {
namespace {

using namespace jt::test;

class ViewerMaterialFields : public ViewerFixture {
  protected:
    ViewerMaterialFields() : ViewerFixture(1100, 900) {}

    // Ctrl+click on the field `label` (ImGui's typing mode), `text`, Enter.
    bool type_into(const std::string& label, const std::string& text) {
        const UiItem* field = find_item(viewer.ui_items(), label);
        if (!field) return false;
        const ScreenRect r = field->rect;
        viewer.press_mouse(state, 0, (r.x0 + r.x1) * 0.5f, (r.y0 + r.y1) * 0.5f, kCtrl);
        viewer.release_mouse(state, 0);
        viewer.frame(state);
        for (char c : text) ImGui::GetIO().AddInputCharacter(c);
        viewer.frame(state);
        viewer.press_key(state, keys::enter);
        viewer.frame(state);
        return true;
    }
    // The note a field shows under itself for a refused value, or "".
    std::string refusal() const {
        for (const UiItem& item : viewer.ui_items())
            if (item.label.find(" is refused: ") != std::string::npos) return item.label;
        return "";
    }
};

TEST_F(ViewerMaterialFields, ACheckerCanBeSetEditedAndClearedAndAnImageMapNamed) {
    open_rendered_copy("material-fields");
    ASSERT_FALSE(HasFatalFailure());
    select(state.view, {Selection::Kind::primitive, 1});  // the sphere
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    ASSERT_NE(find_item(viewer.ui_items(), "checker"), nullptr) << "a checker field";
    ASSERT_NE(find_item(viewer.ui_items(), "image_map"), nullptr) << "an image map field";

    ASSERT_TRUE(viewer.click(state, "checker"));
    viewer.frame(state);
    ASSERT_TRUE(state.doc.scene.primitives[1].material.finish->checker);
    EXPECT_NE(document_text(state.doc).find("checker: <0.1, 0.1, 0.1>;"), std::string::npos)
        << document_text(state.doc);
    ASSERT_TRUE(viewer.click(state, "checker"));
    viewer.frame(state);
    EXPECT_FALSE(state.doc.scene.primitives[1].material.finish->checker);
    EXPECT_EQ(document_text(state.doc).find("checker"), std::string::npos)
        << document_text(state.doc);

    ASSERT_TRUE(viewer.click(state, "image_map"));
    for (char c : std::string("maps/tiles.png")) ImGui::GetIO().AddInputCharacter(c);
    viewer.frame(state);
    EXPECT_EQ(state.doc.scene.primitives[1].material.finish->image_map, "")
        << "applied on Enter only";
    viewer.press_key(state, keys::enter);
    EXPECT_EQ(state.doc.scene.primitives[1].material.finish->image_map, "maps/tiles.png");
    EXPECT_NE(document_text(state.doc).find("image_map: \"maps/tiles.png\";"), std::string::npos)
        << document_text(state.doc);
}

// A value past the language's limit typed into a field is
// refused, the field saying the limit, as --check and the parser would.
TEST_F(ViewerMaterialFields, AValuePastTheLimitIsRefusedAndTheFieldSaysTheLimit) {
    open_rendered_copy("field-limit");
    ASSERT_FALSE(HasFatalFailure());
    select(state.view, {Selection::Kind::primitive, 1});  // the sphere, radius 1
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    const std::string before = document_text(state.doc);

    for (const std::string typed : {"1e17", "1e308"}) {
        ASSERT_TRUE(type_into("radius", typed)) << "a radius field";
        const auto& sphere = shape_as<Sphere>(state.doc.scene.primitives[1].shape);
        EXPECT_EQ(sphere.radius, 1.0) << typed << " is refused";
        EXPECT_EQ(document_text(state.doc), before) << typed << " never reaches the file";
        EXPECT_NE(refusal().find("radius: "), std::string::npos) << typed;
        EXPECT_NE(refusal().find("must be greater than 0 and at most 1e+09"), std::string::npos)
            << refusal();
    }
    ASSERT_TRUE(type_into("radius", "2.5"));
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[1].shape).radius, 2.5);
    EXPECT_EQ(refusal(), "") << "a value taken clears the note";

    ASSERT_TRUE(type_into("center", "2e9"));
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[1].shape).center, Vec3(0, 1, 0));
    EXPECT_NE(refusal().find("must be from -1e+09 to 1e+09"), std::string::npos) << refusal();
}

// A whole number typed past its limit is refused as a number is, never
// clamped: width 100000 once became 65535 without a word.
TEST_F(ViewerMaterialFields, AWholeNumberPastItsLimitIsRefusedNotClamped) {
    open_rendered_copy("int-field-limit");
    ASSERT_FALSE(HasFatalFailure());
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    const int width = state.doc.scene.settings.width;
    const std::string before = document_text(state.doc);
    ASSERT_TRUE(type_into("width", "100000")) << "a width field";
    EXPECT_EQ(state.doc.scene.settings.width, width) << "neither taken nor clamped to 65535";
    EXPECT_EQ(document_text(state.doc), before);
    EXPECT_EQ(refusal(), "width: 100000 is refused: must be a whole number from 0 to 65535");
    ASSERT_TRUE(type_into("width", "80"));
    EXPECT_EQ(state.doc.scene.settings.width, 80);
    EXPECT_EQ(refusal(), "") << "a value taken clears the note";
}

// ImGui's colour picker changes the value in the frame it becomes active, so
// the value before the edit must be kept before the fields are drawn: one
// undo step gives the colour back exactly, and a redo the picked one.
TEST_F(ViewerMaterialFields, AColourPickedInThePickerIsOneUndoStep) {
    open_rendered_copy("colour-picker");
    ASSERT_FALSE(HasFatalFailure());
    select(state.view, {Selection::Kind::primitive, 1});  // the sphere
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    const Colour before = state.doc.scene.primitives[1].material.pigment;
    const std::size_t steps = state.history.undo.size();
    const UiItem* field = find_item(viewer.ui_items(), "pigment");
    ASSERT_NE(field, nullptr);
    // The swatch, between the three numbers and the label, opens the picker.
    const float swatch_x = field->rect.x1 - ImGui::CalcTextSize("pigment").x -
                           ImGui::GetStyle().ItemInnerSpacing.x - ImGui::GetFrameHeight() * 0.5f;
    const float y = (field->rect.y0 + field->rect.y1) * 0.5f;
    viewer.press_mouse(state, 0, swatch_x, y);
    viewer.release_mouse(state, 0);
    viewer.frame(state);
    ASSERT_FALSE(GImGui->OpenPopupStack.empty()) << "the picker is open";
    const ImGuiWindow* picker = GImGui->OpenPopupStack.back().Window;
    ASSERT_NE(picker, nullptr);
    // Inside its saturation-value square, below the label line.
    const float x0 = picker->Pos.x + ImGui::GetStyle().WindowPadding.x + 20.0f;
    const float y0 = picker->Pos.y + ImGui::GetStyle().WindowPadding.y +
                     ImGui::GetFrameHeightWithSpacing() + 30.0f;
    viewer.drag(state, 0, x0, y0, x0 + 10.0f, y0 + 10.0f);
    viewer.frame(state);
    const Colour picked = state.doc.scene.primitives[1].material.pigment;
    ASSERT_NE(picked, before) << "the picker changed the colour";
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one step for the whole pick";
    undo(state);
    viewer.frame(state);
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, before);
    EXPECT_EQ(state.doc.scene, *state.doc.original);
    redo(state);
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, picked);
}

}  // namespace
}  // namespace jt::view
