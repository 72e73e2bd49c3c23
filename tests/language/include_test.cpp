// Language 1.3 `include` (docs/language.md §15.6): files read in place, paths,
// depth, cycles, missing files, names across files and located messages.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/limits.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/scene_file.hpp"
#include "test_util.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <thread>

namespace jt {
namespace {

using test::brief;
using test::write_file;

class Include : public testing::Test {
  protected:
    test::ScratchDir scratch{"include"};
    const std::filesystem::path& dir = scratch.path();

    void write(const std::string& name, std::string_view text) {
        std::filesystem::create_directories((dir / name).parent_path());
        write_file(dir / name, text);
    }
    // Parses `text` as the file main.jts of the scratch folder.
    ParseResult parse(std::string_view text, ParseOptions options = {}) {
        options.main_file = (dir / "main.jts").string();
        return parse_scene(text, options);
    }
    // "FILE:LINE:COL: error: ..." per diagnostic, FILE the scratch-relative name.
    std::string located(const ParseResult& r) {
        std::string out;
        for (const Diagnostic& d : r.diagnostics) {
            const std::string name =
                d.pos.file == 0 ? "main.jts"
                                : std::filesystem::path(r.source.files[d.pos.file - 1].name)
                                      .lexically_relative(dir)
                                      .generic_string();
            out += (out.empty() ? "" : "\n") + name + ":" + brief({d});
        }
        return out;
    }
};

const Sphere& sphere(const ParseResult& r, std::size_t i) {
    return shape_as<Sphere>(r.scene.primitives.at(i).shape);
}

TEST_F(Include, FilesAreReadInPlaceAtTheTopInCamerasAndInScene) {
    write("settings.jts", "render_settings { width: 40; height: 30; }\n");
    write("camera.jts", "perspective_camera { name: \"side\"; position: <0, 0, -5>; }\n");
    write("spheres.jts", "sphere { radius: 2; }\npoint_light { position: <1, 2, 3>; }\n");
    const std::string included =
        "include \"settings.jts\";\n"
        "cameras { perspective_camera { name: \"front\"; } include \"camera.jts\"; }\n"
        "scene { sphere { radius: 1; } include \"spheres.jts\"; sphere { radius: 3; } }\n";
    const std::string flat =
        "render_settings { width: 40; height: 30; }\n"
        "cameras { perspective_camera { name: \"front\"; }\n"
        "perspective_camera { name: \"side\"; position: <0, 0, -5>; } }\n"
        "scene { sphere { radius: 1; } sphere { radius: 2; }\n"
        "point_light { position: <1, 2, 3>; } sphere { radius: 3; } }\n";
    ParseResult r = parse(included);
    EXPECT_EQ(brief(r.diagnostics), "");
    EXPECT_EQ(r.scene, parse_scene(flat).scene);
    ASSERT_EQ(r.scene.primitives.size(), 3u);
    EXPECT_EQ(sphere(r, 1).radius, 2.0);
    ASSERT_EQ(r.source.files.size(), 3u);
    EXPECT_EQ(r.source.files[1].name, (dir / "camera.jts").string());
    EXPECT_EQ(r.source.files[1].included_at, (SourcePos{2, 57}));
    // Every block knows its file; its spans are in that file's text.
    EXPECT_EQ(r.source.cameras.at(1).keyword_span.pos, (SourcePos{1, 1, 2}));
    EXPECT_EQ(r.source.primitives.at(1).keyword_span.pos, (SourcePos{1, 1, 3}));
    EXPECT_EQ(r.source.primitives.at(2).keyword_span.pos.file, 0u);
    EXPECT_EQ(r.source.render_settings->keyword_span.pos.file, 1u);
    const PropertySource& radius =
        r.source.properties.at(r.source.primitives.at(1).properties.first);
    EXPECT_EQ(r.source.files[2].text.substr(radius.value_span.offset, radius.value_span.length),
              "2");
}

// A vector of plain numbers (read in one scan, lexer.hpp's plain_vector) is
// read from the file it is written in, even where the main text holds another
// vector at the same offset.
TEST_F(Include, PlainVectorsAreReadFromTheirOwnFile) {
    const std::string main_text = "scene { include \"a.jts\"; sphere { center: <7, 8, 9>; } }\n";
    const std::size_t at = main_text.find('<');
    write("a.jts", "sphere { center:" + std::string(at - 16, ' ') + "<1, -2, 3>; }\n");
    ParseResult r = parse(main_text);
    EXPECT_EQ(brief(r.diagnostics), "");
    ASSERT_EQ(r.scene.primitives.size(), 2u);
    EXPECT_EQ(sphere(r, 0).center, Vec3(1, -2, 3));
    EXPECT_EQ(sphere(r, 1).center, Vec3(7, 8, 9));
    const PropertySource& center =
        r.source.properties.at(r.source.primitives.at(0).properties.first);
    EXPECT_EQ(center.value_span.pos, (SourcePos{1, static_cast<int>(at) + 1, 1}));
}

TEST_F(Include, AScenelessOfIncludesKeepsNoFiles) {
    ParseResult r = parse("scene { sphere { } }");
    EXPECT_TRUE(r.source.files.empty());
    EXPECT_TRUE(r.source.unread_includes.empty());
    EXPECT_EQ(r.source, parse_scene("scene { sphere { } }").source);
}

TEST_F(Include, ElsewhereIsAnErrorAtTheKeyword) {
    write("a.jts", "");
    EXPECT_EQ(brief(parse("scene { sphere { include \"a.jts\"; } }").diagnostics),
              "1:18: error: 'include' may stand only at the top level, directly in 'cameras' or "
              "directly in 'scene'");
    EXPECT_EQ(brief(parse("render_settings { include \"a.jts\"; }").diagnostics),
              "1:19: error: 'include' may stand only at the top level, directly in 'cameras' or "
              "directly in 'scene'");
    EXPECT_EQ(brief(parse("scene { sphere { material { include \"a.jts\"; } } }").diagnostics),
              "1:29: error: 'include' may stand only at the top level, directly in 'cameras' or "
              "directly in 'scene'");
    EXPECT_EQ(brief(parse("include a;").diagnostics),
              "1:9: error: expected the path of a file in double quotes after 'include', got "
              "the word 'a' (an include takes a string literal, not a name: write 'include "
              "\"FILE.jts\";')");
    // A name holding the path: the hint writes its string out.
    EXPECT_EQ(brief(parse("define s = \"base.inc\";\ninclude s;").diagnostics),
              "2:9: error: expected the path of a file in double quotes after 'include', got "
              "the word 's' (an include takes a string literal, not a name: write 'include "
              "\"base.inc\";')");
    EXPECT_EQ(brief(parse("include \"a.jts\" scene { }").diagnostics),
              "1:16: error: expected ';' after 'include \"a.jts\"'");
    EXPECT_EQ(brief(parse("include \"\";").diagnostics),
              "1:9: error: 'include' takes the path of a file; this string is empty");
}

TEST_F(Include, ABlockOpenedInAFileClosesInIt) {
    write("open.jts", "sphere {\n  radius: 1;\n");
    write("close.jts", "sphere { } }\n");
    EXPECT_EQ(located(parse("scene { include \"open.jts\"; }\n")),
              "open.jts:1:1: error: this 'sphere' block is never closed: expected '}' before the "
              "end of the file");
    EXPECT_EQ(located(parse("scene { include \"close.jts\"; }\n")),
              "close.jts:1:12: error: this '}' closes no block of this file: a block opened in a "
              "file closes in that file");
    write("top.jts", "scene {\n");
    EXPECT_EQ(located(parse("include \"top.jts\";\n")),
              "top.jts:1:1: error: this 'scene' block is never closed: expected '}' before the "
              "end of the file");
}

TEST_F(Include, PathsAreRelativeToTheNamingFile) {
    write("parts/a.jts",
          "include \"b.jts\";\n"
          "render_settings { background_map: \"sky.png\"; }\n");
    write("parts/b.jts",
          "scene { mesh { file: \"../models/m.obj\"; material { image_map: \"wood.png\"; } }"
          " mesh { file: \"/abs/m.obj\"; } }\n");
    ParseResult r = parse("include \"parts/a.jts\";");
    EXPECT_EQ(brief(r.diagnostics), "");
    EXPECT_EQ(r.scene.settings.background_map, "parts/sky.png");
    ASSERT_EQ(r.scene.primitives.size(), 2u);
    EXPECT_EQ(shape_as<Mesh>(r.scene.primitives[0].shape).file, "models/m.obj");
    EXPECT_EQ(r.scene.primitives[0].material.finish->image_map, "parts/wood.png");
    EXPECT_EQ(shape_as<Mesh>(r.scene.primitives[1].shape).file, "/abs/m.obj");
    ASSERT_EQ(r.source.files.size(), 2u);
    EXPECT_EQ(r.source.files[1].name, (dir / "parts/b.jts").string());
    // An absolute include path is allowed.
    EXPECT_EQ(brief(parse("include \"" + (dir / "parts/b.jts").string() + "\";").diagnostics), "");
}

TEST_F(Include, Depth32IsAllowedAnd33IsAnErrorAtTheString) {
    for (int d = 1; d <= 33; ++d)
        write("d" + std::to_string(d) + ".jts", "include \"d" + std::to_string(d + 1) + ".jts\";");
    write("d33.jts", "scene { sphere { } }");
    write("d34.jts", "");
    ParseResult r = parse("include \"d1.jts\";");
    EXPECT_EQ(located(r),
              "d32.jts:1:9: error: includes are nested too deeply: a file may be included at "
              "most 32 levels deep");
    // Depth 32 itself: d2 includes down to d33 at depth 32, which holds the scene.
    ParseResult ok = parse("include \"d2.jts\";");
    EXPECT_EQ(brief(ok.diagnostics), "");
    EXPECT_EQ(ok.scene.primitives.size(), 1u);
    EXPECT_EQ(ok.source.files.size(), static_cast<std::size_t>(kMaxIncludeDepth));
}

TEST_F(Include, ACycleIsAnErrorAtTheStringThatClosesIt) {
    write("a.jts", "include \"b.jts\";\n");
    write("b.jts", "scene { }\ninclude \"a.jts\";\n");
    EXPECT_EQ(located(parse("include \"a.jts\";")),
              "b.jts:2:9: error: an include cycle: '" + (dir / "a.jts").string() +
                  "' is already being read, so it would include itself");
    // The main file including itself, here through a symbolic link.
    write("main.jts", "include \"link.jts\";");
    std::filesystem::create_symlink(dir / "main.jts", dir / "link.jts");
    Expected<LoadedScene> loaded = load_scene_file(dir / "main.jts");
    ASSERT_TRUE(loaded);
    EXPECT_EQ(brief(loaded->parsed.diagnostics),
              "1:9: error: an include cycle: '" + (dir / "link.jts").string() +
                  "' is already being read, so it would include itself");
}

TEST_F(Include, AMissingFileIsAnErrorAndHidesUnknownNames) {
    ParseResult r = parse(
        "include \"nope.jts\";\n"
        "scene { sphere { radius: r; material: m; } }\n");
    EXPECT_EQ(brief(r.diagnostics),
              "1:9: error: cannot read '" + (dir / "nope.jts").string() + "': no such file");
    EXPECT_EQ(r.source.unread_includes, std::vector<std::string>{(dir / "nope.jts").string()});
    std::filesystem::create_directory(dir / "folder.jts");
    EXPECT_EQ(
        brief(parse("include \"folder.jts\";").diagnostics),
        "1:9: error: '" + (dir / "folder.jts").string() + "' is a directory, not a scene file");
}

// As in the main file, a byte that is no text is located where it is, in the
// file that holds it, with the include chain: a large file need not be searched.
TEST_F(Include, AFileThatIsNotTextIsAnErrorAtItsFirstBadByte) {
    write("binary.jts", std::string("scene {\n  \0}", 12));
    write("parts/latin.jts", "# caf\xe9\n");
    write("parts/outer.jts", "\ninclude \"latin.jts\";\n");
    ParseResult r = parse(
        "include \"binary.jts\";\ninclude \"parts/outer.jts\";\n"
        "scene { sphere { radius: r; } }\n");
    EXPECT_EQ(located(r),
              "binary.jts:2:3: error: the file is not a text file: it contains a NUL byte\n"
              "parts/latin.jts:1:6: error: the file is not a text file: it contains a byte that "
              "is not UTF-8 text");
    ASSERT_EQ(r.source.files.size(), 3u);
    EXPECT_EQ(r.source.files[2].included_at, (SourcePos{2, 9, 2}));
    std::string formatted;
    for (const Diagnostic& d : r.diagnostics)
        formatted += format_diagnostic(d, "main.jts", "", r.source.files);
    EXPECT_NE(formatted.find("note: included from " + (dir / "parts/outer.jts").string() +
                             ":2:9\nnote: included from main.jts:2:9\n"),
              std::string::npos)
        << formatted;
}

// Opening a FIFO for reading waits for a writer: with none, the parse (and
// the render, or the viewer's reload) would hang for good.
TEST_F(Include, AFifoIsRefusedWithoutWaitingForAWriter) {
    const std::filesystem::path fifo = dir / "pipe.jts";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Should the parse wait on the FIFO after all, a writer comes after a
    // while and ends it, so that the test fails instead of hanging.
    std::atomic<bool> parsed{false};
    std::thread writer([&] {
        for (int i = 0; i < 100 && !parsed; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) ::close(fd);
    });
    const std::string found = brief(parse("include \"pipe.jts\";").diagnostics);
    parsed = true;
    writer.join();
    EXPECT_EQ(found,
              "1:9: error: '" + fifo.string() + "' is a named pipe (FIFO), not a scene file");
    EXPECT_EQ(brief(parse("include \"/dev/null\";").diagnostics),
              "1:9: error: '/dev/null' is a device, not a scene file");
}

// The included files share one limit: the message says so, and how much of
// it the files before took, rather than a limit of odd size for this file.
// Sparse files: their sizes are what count, nothing is read.
TEST_F(Include, TheSizeLimitIsSharedByTheIncludedFilesAndSaysSo) {
    write("small.jts", "define r = 1;\n");
    write("big.jts", "");
    std::filesystem::resize_file(dir / "big.jts", max_scene_file_bytes);
    write("huge.jts", "");
    std::filesystem::resize_file(dir / "huge.jts", max_scene_file_bytes + 1);
    const std::string limit = "the files a scene includes may hold 1 GiB (1073741824 bytes) in all";
    EXPECT_EQ(brief(parse("include \"small.jts\";\ninclude \"big.jts\";").diagnostics),
              "2:9: error: '" + (dir / "big.jts").string() +
                  "' is too large to include (1073741824 bytes): " + limit +
                  ", and the files included before it hold 14");
    EXPECT_EQ(brief(parse("include \"huge.jts\";").diagnostics),
              "1:9: error: '" + (dir / "huge.jts").string() +
                  "' is too large to include (1073741825 bytes): " + limit);
}

// "the one at line 1" would send the reader to line 1 of the file the
// warning is in, where the block replaced is not.
TEST_F(Include, ABlockReplacedInAnotherFileIsNamedWithItsFile) {
    write("parts/settings.jts", "render_settings { width: 8; }\nscene { }\n");
    EXPECT_EQ(located(parse("include \"parts/settings.jts\";\n"
                            "render_settings { width: 9; }\nscene { }\n")),
              "main.jts:2:1: warning: another 'render_settings' block: only the last one is "
              "used, so the one at " +
                  (dir / "parts/settings.jts").string() +
                  ":1:1 is ignored\n"
                  "main.jts:3:1: warning: another 'scene' block: only the last one is used, so "
                  "the one at " +
                  (dir / "parts/settings.jts").string() + ":2:1 is ignored");
    EXPECT_EQ(located(parse("render_settings { width: 9; }\nscene { }\n"
                            "include \"parts/settings.jts\";\n")),
              "parts/settings.jts:1:1: warning: another 'render_settings' block: only the last "
              "one is used, so the one at " +
                  (dir / "main.jts").string() +
                  ":1:1 is ignored\n"
                  "parts/settings.jts:2:1: warning: another 'scene' block: only the last one is "
                  "used, so the one at " +
                  (dir / "main.jts").string() + ":2:1 is ignored");
    // In one file, its line is enough.
    EXPECT_EQ(located(parse("scene { }\nscene { }\n")),
              "main.jts:2:1: warning: another 'scene' block: only the last one is used, so the "
              "one at line 1 is ignored");
}

// A POV-Ray user's colors.inc turned into an included file often keeps its
// '#declare' lines, which are comments here: the unknown name's message says
// so wherever that comment is, naming its file when it is in another.
TEST_F(Include, APovRayDirectiveInAnyFileReadIsNamedWithItsFile) {
    const std::string unknown =
        "error: unknown name 'Red' (names must be defined before they are used); POV-Ray's "
        "#include and #declare are comments here, as at ";
    const std::string advice = ": write include \"FILE\"; and define NAME = VALUE;";
    const std::string colors = (dir / "colors.jts").string();
    write("colors.jts", "# colours\n#declare Red = <1, 0, 0>;\n");
    EXPECT_EQ(located(parse("include \"colors.jts\";\n"
                            "scene { sphere { material { pigment: Red; } } }\n")),
              "main.jts:2:38: " + unknown + colors + ":2:1" + advice);
    // In the file that uses the name, its line and column are enough.
    write("ball.jts", "#declare Red = <1, 0, 0>;\nsphere { material { pigment: Red; } }\n");
    EXPECT_EQ(located(parse("scene { include \"ball.jts\"; }\n")),
              "ball.jts:2:30: " + unknown + "1:1" + advice);
    // The main file's comment, seen from an included file.
    write("uses.jts", "sphere { material { pigment: Red; } }\n");
    EXPECT_EQ(located(parse("#include \"colors.inc\"\nscene { include \"uses.jts\"; }\n")),
              "uses.jts:1:30: " + unknown + (dir / "main.jts").string() + ":1:1" + advice);
}

TEST_F(Include, ABackslashInAPathThatIsNotFoundSaysFoldersUseSlashes) {
    write("parts/ball.jts", "define r = 1;\n");
    EXPECT_EQ(brief(parse("include \"parts\\ball.jts\";").diagnostics),
              "1:9: error: cannot read '" + (dir / "parts\\ball.jts").string() +
                  "': no such file (folders are separated by '/' on every platform)");
    EXPECT_EQ(brief(parse("include \"parts/ball.jts\";").diagnostics), "");
}

TEST_F(Include, TheSameFileTwiceIsFineUnlessItDefinesNames) {
    write("ball.jts", "sphere { radius: r; }\n");
    ParseResult r = parse(
        "define r = 2;\n"
        "scene { include \"ball.jts\"; include \"ball.jts\"; }\n");
    EXPECT_EQ(brief(r.diagnostics), "");
    EXPECT_EQ(r.scene.primitives.size(), 2u);
    EXPECT_EQ(r.source.files.size(), 2u);
    write("defs.jts", "define r = 2;\n");
    write("mats.jts", "include \"defs.jts\";\n");
    EXPECT_EQ(located(parse("include \"mats.jts\";\ninclude \"defs.jts\";\n")),
              "defs.jts:1:8: error: 'r' is defined twice: it was first defined at " +
                  (dir / "defs.jts").string() + ":1:8, included from " +
                  (dir / "mats.jts").string() + ":1:9, included from " +
                  (dir / "main.jts").string() + ":1:9; read again here, included from " +
                  (dir / "main.jts").string() + ":2:9");
    // A first definition in the main file, seen from an included file: its
    // "1:8" alone would be read in the included file.
    EXPECT_EQ(located(parse("define r = 1;\ninclude \"defs.jts\";\n")),
              "defs.jts:1:8: error: 'r' is defined twice: it was first defined at " +
                  (dir / "main.jts").string() + ":1:8; read again here, included from " +
                  (dir / "main.jts").string() + ":2:9");
}

TEST_F(Include, AFindingInAnIncludedFileNamesThatFileForItsEarlierPlace) {
    // A primitive naming two materials points at the first: in an included
    // file, with the file and the chain it came through, as for a name
    // defined twice.
    write("ball.jts", "sphere {\n  material: m;\n  material: m;\n}\n");
    EXPECT_EQ(located(parse("material m { reflection: 0.5; }\n"
                            "scene { include \"ball.jts\"; }\n")),
              "ball.jts:3:3: error: a primitive names at most one material; this one "
              "already names one at " +
                  (dir / "ball.jts").string() + ":2:3, included from " +
                  (dir / "main.jts").string() + ":2:17");
}

TEST_F(Include, NamesAreVisibleAcrossFilesInReadingOrder) {
    write("defs.jts", "define r = 2;\nmaterial red { pigment: <1, 0, 0>; }\n");
    write("use.jts", "scene { sphere { radius: r; material: red; } }\n");
    ParseResult r = parse("include \"defs.jts\";\ninclude \"use.jts\";\n");
    EXPECT_EQ(brief(r.diagnostics), "");
    EXPECT_EQ(sphere(r, 0).radius, 2.0);
    EXPECT_EQ(r.scene.primitives[0].material.pigment, Vec3(1, 0, 0));
    EXPECT_EQ(r.source.definitions.at(1).name_span.pos, (SourcePos{2, 10, 1}));
    // Used before the include that defines it: unknown.
    EXPECT_EQ(located(parse("include \"use.jts\";\ninclude \"defs.jts\";\n")),
              "use.jts:1:26: error: unknown name 'r' (names must be defined before they are "
              "used)\n"
              "use.jts:1:39: error: unknown name 'red' (names must be defined before they are "
              "used)");
}

TEST_F(Include, DiagnosticsNameTheFileAndEveryIncludeOnTheWay) {
    write("main.jts", "scene {\n  include \"parts/objects.jts\";\n}\n");
    write("parts/objects.jts", "sphere { }\ninclude \"../more.jts\";\n");
    write("more.jts", "sphere { radius: -1; }\n");
    // Named as given on the command line: relative names stay relative.
    const std::filesystem::path cwd = std::filesystem::current_path();
    std::filesystem::current_path(dir);
    Expected<LoadedScene> loaded = load_scene_file("./main.jts");
    std::filesystem::current_path(cwd);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(format_diagnostics(check_scene(*loaded), *loaded),
              "more.jts:1:18: error: 'radius' must be greater than 0 and at most 1e+09, got -1\n"
              "    sphere { radius: -1; }\n"
              "                     ^\n"
              "note: included from parts/objects.jts:2:9\n"
              "note: included from ./main.jts:2:11\n");
}

// "expected ';'" points just past the value, in the file that holds it,
// whichever way the value was read: a lone number, a plain vector, an
// expression, a define's value.
TEST_F(Include, AMissingSemicolonIsReportedInTheIncludedFile) {
    write("parts/objects.jts",
          "sphere { radius: 1 }\n"
          "sphere { center: <1, 2, 3> }\n"
          "sphere { radius: 2 * 3 }\n");
    write("parts/names.jts", "define r = 1 + 2\n");
    ParseResult r =
        parse("include \"parts/names.jts\";\nscene {\n  include \"parts/objects.jts\";\n}\n");
    EXPECT_EQ(located(r),
              "parts/names.jts:1:17: error: expected ';' after the value of 'define r'\n"
              "parts/objects.jts:1:19: error: expected ';' after the value of 'radius'\n"
              "parts/objects.jts:2:27: error: expected ';' after the value of 'center'\n"
              "parts/objects.jts:3:23: error: expected ';' after the value of 'radius'");
}

TEST_F(Include, NotesDoNotCountTowardTheErrorLimit) {
    std::string bad;
    for (int i = 0; i < 30; ++i) bad += "x;\n";
    write("bad.jts", bad);
    ParseResult r = parse("include \"bad.jts\";");
    EXPECT_EQ(r.diagnostics.size(), 21u);  // 20 errors and "too many errors"
    const std::string text = format_diagnostics(r.diagnostics, "main.jts", "", r.source.files);
    std::size_t notes = 0;
    for (std::size_t at = 0; (at = text.find("note: included from", at)) != std::string::npos; ++at)
        ++notes;
    EXPECT_EQ(notes, 21u);
}

TEST(IncludeReader, ACustomReaderConfinesIncludes) {
    const std::map<std::string, std::string> files{{"a.jts", "scene { sphere { } }"}};
    ParseOptions options;
    options.read_include = [&](const std::string& path, std::uintmax_t) -> Expected<IncludedText> {
        auto found = files.find(path);
        if (found == files.end()) return Error{"'" + path + "' is not one of the test's files"};
        return IncludedText{found->first, found->second};
    };
    EXPECT_EQ(parse_scene("include \"a.jts\";", options).scene.primitives.size(), 1u);
    EXPECT_EQ(brief(parse_scene("include \"/etc/passwd\";", options).diagnostics),
              "1:9: error: '/etc/passwd' is not one of the test's files");
}

TEST(IncludeReader, ATextWithoutAFileReadsFromTheWorkingDirectory) {
    test::ScratchDir scratch{"include-cwd"};
    write_file(scratch.path() / "here.jts", "scene { sphere { } }");
    const std::filesystem::path cwd = std::filesystem::current_path();
    std::filesystem::current_path(scratch.path());
    ParseResult r = parse_scene("include \"here.jts\";");
    std::filesystem::current_path(cwd);
    EXPECT_EQ(brief(r.diagnostics), "");
    EXPECT_EQ(r.scene.primitives.size(), 1u);
    EXPECT_EQ(r.source.files.at(0).name, "here.jts");
}

TEST(IncludeReader, RepeatedIncludesCannotMultiplyWithoutBound) {
    // Each file includes the next twice: 2^14 readings without a bound.
    std::map<std::string, std::string> files{{"f13", ""}};
    for (int d = 0; d < 13; ++d)
        files["f" + std::to_string(d)] = "include \"f" + std::to_string(d + 1) + "\"; include \"f" +
                                         std::to_string(d + 1) + "\";";
    ParseOptions options;
    options.read_include = [&](const std::string& path, std::uintmax_t) -> Expected<IncludedText> {
        return IncludedText{path + "#" + std::to_string(files.size()), files[path]};
    };
    ParseResult r = parse_scene("include \"f0\";", options);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].message,
              "too many files included: a scene may read at most 4096 (counting repeats)");
    EXPECT_EQ(r.source.files.size(), kMaxIncludeReadings);
}

}  // namespace
}  // namespace jt
