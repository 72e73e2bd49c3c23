// Adding, renaming and changing cameras in the text.

#include "jtracer/camera_edit.hpp"
#include "jtracer/new_block.hpp"

#include "edit_fixture.hpp"
#include "edit_test_support.hpp"

#include <gtest/gtest.h>

namespace jt::test {
namespace {

TEST(CameraEdit, UniqueNames) {
    const Parsed base(kEditScene);
    EXPECT_EQ(unique_camera_name(base.scene(), "top"), "top");
    EXPECT_EQ(unique_camera_name(base.scene(), "side"), "side 2");
    Scene more = base.scene();
    more.cameras.push_back(Camera{.name = "side 2", .focus_distance = std::nullopt});
    EXPECT_EQ(unique_camera_name(more, "side"), "side 3");
    EXPECT_EQ(unique_camera_name(more, "side 2"), "side 3");
}

TEST(CameraEdit, AddAppendsToTheCamerasBlock) {
    const Parsed base(kEditScene);
    const Camera added = new_camera(base.scene());
    EXPECT_EQ(added.name, "side 2");  // a copy of the active camera
    EXPECT_EQ(added.position, base.scene().cameras[1].position);
    Scene expected = base.scene();
    expected.cameras.push_back(added);
    const std::string text = expect_scene(add_camera(base.scene_text(), added), expected);
    const std::size_t close = span_of(base.text, "    }\n}\n\nscene").first + 6;
    expect_only_changed(base.text, text, close, close);

    EXPECT_EQ(error_of(add_camera(base.scene_text(), base.scene().cameras[0])),
              "camera 1 is already named \"front\": camera names must differ");
    Camera bad = added;
    bad.fov = 180;
    EXPECT_NE(error_of(add_camera(base.scene_text(), bad)).find("'fov' must be between"),
              std::string::npos);
}

TEST(CameraEdit, RenameCarriesActiveCameraAlong) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.cameras[1].name = "left";
    expected.settings.active_camera = "left";
    const std::string text = expect_scene(rename_camera(base.scene_text(), 1, "left"), expected);
    // Only the two values changed.
    const auto [begin, end] = span_of(base.text, "\"side\";\n}");
    expect_only_changed(base.text, text, begin, span_of(base.text, "\"side\";   #").second);
    (void)end;

    expected = base.scene();
    expected.cameras[0].name = "wide";
    const std::string front = expect_scene(rename_camera(base.scene_text(), 0, "wide"), expected);
    const auto name = span_of(base.text, "\"front\"");
    expect_only_changed(base.text, front, name.first, name.second);
}

TEST(CameraEdit, RenameRefusesEmptyDuplicateAndUnwritableNames) {
    const Parsed base(kEditScene);
    EXPECT_EQ(error_of(rename_camera(base.scene_text(), 1, "front")),
              "camera 1 is already named \"front\": camera names must differ");
    EXPECT_EQ(error_of(rename_camera(base.scene_text(), 1, "")), "a camera needs a name");
    EXPECT_NE(error_of(rename_camera(base.scene_text(), 1, "say \"hi\"")).find("cannot be written"),
              std::string::npos);
    EXPECT_EQ(error_of(rename_camera(base.scene_text(), 2, "x")),
              "there is no camera 3: the scene has 2 cameras");
    // Renaming to its own name changes nothing.
    EXPECT_EQ(expect_scene(rename_camera(base.scene_text(), 1, "side"), base.scene()), base.text);
}

TEST(CameraEdit, EveryPropertyNumerically) {
    const Parsed base(kEditScene);
    for (std::size_t index : {0u, 1u}) {
        SCOPED_TRACE(index);
        Camera changed = base.scene().cameras[index];
        changed.position = {1, 2, 3};
        changed.look_at = {0, 1, 0};
        changed.up = {0, 0, 1};
        changed.fov = 30;
        changed.aspect = 1.5;
        Scene expected = base.scene();
        expected.cameras[index] = changed;
        const std::string text =
            expect_scene(set_camera(base.scene_text(), index, changed), expected);
        // Nothing outside the camera's block changed.
        const auto& block = base.result.source.cameras[index];
        expect_only_changed(base.text, text, block.keyword_span.offset, block.close_brace + 1);
    }
    Camera wrong = base.scene().cameras[0];
    wrong.aspect = 0;
    EXPECT_EQ(error_of(set_camera(base.scene_text(), 0, wrong)),
              "camera 1: 'aspect' must be greater than 0 and at most 1e+09, got 0");
}

TEST(CameraEdit, AspectFromTheImageSize) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.cameras[1].aspect = 64.0 / 48.0;
    const std::string text = expect_scene(set_aspect_from_image(base.scene_text(), 1), expected);
    EXPECT_NE(text.find("        aspect: 1.3333333333333333;\n    }"), std::string::npos) << text;

    const Parsed no_size("cameras { perspective_camera { } }");
    EXPECT_EQ(error_of(set_aspect_from_image(no_size.scene_text(), 0)),
              "the image has no size yet: set render_settings' width and height first");
}

}  // namespace
}  // namespace jt::test
