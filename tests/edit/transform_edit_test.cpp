// Adding, moving and removing transform operations in the text.

#include "jtracer/transform_edit.hpp"

#include "edit_fixture.hpp"
#include "edit_test_support.hpp"

#include <gtest/gtest.h>

namespace jt::test {
namespace {

const TransformOp kScale{TransformKind::scale, Vec3{2, 2, 2}, 0};

TEST(TransformOps, AddAtTheEndOfAnInlineBlock) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.primitives[0].transforms.push_back(kScale);
    const std::string text =
        expect_scene(add_transform_op(base.scene_text(), 0, 2, kScale), expected);
    const std::size_t at = span_of(base.text, "yrotate: 30;").second;
    expect_only_changed(base.text, text, at, at);
    EXPECT_NE(text.find("transform { translate: <0, 1, 0>; yrotate: 30; scale: <2, 2, 2>; }"),
              std::string::npos)
        << text;
}

TEST(TransformOps, AddBeforeAnOperationOnItsOwnLine) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    auto& ops = expected.primitives[2].transforms;
    ops.insert(ops.begin(), kScale);
    const std::string text =
        expect_scene(add_transform_op(base.scene_text(), 2, 0, kScale), expected);
    const std::size_t line = span_of(base.text, "            translate: <1, 0, 0>;").first;
    expect_only_changed(base.text, text, line, line);
    EXPECT_NE(
        text.find("            scale: <2, 2, 2>;\n            translate: <1, 0, 0>;   # first"),
        std::string::npos)
        << text;

    // After the last one: a new line with the same indentation.
    expected = base.scene();
    expected.primitives[2].transforms.push_back(kScale);
    const std::string last =
        expect_scene(add_transform_op(base.scene_text(), 2, 3, kScale), expected);
    EXPECT_NE(last.find("            zrotate: 10;\n            scale: <2, 2, 2>;\n        }"),
              std::string::npos)
        << last;
}

TEST(TransformOps, AddToAnObjectWithoutATransformBlockCreatesOne) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    expected.primitives[1].transforms.push_back(kScale);
    const std::string text =
        expect_scene(add_transform_op(base.scene_text(), 1, 0, kScale), expected);
    EXPECT_NE(text.find("plane { distance: -1; transform { scale: <2, 2, 2>; } }"),
              std::string::npos)
        << text;

    const Parsed empty_block(
        "cameras { perspective_camera { } }\nscene {\n    sphere {\n        "
        "transform {\n        }\n    }\n}\n");
    expected = empty_block.scene();
    expected.primitives[0].transforms.push_back(kScale);
    EXPECT_NE(expect_scene(add_transform_op(empty_block.scene_text(), 0, 0, kScale), expected)
                  .find("        transform {\n            scale: <2, 2, 2>;\n        }\n"),
              std::string::npos);
}

TEST(TransformOps, MoveRotatesTheStatementsThroughTheirSlots) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    auto& ops = expected.primitives[2].transforms;
    std::rotate(ops.begin(), ops.begin() + 1, ops.end());  // translate goes last
    const std::string text = expect_scene(move_transform_op(base.scene_text(), 2, 0, 2), expected);
    const std::size_t begin = span_of(base.text, "translate: <1, 0, 0>;").first;
    const std::size_t end = span_of(base.text, "zrotate: 10;").second;
    expect_only_changed(base.text, text, begin, end);
    EXPECT_NE(text.find("            scale: <1, 2, 1>;   # first\n            zrotate: 10;\n"
                        "            translate: <1, 0, 0>;\n"),
              std::string::npos)
        << text;

    // And back up.
    const Parsed moved(text);
    EXPECT_EQ(expect_scene(move_transform_op(moved.scene_text(), 2, 2, 0), base.scene()),
              base.text);
    EXPECT_EQ(expect_scene(move_transform_op(base.scene_text(), 2, 1, 1), base.scene()), base.text);
}

TEST(TransformOps, RemoveTakesTheLineOrTheStatement) {
    const Parsed base(kEditScene);
    Scene expected = base.scene();
    auto& ops = expected.primitives[2].transforms;
    ops.erase(ops.begin() + 1);
    const std::string text = expect_scene(remove_transform_op(base.scene_text(), 2, 1), expected);
    const auto [begin, end] = span_of(base.text, "            scale: <1, 2, 1>;\n");
    expect_only_changed(base.text, text, begin, end);

    expected = base.scene();
    expected.primitives[0].transforms.erase(expected.primitives[0].transforms.begin());
    const std::string first = expect_scene(remove_transform_op(base.scene_text(), 0, 0), expected);
    EXPECT_NE(first.find("transform { yrotate: 30; }"), std::string::npos) << first;
}

TEST(TransformOps, OperationsThatAreNotThere) {
    const Parsed base(kEditScene);
    EXPECT_EQ(error_of(remove_transform_op(base.scene_text(), 1, 0)),
              "plane 2 has no transform operation 1 (it has 0)");
    EXPECT_EQ(error_of(move_transform_op(base.scene_text(), 2, 0, 3)),
              "cylinder 3 has no transform operation 4 (it has 3)");
    EXPECT_EQ(error_of(add_transform_op(base.scene_text(), 0, 5, kScale)),
              "cannot insert transform operation 6 into sphere 1: it has 2");
    EXPECT_EQ(error_of(add_transform_op(base.scene_text(), 7, 0, kScale)),
              "there is no object 8: the scene has 3 objects");
}

}  // namespace
}  // namespace jt::test
