// Issue 27 item 21: the material panel edits a checker's colour and an image
// map's file, which the showcase's backdrop and the globe use; through the
// OSMesa frame code, into the text as Save scene writes it.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <filesystem>
#include <string>

namespace jt::view {
namespace {

using namespace jt::test;
namespace fs = std::filesystem;

TEST(ViewerMaterialFields, ACheckerCanBeSetEditedAndClearedAndAnImageMapNamed) {
    HeadlessViewer viewer(1100, 900);
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    AppState state{test_config()};
    const fs::path file = scene_copy("material-fields");
    open_scene(state, file);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    select(state.view, {Selection::Kind::primitive, 1});  // the sphere
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    ASSERT_NE(find_item(viewer.ui_items(), "checker"), nullptr) << "a checker field";
    ASSERT_NE(find_item(viewer.ui_items(), "image_map"), nullptr) << "an image map field";

    ASSERT_TRUE(viewer.click(state, "checker"));
    viewer.frame(state);
    ASSERT_TRUE(state.doc.scene.primitives[1].material.checker);
    EXPECT_NE(document_text(state.doc).find("checker: <0.1, 0.1, 0.1>;"), std::string::npos)
        << document_text(state.doc);
    ASSERT_TRUE(viewer.click(state, "checker"));
    viewer.frame(state);
    EXPECT_FALSE(state.doc.scene.primitives[1].material.checker);
    EXPECT_EQ(document_text(state.doc).find("checker"), std::string::npos)
        << document_text(state.doc);

    ASSERT_TRUE(viewer.click(state, "image_map"));
    for (char c : std::string("maps/tiles.png")) ImGui::GetIO().AddInputCharacter(c);
    viewer.frame(state);
    EXPECT_EQ(state.doc.scene.primitives[1].material.image_map, "") << "applied on Enter only";
    viewer.press_key(state, keys::enter);
    EXPECT_EQ(state.doc.scene.primitives[1].material.image_map, "maps/tiles.png");
    EXPECT_NE(document_text(state.doc).find("image_map: \"maps/tiles.png\";"), std::string::npos)
        << document_text(state.doc);
    fs::remove_all(file.parent_path());
}

// Issue 27 item 14: a value past the language's limit typed into a field is
// refused, the field saying the limit, as --check and the parser would.
TEST(ViewerMaterialFields, AValuePastTheLimitIsRefusedAndTheFieldSaysTheLimit) {
    HeadlessViewer viewer(1100, 900);
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    AppState state{test_config()};
    const fs::path file = scene_copy("field-limit");
    open_scene(state, file);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    select(state.view, {Selection::Kind::primitive, 1});  // the sphere, radius 1
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    const std::string before = document_text(state.doc);
    auto type_into = [&](const std::string& label, const std::string& text) {
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
    };
    auto refusal = [&]() -> std::string {
        for (const UiItem& item : viewer.ui_items())
            if (item.label.find(" is refused: ") != std::string::npos) return item.label;
        return "";
    };

    for (const std::string typed : {"1e17", "1e308"}) {
        ASSERT_TRUE(type_into("radius", typed)) << "a radius field";
        const auto& sphere = std::get<Sphere>(state.doc.scene.primitives[1].shape);
        EXPECT_EQ(sphere.radius, 1.0) << typed << " is refused";
        EXPECT_EQ(document_text(state.doc), before) << typed << " never reaches the file";
        EXPECT_NE(refusal().find("radius: "), std::string::npos) << typed;
        EXPECT_NE(refusal().find("must be greater than 0 and at most 1e+09"), std::string::npos)
            << refusal();
    }
    ASSERT_TRUE(type_into("radius", "2.5"));
    EXPECT_EQ(std::get<Sphere>(state.doc.scene.primitives[1].shape).radius, 2.5);
    EXPECT_EQ(refusal(), "") << "a value taken clears the note";

    ASSERT_TRUE(type_into("center", "2e9"));
    EXPECT_EQ(std::get<Sphere>(state.doc.scene.primitives[1].shape).center, Vec3(0, 1, 0));
    EXPECT_NE(refusal().find("must be from -1e+09 to 1e+09"), std::string::npos) << refusal();
    fs::remove_all(file.parent_path());
}

}  // namespace
}  // namespace jt::view
