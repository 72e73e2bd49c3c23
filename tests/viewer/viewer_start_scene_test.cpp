// Start a scene in an empty file, through the OSMesa frame
// code: the Objects panel opens on its empty list, ready for Add object, the
// image is named after the file and the camera has a name; new objects go
// with the objects, and a plane lies at the view's floor.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt::view {
namespace {

using namespace jt::test;
namespace fs = std::filesystem;

class ViewerStartScene : public ViewerFixture {
  protected:
    ViewerStartScene() : ViewerFixture(1100, 700) {}
    void TearDown() override { fs::remove_all(dir); }
    const fs::path dir = make_scratch_dir("viewer-start-scene");
};

TEST_F(ViewerStartScene, TheObjectsPanelOpensOnTheEmptyListAndObjectsGoWithTheObjects) {
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path file = dir / "garden.jts";
    write_file(file, "");
    open_scene(state, file);
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Start a scene"));
    ASSERT_TRUE(state.doc.loaded) << state.message;
    viewer.frame(state);
    viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "Add object"), nullptr) << "the Objects panel is open";
    const std::string text = document_text(state.doc);
    EXPECT_NE(text.find("filename: \"garden.bmp\";"), std::string::npos) << text;
    EXPECT_EQ(text.find("name: \"\""), std::string::npos) << text;

    ASSERT_TRUE(add_object(state, ShapeKind::plane));
    const std::string with_plane = document_text(state.doc);
    EXPECT_LT(with_plane.find("plane {"), with_plane.find("point_light {")) << with_plane;
    EXPECT_NE(with_plane.find("distance: 0;"), std::string::npos) << with_plane;
}

}  // namespace
}  // namespace jt::view
