// scene_file.hpp: reading scene files with clear I/O errors, and the one-call check.

#include "jtracer/scene_file.hpp"

#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include "test_util.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace jt {
namespace {

namespace fs = std::filesystem;

class SceneFile : public test::ScratchTest {
  protected:
    fs::path write(const std::string& name, const std::string& text) {
        test::write_file(dir / name, text);
        return dir / name;
    }
};

TEST_F(SceneFile, ReadsAFileWhole) {
    std::string text = "scene { }\n# \xC3\xA9\n";
    const Expected<std::string> file = read_text_file(write("a.jts", text));
    ASSERT_TRUE(file) << file.error().message;
    EXPECT_EQ(*file, text);
}

TEST_F(SceneFile, MissingFile) {
    fs::path path = dir / "nope.jts";
    const Expected<std::string> file = read_text_file(path);
    ASSERT_FALSE(file);
    EXPECT_EQ(file.error().message, "cannot read '" + path.string() + "': no such file");
}

TEST_F(SceneFile, Directory) {
    const Expected<std::string> file = read_text_file(dir);
    const std::string shown = dir.string();
    ASSERT_FALSE(file);
    EXPECT_EQ(file.error().message, "'" + shown + "' is a directory, not a scene file");
}

TEST_F(SceneFile, TooLarge) {
    fs::path path = write("big.jts", std::string(100, ' '));
    const Expected<std::string> file = read_text_file(path, 99);
    const std::string name = path.string();
    ASSERT_FALSE(file);
    EXPECT_EQ(file.error().message,
              "'" + name + "' is too large to read (100 bytes; the limit is 99)");
    EXPECT_TRUE(read_text_file(path, 100));
}

TEST_F(SceneFile, Unreadable) {
    if (::geteuid() == 0) GTEST_SKIP() << "root reads any file";
    fs::path path = write("locked.jts", "scene { }");
    fs::permissions(path, fs::perms::none);
    const Expected<std::string> file = read_text_file(path);
    ASSERT_FALSE(file);
    EXPECT_EQ(file.error().message, "cannot read '" + path.string() + "': permission denied");
}

TEST_F(SceneFile, LoadAndCheckReportsParseThenValidation) {
    fs::path path = write("s.jts",
                          "render_settings { width: 4; height: 4; }\n"
                          "cameras { perspective_camera { look_at: <0, 0, 0>; } }\n"
                          "scene { sphere { radius: 2; radius: 3; } }\n");
    const Expected<LoadedScene> read = load_scene_file(path);
    ASSERT_TRUE(read) << read.error().message;
    const LoadedScene& loaded = *read;
    EXPECT_EQ(loaded.path, path.string());
    auto diagnostics = check_scene(loaded);
    EXPECT_EQ(format_diagnostics(diagnostics, "s.jts", loaded.text),
              "s.jts:3:29: warning: 'radius' is set again in this 'sphere'; the later value wins "
              "(first set at line 3)\n"
              "    scene { sphere { radius: 2; radius: 3; } }\n"
              "                                ^\n"
              "s.jts:2:41: error: camera 1: 'look_at' equals 'position', so the camera looks "
              "nowhere\n"
              "    cameras { perspective_camera { look_at: <0, 0, 0>; } }\n"
              "                                            ^\n");
    EXPECT_TRUE(has_errors(diagnostics));
}

// Loaded without its source map (as the CLI does), the scene is the same and
// check_scene still locates every finding, by parsing again when there is one.
TEST_F(SceneFile, WithoutTheSourceMapTheFindingsAreStillLocated) {
    fs::path path = write("s.jts",
                          "render_settings { width: 4; height: 4; }\n"
                          "cameras { perspective_camera { look_at: <0, 0, 0>; } }\n"
                          "scene { sphere { radius: 2; radius: 3;\n"
                          "  transform { scale: <1, 0, 1>; } } }\n");
    const LoadedScene mapped = load_scene_file(path).value();
    const LoadedScene unmapped = load_scene_file(path, {.source_map = false}).value();
    EXPECT_EQ(unmapped.parsed.scene, mapped.parsed.scene);
    EXPECT_EQ(unmapped.parsed.source, SceneSource{});
    EXPECT_FALSE(mapped.parsed.source.properties.empty());
    EXPECT_EQ(check_scene(unmapped), check_scene(mapped));
    EXPECT_EQ(test::brief(check_scene(unmapped)),
              "3:29: warning: 'radius' is set again in this 'sphere'; the later value wins (first "
              "set at line 3)\n"
              "2:41: error: camera 1: 'look_at' equals 'position', so the camera looks nowhere\n"
              "4:15: warning: 'scale' <1, 0, 1> has a zero component: it flattens the primitive "
              "to nothing; it is left out");

    fs::path clean = write("c.jts",
                           "render_settings { width: 4; height: 4; }\n"
                           "cameras { perspective_camera { aspect: 1; } }\n"
                           "scene { sphere { } }\n");
    EXPECT_TRUE(check_scene(load_scene_file(clean, {.source_map = false}).value()).empty());
}

// A finding about the settings or cameras alone is located by a parse that
// keeps no primitive: the same positions as with the whole map.
TEST_F(SceneFile, FindingsOutsidePrimitivesAreLocatedWithoutThem) {
    fs::path path = write("a.jts",
                          "render_settings { width: 8; height: 4; }\n"
                          "cameras { perspective_camera { aspect: 1; } }\n"
                          "scene { sphere { radius: 2; material { pigment: <1, 0, 0>; } }\n"
                          "  point_light { position: <0, 1, 0>; }\n"
                          "  sphere { transform { translate: <1, 0, 0>; } } }\n");
    const LoadedScene mapped = load_scene_file(path).value();
    const LoadedScene unmapped = load_scene_file(path, {.source_map = false}).value();
    EXPECT_EQ(check_scene(unmapped), check_scene(mapped));
    EXPECT_EQ(test::brief(check_scene(unmapped)),
              "2:40: warning: camera 1: 'aspect' 1 differs from width/height = 2 by more than 1%, "
              "so the image will look stretched");
}

// A quiet caller drops warnings: they stay unlocated (no second parse), while
// errors are located as ever.
TEST_F(SceneFile, WarningsNeedNotBeLocated) {
    fs::path warned = write("w.jts",
                            "render_settings { width: 8; height: 4; }\n"
                            "cameras { perspective_camera { aspect: 1; } }\n"
                            "scene { sphere { } }\n");
    const LoadedScene loaded = load_scene_file(warned, {.source_map = false}).value();
    const std::vector<Diagnostic> found = check_scene(loaded, {.locate_warnings = false});
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pos, SourcePos{});
    EXPECT_EQ(found[0].severity, Severity::warning);

    fs::path wrong = write("e.jts",
                           "render_settings { width: 8; height: 4; }\n"
                           "cameras { perspective_camera { look_at: <0, 0, 0>; aspect: 1; } }\n"
                           "scene { sphere { } }\n");
    const LoadedScene bad = load_scene_file(wrong, {.source_map = false}).value();
    EXPECT_EQ(check_scene(bad, {.locate_warnings = false}),
              check_scene(load_scene_file(wrong).value()));
}

TEST_F(SceneFile, ValidationIsSkippedWhenParsingFailed) {
    const LoadedScene loaded =
        load_scene_file(write("bad.jts", "scene { sphere { radius: -1; } }")).value();
    EXPECT_EQ(test::brief(check_scene(loaded)),
              "1:26: error: 'radius' must be greater than 0 and at most 1e+09, got -1");
}

TEST_F(SceneFile, LoadReportsIoErrorsWithoutParsing) {
    const Expected<LoadedScene> loaded = load_scene_file(dir / "missing.jts");
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().message.find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace jt
