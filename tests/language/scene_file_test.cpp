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

// Read to the limit, /dev/zero took a gigabyte and seconds before it failed.
TEST_F(SceneFile, DeviceIsRefusedAtOnce) {
    for (const std::string device : {"/dev/zero", "/dev/null"}) {
        const Expected<std::string> file = read_text_file(device);
        ASSERT_FALSE(file) << device;
        EXPECT_EQ(file.error().message, "'" + device + "' is a device, not a scene file");
    }
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

// A text of 64 MiB or more, loaded for a render: 70 spheres, each after a
// comment line of a MiB, then `last` on the last line.
std::string large_text(const std::string& last) {
    std::string text =
        "render_settings { width: 8; height: 4; }\n"
        "cameras { perspective_camera { aspect: 1; } }\n"
        "scene {\n";
    const std::string comment = "# " + std::string(std::size_t{1} << 20, 'c') + "\n";
    for (int i = 0; i < 70; ++i)
        text += comment + "  sphere { center: <" + std::to_string(i) + ", 0, 0>; }\n";
    text += last + "\n}\n";
    EXPECT_GE(text.size(), smallest_text_given_back);
    return text;
}

// The render's load gives the text back as the parse passes it: the same
// scene, the same diagnostics, located and quoted from the file read again.
TEST_F(SceneFile, ALargeTextIsGivenBackAndReadAgainForItsMessages) {
    const fs::path path = write("large.jts", large_text("  sphere { radius: 2; radius: 3; }"));
    // One thread: parts read on others would keep the text whole.
    const ParseOptions options{.source_map = false, .threads = 1};
    const LoadedScene whole = load_scene_file(path, options).value();
    const LoadedScene given =
        load_scene_file(path, options, TextKeeping::given_back_when_large).value();
    EXPECT_FALSE(whole.text_given_back);
    ASSERT_TRUE(given.text_given_back);
    EXPECT_TRUE(given.text.empty());
    EXPECT_EQ(given.parsed.scene, whole.parsed.scene);
    EXPECT_EQ(given.parsed.scene.primitives.size(), 71u);

    const std::vector<Diagnostic> found = check_scene(given);
    EXPECT_EQ(found, check_scene(whole));
    ASSERT_EQ(found.size(), 2u);  // the radius set twice, the camera's aspect
    EXPECT_EQ(found[0].pos.line, 144);
    EXPECT_EQ(found[1].pos.line, 2);
    const std::string quoted = format_diagnostics(found, given);
    EXPECT_EQ(quoted, format_diagnostics(found, whole));
    EXPECT_NE(quoted.find("    sphere { radius: 2; radius: 3; }\n"), std::string::npos) << quoted;

    // A small text, or one parsed with the map, is kept whole.
    const fs::path small = write("small.jts", "scene { sphere { } }\n");
    EXPECT_FALSE(load_scene_file(small, options, TextKeeping::given_back_when_large)
                     .value()
                     .text_given_back);
    EXPECT_FALSE(load_scene_file(path, {.threads = 1}, TextKeeping::given_back_when_large)
                     .value()
                     .text_given_back);
}

// Changed after it was read, the file is not read again for a text it no
// longer holds: the messages stay unlocated and unquoted, and a note says why.
TEST_F(SceneFile, AGivenBackTextWhoseFileChangedIsNotQuoted) {
    const fs::path path = write("large.jts", large_text("  sphere { radius: 2; radius: 3; }"));
    const ParseOptions options{.source_map = false, .threads = 1};
    const LoadedScene given =
        load_scene_file(path, options, TextKeeping::given_back_when_large).value();
    ASSERT_TRUE(given.text_given_back);
    const std::vector<Diagnostic> parse_found = given.parsed.diagnostics;
    ASSERT_EQ(parse_found.size(), 1u);

    write("large.jts", "scene { }\n");
    const std::string quoted = format_diagnostics(parse_found, given);
    EXPECT_NE(quoted.find("'radius' is set again"), std::string::npos) << quoted;
    EXPECT_EQ(quoted.find("radius: 2; radius: 3;"), std::string::npos) << quoted;
    EXPECT_NE(quoted.find("changed or went away after it was read, so the messages above "
                          "cannot quote it"),
              std::string::npos)
        << quoted;

    // The camera's aspect needs locating: it stays at line 0, with the note.
    const std::vector<Diagnostic> found = check_scene(given);
    ASSERT_EQ(found.size(), 3u);
    EXPECT_EQ(found[1].pos, SourcePos{});
    EXPECT_EQ(found[1].severity, Severity::warning);
    EXPECT_EQ(found[2].severity, Severity::note);
    EXPECT_NE(found[2].message.find("the messages above say no line"), std::string::npos);
}

TEST_F(SceneFile, LoadReportsIoErrorsWithoutParsing) {
    const Expected<LoadedScene> loaded = load_scene_file(dir / "missing.jts");
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().message.find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace jt
