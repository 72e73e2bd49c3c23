// Adding, duplicating and deleting blocks, and adding material and transform
// blocks: each edit reads back as the expected scene, and the text outside
// the changed block keeps every byte.

#include "jtracer/block_edit.hpp"
#include "jtracer/new_block.hpp"
#include "jtracer/serializer.hpp"

#include "edit_fixture.hpp"
#include "edit_test_support.hpp"

#include <gtest/gtest.h>

namespace jt::test {
namespace {

// The offset where the line holding `part` starts.
std::size_t line_of(std::string_view text, std::string_view part) {
    const std::size_t at = span_of(text, part).first;
    return text.rfind('\n', at) + 1;
}

// A primitive goes with the primitives (after the last, before the lights
// that follow it), a light after the last item.
TEST(AddBlock, EveryKindGoesAfterTheLastOfItsKindInTheBlocksStyle) {
    const Parsed base(kEditScene);
    const std::size_t close = base.text.rfind("}\n");
    const std::size_t after_objects = line_of(base.text, "    point_light") - 1;  // the blank line
    for (ShapeKind kind : kShapeKinds) {
        SCOPED_TRACE(std::string(keyword_of(kind)));
        const Primitive added = new_primitive(kind, base.scene());
        Scene expected = base.scene();
        expected.primitives.push_back(added);
        const std::string text = expect_scene(add_primitive(base.scene_text(), added), expected);
        expect_only_changed(base.text, text, after_objects, after_objects);
        // A blank line, then the serializer's block at the items' indentation.
        std::string block = "\n";
        for (const std::string& line : block_lines(added)) block += "    " + line + "\n";
        EXPECT_EQ(text.substr(after_objects, block.size()), block);
    }
    const PointLight light = new_light(base.scene());
    Scene expected = base.scene();
    expected.lights.push_back(light);
    const std::string text = expect_scene(add_light(base.scene_text(), light), expected);
    expect_only_changed(base.text, text, close, close);
}

TEST(AddBlock, CreatesTheSceneBlockWhenThereIsNone) {
    const Parsed base("cameras { perspective_camera { } }");
    const Primitive added = new_primitive(ShapeKind::sphere, base.scene());
    Scene expected = base.scene();
    expected.primitives.push_back(added);
    const std::string text = expect_scene(add_primitive(base.scene_text(), added), expected);
    expect_only_changed(base.text, text, base.text.size(), base.text.size());
    EXPECT_NE(text.find("\n\nscene {\n    sphere {\n"), std::string::npos) << text;
}

TEST(AddBlock, IntoAnEmptyOrOneLineSceneBlock) {
    const Parsed empty("cameras { perspective_camera { } }\nscene {\n}\n");
    Scene expected = empty.scene();
    expected.lights.push_back(new_light(empty.scene()));
    const std::string text =
        expect_scene(add_light(empty.scene_text(), expected.lights[0]), expected);
    EXPECT_NE(text.find("scene {\n    point_light {\n        position:"), std::string::npos)
        << text;

    const Parsed one_line("cameras { perspective_camera { } } scene { sphere { } }");
    expected = one_line.scene();
    expected.lights.push_back(new_light(one_line.scene()));
    const std::string inline_text =
        expect_scene(add_light(one_line.scene_text(), expected.lights[0]), expected);
    EXPECT_EQ(inline_text.find('\n'), std::string::npos) << inline_text;
}

// In new_scene()'s text, which holds a light and no primitive, the first
// primitive goes before the light.
TEST(AddBlock, TheFirstPrimitiveGoesBeforeTheLights) {
    const Parsed base(serialize_scene(new_scene()));
    const Primitive added = new_primitive(ShapeKind::sphere, base.scene());
    Scene expected = base.scene();
    expected.primitives.push_back(added);
    const std::string text = expect_scene(add_primitive(base.scene_text(), added), expected);
    ASSERT_NE(text.find("sphere {"), std::string::npos) << text;
    EXPECT_LT(text.find("sphere {"), text.find("point_light {")) << text;
}

TEST(DuplicateBlock, CopiesThePrimitiveWithItsCommentsRightAfterIt) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.primitives.insert(expected.primitives.begin() + 1, expected.primitives[0]);
    const std::string text =
        expect_scene(duplicate_block(base.scene_text(), {BlockKind::primitive, 0}), expected);
    const std::size_t after = line_of(base.text, "plane {") - 1;  // the blank line after the sphere
    expect_only_changed(base.text, text, after, after);
    const std::string sphere = base.text.substr(line_of(base.text, "    sphere {"),
                                                after - line_of(base.text, "    sphere {"));
    EXPECT_EQ(text.substr(after, sphere.size() + 1), "\n" + sphere) << text;
    EXPECT_NE(sphere.find("# unit"), std::string::npos);
}

TEST(DuplicateBlock, ACameraCopyGetsAFreeName) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    Camera copy = expected.cameras[0];
    copy.name = "front 2";
    expected.cameras.insert(expected.cameras.begin() + 1, copy);
    const std::string text =
        expect_scene(duplicate_block(base.scene_text(), {BlockKind::camera, 0}), expected);
    const std::size_t after = line_of(base.text, "    perspective_camera {\n");
    expect_only_changed(base.text, text, after, after);
    const std::string line = "    perspective_camera { name: \"front 2\"; position: <0, 0, 5>; }\n";
    EXPECT_EQ(text.substr(after, line.size()), line);

    // An unnamed camera's copy is named too.
    const Parsed unnamed("cameras { perspective_camera { fov: 30; } }");
    expected = unnamed.scene();
    copy = expected.cameras[0];
    copy.name = "camera";
    expected.cameras.push_back(copy);
    EXPECT_EQ(expect_scene(duplicate_block(unnamed.scene_text(), {BlockKind::camera, 0}), expected),
              "cameras { perspective_camera { fov: 30; } perspective_camera { fov: 30; name: "
              "\"camera\"; } }");
}

TEST(DuplicateBlock, ALight) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.lights.push_back(expected.lights[0]);
    const std::string text =
        expect_scene(duplicate_block(base.scene_text(), {BlockKind::light, 0}), expected);
    const std::size_t end = base.text.rfind("}\n");
    expect_only_changed(base.text, text, end, end);
}

TEST(DeleteBlock, TheWholeBlockAndOneOfTheBlankLinesAroundIt) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.primitives.erase(expected.primitives.begin());
    const std::string text =
        expect_scene(delete_block(base.scene_text(), {BlockKind::primitive, 0}), expected);
    // The sphere's lines go; the comment above it is outside the block and stays.
    const std::size_t begin = line_of(base.text, "    sphere {");
    const std::size_t end = line_of(base.text, "    plane {") - 1;
    expect_only_changed(base.text, text, begin, end);
    EXPECT_EQ(text.size(), base.text.size() - (end - begin));
    EXPECT_NE(text.find("# A red ball.\n\n    plane {"), std::string::npos) << text;

    // Between two blank lines, one of them goes with it.
    expected = base.scene();
    expected.primitives.erase(expected.primitives.begin() + 1);
    const std::string no_plane =
        expect_scene(delete_block(base.scene_text(), {BlockKind::primitive, 1}), expected);
    const std::size_t plane = line_of(base.text, "    plane {");
    expect_only_changed(base.text, no_plane, plane, line_of(base.text, "    cylinder {"));
    EXPECT_NE(no_plane.find("    }\n\n    cylinder {"), std::string::npos) << no_plane;
    EXPECT_EQ(text.find("# unit"), std::string::npos);

    // The last item: the blank line before it goes, the scene's brace stays.
    expected = base.scene();
    expected.lights.clear();
    const std::string no_light =
        expect_scene(delete_block(base.scene_text(), {BlockKind::light, 0}), expected);
    EXPECT_EQ(no_light.substr(no_light.size() - 8), "    }\n}\n");
}

TEST(DeleteBlock, AOneLineBlockWithItsTrailingComment) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.cameras.erase(expected.cameras.begin());
    const std::string text =
        expect_scene(delete_block(base.scene_text(), {BlockKind::camera, 0}), expected);
    const std::size_t begin = line_of(base.text, "name: \"front\"");
    expect_only_changed(base.text, text, begin, line_of(base.text, "    perspective_camera {\n"));

    const Parsed inline_scene("cameras { perspective_camera { } } scene { sphere { } plane { } }");
    expected = inline_scene.scene();
    expected.primitives.erase(expected.primitives.begin());
    EXPECT_EQ(
        expect_scene(delete_block(inline_scene.scene_text(), {BlockKind::primitive, 0}), expected),
        "cameras { perspective_camera { } } scene { plane { } }");
}

TEST(DeleteBlock, TheActiveCameraTakesItsActiveCameraLineAlong) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.cameras.pop_back();
    expected.settings.active_camera.clear();
    const std::string text =
        expect_scene(delete_block(base.scene_text(), {BlockKind::camera, 1}), expected);
    EXPECT_EQ(text.find("active_camera"), std::string::npos) << text;
    EXPECT_NE(text.find("    height: 48;\n}\n"), std::string::npos) << text;
}

TEST(DeleteBlock, RefusesTheOnlyCameraAndBlocksThatAreNotThere) {
    const Parsed one("cameras { perspective_camera { } } scene { sphere { } }");
    EXPECT_NE(error_of(delete_block(one.scene_text(), {BlockKind::camera, 0})).find("only camera"),
              std::string::npos);
    EXPECT_EQ(error_of(delete_block(one.scene_text(), {BlockKind::primitive, 1})),
              "there is no object 2: the scene has 1 objects");
    EXPECT_EQ(error_of(duplicate_block(one.scene_text(), {BlockKind::light, 0})),
              "there is no point_light 1: the scene has 0 lights");
}

TEST(ChildBlocks, AMaterialForAnObjectThatHasNone) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.primitives[1].material = new_material();
    const std::string text =
        expect_scene(add_material_block(base.scene_text(), 1, new_material()), expected);
    // The one-line plane stays on one line.
    const auto [begin, end] = span_of(base.text, "plane { distance: -1; }");
    expect_only_changed(base.text, text, end - 1, end - 1);
    EXPECT_NE(text.find("plane { distance: -1; material { pigment: <0.8, 0.8, 0.8>; "),
              std::string::npos)
        << text;
    (void)begin;

    // A block with lines of its own gets lines at its items' indentation.
    expected = base.scene();
    expected.primitives[2].material.pigment = Colour{0.5};
    Material grey;
    grey.pigment = Colour{0.5};
    const std::string cylinder =
        expect_scene(add_material_block(base.scene_text(), 2, grey), expected);
    EXPECT_NE(
        cylinder.find("        }\n        material {\n            pigment: <0.5, 0.5, 0.5>;\n"),
        std::string::npos)
        << cylinder;

    EXPECT_EQ(error_of(add_material_block(base.scene_text(), 0, grey)),
              "sphere 1 already has a material block");
}

TEST(ChildBlocks, ATransformForAnObjectThatHasNone) {
    const Parsed base(kEditScene);
    const std::string empty = expect_scene(add_transform_block(base.scene_text(), 1), base.scene());
    EXPECT_NE(empty.find("plane { distance: -1; transform { } }"), std::string::npos) << empty;

    Scene expected = base.scene();
    const TransformOp up{TransformKind::translate, Vec3{0, 2, 0}, 0};
    expected.primitives[1].transforms = {up};
    const std::string text =
        expect_scene(add_transform_block(base.scene_text(), 1, {up}), expected);
    EXPECT_NE(text.find("plane { distance: -1; transform { translate: <0, 2, 0>; } }"),
              std::string::npos)
        << text;
    EXPECT_EQ(error_of(add_transform_block(base.scene_text(), 2)),
              "cylinder 3 already has a transform block");
}

}  // namespace
}  // namespace jt::test
