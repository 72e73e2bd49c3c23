// Save-in-place of values read from included files (docs/language.md §15.6):
// an edit is written into the file that holds the value, every other byte of
// every file unchanged.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/source_edit.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt {
namespace {

namespace fs = std::filesystem;

class IncludeEdit : public testing::Test {
  protected:
    test::ScratchDir scratch{"include-edit"};
    const fs::path dir = scratch.path();
    const std::string main_text =
        "# main\n"
        "render_settings { width: 40; }\n"
        "scene {\n"
        "    sphere { radius: 1; }   # in main\n"
        "    include \"parts/ball.jts\";\n"
        "}\n";
    const std::string ball_text =
        "# a ball\n"
        "sphere {\n"
        "    center: <1.0, 2.0, 3.0>;   # kept\n"
        "    material { pigment: <0.5, 0.5, 0.5>; }\n"
        "}\n";

    ParseResult parse() {
        fs::create_directories(dir / "parts");
        test::write_file(dir / "parts/ball.jts", ball_text);
        ParseOptions options;
        options.main_file = (dir / "main.jts").string();
        return parse_scene(main_text, options);
    }
};

TEST_F(IncludeEdit, AValueOfAnIncludedFileIsWrittenIntoThatFile) {
    const ParseResult r = parse();
    ASSERT_TRUE(r.ok());
    Scene edited = r.scene;
    shape_as<Sphere>(edited.primitives[1].shape).center.y = 5;
    edited.primitives[1].material.pigment = Colour(1, 0, 0);
    edited.primitives[1].material.finish.edit().reflection = 0.25;  // never written: inserted there
    const SourceEditResult result = apply_scene_edits(main_text, r.source, r.scene, edited);
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_EQ(result.text, main_text);
    ASSERT_EQ(result.files.size(), 1u);
    EXPECT_EQ(result.files[0].file, 1u);
    EXPECT_EQ(result.files[0].path, (dir / "parts/ball.jts").string());
    EXPECT_EQ(result.files[0].text,
              "# a ball\n"
              "sphere {\n"
              "    center: <1.0, 5, 3.0>;   # kept\n"
              "    material { pigment: <1, 0, 0>; reflection: 0.25; }\n"
              "}\n");
}

TEST_F(IncludeEdit, EditsOfBothFilesLeaveEveryOtherByte) {
    const ParseResult r = parse();
    Scene edited = r.scene;
    shape_as<Sphere>(edited.primitives[0].shape).radius = 2;
    shape_as<Sphere>(edited.primitives[1].shape).center.x = -1;
    const SourceEditResult result = apply_scene_edits(main_text, r.source, r.scene, edited);
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_EQ(result.text,
              "# main\n"
              "render_settings { width: 40; }\n"
              "scene {\n"
              "    sphere { radius: 2; }   # in main\n"
              "    include \"parts/ball.jts\";\n"
              "}\n");
    ASSERT_EQ(result.files.size(), 1u);
    EXPECT_EQ(result.files[0].text.find("center: <-1, 2.0, 3.0>;   # kept"), 9u + 9u + 4u);
}

TEST_F(IncludeEdit, AFileReadTwiceChangesForEveryReadingOrNotAtAll) {
    const std::string twice = "scene { include \"parts/ball.jts\"; include \"parts/ball.jts\"; }\n";
    fs::create_directories(dir / "parts");
    test::write_file(dir / "parts/ball.jts", ball_text);
    ParseOptions options;
    options.main_file = (dir / "main.jts").string();
    const ParseResult r = parse_scene(twice, options);
    ASSERT_TRUE(r.ok());
    Scene edited = r.scene;
    for (Primitive& p : edited.primitives) shape_as<Sphere>(p.shape).center.z = 7;
    SourceEditResult result = apply_scene_edits(twice, r.source, r.scene, edited);
    ASSERT_TRUE(result.ok()) << result.error;
    ASSERT_EQ(result.files.size(), 1u);
    EXPECT_EQ(result.files[0].readings, 2);
    EXPECT_NE(result.files[0].text.find("center: <1.0, 2.0, 7>;"), std::string::npos);
    // The two readings edited differently: one text cannot hold both.
    shape_as<Sphere>(edited.primitives[1].shape).center.z = 8;
    result = apply_scene_edits(twice, r.source, r.scene, edited);
    EXPECT_FALSE(result.ok());
    EXPECT_TRUE(result.files.empty());
    EXPECT_EQ(result.text, twice);
}

}  // namespace
}  // namespace jt
