// jtracer-cli end to end: exit codes, which file it writes, and that no file
// is written on any error.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/version.hpp"
#include "memory_cap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace jt {
namespace {

namespace fs = std::filesystem;

const std::string small_scene = R"(
render_settings { width: 32; height: 18; filename: "from_scene.bmp"; recurse_depth: 2; }
cameras {
    perspective_camera { name: "front"; position: <0, 1, 5>; look_at: <0, 0.5, 0>; aspect: 1.7778; }
    perspective_camera { name: "top"; position: <0, 6, 0.1>; look_at: <0, 0, 0>; aspect: 1.7778; }
}
scene {
    plane { material { pigment: <0.8, 0.8, 0.8>; diffuse: <1, 1, 1>; reflection: 0.3; } }
    sphere { center: <0, 0.8, 0>; radius: 0.8;
             material { pigment: <1, 0.2, 0.1>; diffuse: <1, 1, 1>; specular: <1, 1, 1>; } }
    cylinder { radius: 0.3; height: 1.2; transform { xrotate: 30; translate: <1.5, 0, 0>; }
               material { pigment: <0.2, 0.4, 1>; diffuse: <1, 1, 1>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)";

class Cli : public test::ScratchTest {
  protected:
    void SetUp() override { write("scene.jts", small_scene); }

    void write(const std::string& name, const std::string& text) {
        test::write_file(dir / name, text);
    }

    // Runs jtracer-cli in `dir` with these arguments (split by the shell).
    test::ProgramRun run(const std::string& args) { return run_shell("'" JT_CLI "' " + args); }

    // Every file in dir other than the ones the test itself made.
    std::vector<std::string> outputs() {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir)) {
            std::string n = e.path().filename().string();
            if (e.path().extension() != ".jts") names.push_back(n);
        }
        std::sort(names.begin(), names.end());
        return names;
    }
};

TEST_F(Cli, WritesTheScenesFilenameAsBmpAndASummary) {
    test::ProgramRun r = run("scene.jts");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(outputs(), std::vector<std::string>{"from_scene.bmp"});
    const Expected<Image8> image = read_bmp(dir / "from_scene.bmp");
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, 32);
    EXPECT_EQ(image->height, 18);
    EXPECT_NE(r.err.find("32x18"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Mrays/s"), std::string::npos) << r.err;
}

TEST_F(Cli, DefaultFilenameIsJtracerBmp) {
    std::string text = small_scene;
    text.replace(text.find(" filename: \"from_scene.bmp\";"), 28, "");
    write("scene.jts", text);
    test::ProgramRun r = run("scene.jts");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(outputs(), std::vector<std::string>{"jtracer.bmp"});
}

TEST_F(Cli, SceneFilenameIsBmpWhateverItsExtension) {
    std::string text = small_scene;
    text.replace(text.find("from_scene.bmp"), 14, "picture.png");
    write("scene.jts", text);
    ASSERT_EQ(run("-q scene.jts").code, 0);
    EXPECT_TRUE(read_bmp(dir / "picture.png")) << "the manual: always a BMP";
    // ... and says so, since a viewer trusting the name refuses the file.
    test::ProgramRun r = run("scene.jts");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("jtracer-cli: warning: the scene's filename 'picture.png' is written as "
                         "a BMP, as the scene's filename always is; -o picture.png writes a PNG"),
              std::string::npos)
        << r.err;
    r = run("scene.jts --frames 2");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("'picture-0000.png' is written as a BMP"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("'picture-0001.png' is written"), std::string::npos) << "once: " << r.err;
}

// A region file is a BMP: a scene's filename naming a PNG is refused as
// `-o part.png --region-output` is, located at the filename, writing nothing.
TEST_F(Cli, RegionOutputUnderASceneFilenameNamingAPngIsRefusedThere) {
    std::string text = small_scene;
    text.replace(text.find("from_scene.bmp"), 14, "part.png");
    write("scene.jts", text);
    const std::string region = " --region 0,0,8,8 --region-output";
    test::ProgramRun r = run("scene.jts -q" + region);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("scene.jts:2:52: error: --region-output writes a BMP (its placement "
                         "record lives in the BMP): name the scene's filename .bmp, or the "
                         "output with -o"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(run("scene.jts --check" + region).code, 2) << "refused by --check as -o is";
    r = run("scene.jts -q --frames 2" + region);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("scene.jts:2:52: error: --region-output writes a BMP"), std::string::npos)
        << r.err;
    r = run("scene.jts -q -o part.png" + region);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--region-output: writes a BMP (its placement record lives in the BMP)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(outputs(), std::vector<std::string>{});
    // Any name but a PNG's is written, as -o's is.
    text.replace(text.find("part.png"), 8, "part.img");
    write("scene.jts", text);
    r = run("scene.jts -q" + region);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(outputs(), std::vector<std::string>{"part.img"});
}

// -o gives a PNG for .png and a BMP for any other name: one that names
// another image format gets a warning, no other does.
TEST_F(Cli, AnOutputNamingAnotherImageFormatWarns) {
    test::ProgramRun r = run("scene.jts -o shot.jpg");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(read_bmp(dir / "shot.jpg"));
    EXPECT_NE(r.err.find("jtracer-cli: warning: -o/--output 'shot.jpg' is written as a BMP"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(run("scene.jts -o shot.jpg -q").err, "");
    for (const char* name : {"shot.bmp", "shot.PNG", "shot", "shot.out"}) {
        r = run(std::string("scene.jts -o ") + name);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << name << ": " << r.err;
    }
}

TEST_F(Cli, OutputOptionWinsAndPngByExtension) {
    test::ProgramRun r = run("scene.jts -o shot.png --width 40 --height 20 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "") << "--quiet";
    EXPECT_EQ(outputs(), std::vector<std::string>{"shot.png"});
    const Expected<Image8> image = read_image(dir / "shot.png");
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, 40);
    EXPECT_EQ(image->height, 20);
    std::ifstream png(dir / "shot.png", std::ios::binary);
    char magic[4] = {};
    png.read(magic, 4);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

// A pipeline's `-o - | next-program`: the BMP goes to standard output, no
// file called "-" is made.
TEST_F(Cli, ADashOutputIsStandardOutput) {
    test::ProgramRun r = run("scene.jts -o - -q > piped.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(outputs(), std::vector<std::string>{"piped.bmp"});
    const Expected<Image8> image = read_bmp(dir / "piped.bmp");
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, 32);
    r = run("scene.jts -o - -q | wc -c > size.txt");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(std::stoi(test::read_file(dir / "size.txt")), 54 + 18 * (32 * 3));
    EXPECT_EQ(run("scene.jts -o ./- -q").code, 0);
    EXPECT_TRUE(fs::exists(dir / "-")) << "./- is still a file of that name";
}

// `-o -` typed with standard output left on the terminal (a forgotten
// redirection) filled the terminal with the image's bytes, possibly leaving
// it in a garbled state, and the render was lost: refused before reading the
// scene, as with a terminal's own device.
TEST_F(Cli, AnImageIsNotWrittenToATerminal) {
    if (run_shell("command -v script").code != 0) GTEST_SKIP() << "no script(1) here";
    // script(1) runs the program with a terminal as its standard output.
    test::ProgramRun r = run_shell("script -qec \"'" JT_CLI "' scene.jts -o -\" /dev/null");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("-o/--output: standard output is a terminal"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("BM"), std::string::npos) << "image bytes reached the terminal";
    r = run_shell("script -qec \"'" JT_CLI "' scene.jts -o \\$(tty)\" /dev/null");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("is a terminal"), std::string::npos) << r.out;
    // Redirected, standard output takes the image.
    r = run_shell("script -qec \"'" JT_CLI "' scene.jts -q -o - > piped.bmp\" /dev/null");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(read_bmp(dir / "piped.bmp"));
}

// -o - is spoken of as standard output, a name the user gave, not as
// /dev/stdout; closed (a job started with >&-), it is refused before the
// render rather than failing after it with "cannot write '/dev/stdout'".
TEST_F(Cli, ADashOutputIsNamedStandardOutput) {
    test::ProgramRun r = run("scene.jts -o - > piped.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("wrote standard output: 32x18"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("/dev/stdout"), std::string::npos) << r.err;
    r = run("scene.jts -o - >&-");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("-o/--output: standard output is closed"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("/dev/stdout"), std::string::npos) << r.err;
    // A write that fails (a full disk behind the redirection) too.
    r = run("scene.jts -q -o - > /dev/full");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(r.err, "jtracer-cli: cannot write standard output: No space left on device\n");
}

TEST_F(Cli, ThreadCountGivesByteIdenticalFiles) {
    ASSERT_EQ(run("-q scene.jts --samples 4 --threads 1 -o one.bmp").code, 0);
    ASSERT_EQ(run("-q scene.jts --samples 4 --threads 2 -o two.bmp").code, 0);
    std::ifstream a(dir / "one.bmp", std::ios::binary), b(dir / "two.bmp", std::ios::binary);
    std::stringstream sa, sb;
    sa << a.rdbuf();
    sb << b.rdbuf();
    EXPECT_GT(sa.str().size(), 54u);
    EXPECT_TRUE(sa.str() == sb.str());
}

TEST_F(Cli, CameraOptionPicksTheCamera) {
    ASSERT_EQ(run("-q scene.jts -o front.bmp").code, 0);
    ASSERT_EQ(run("-q scene.jts -o top.bmp --camera top").code, 0);
    const Expected<Image8> front = read_bmp(dir / "front.bmp");
    const Expected<Image8> top = read_bmp(dir / "top.bmp");
    ASSERT_TRUE(front) << front.error().message;
    ASSERT_TRUE(top) << top.error().message;
    EXPECT_FALSE(*front == *top);
    test::ProgramRun r = run("scene.jts --camera nowhere");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("\"front\", \"top\""), std::string::npos) << r.err;
    EXPECT_EQ(outputs(), (std::vector<std::string>{"front.bmp", "top.bmp"}));
    // Cameras without a name are counted, not listed as "" (no --camera picks one).
    write("unnamed.jts",
          "cameras { perspective_camera { } perspective_camera { name: \"top\"; } "
          "perspective_camera { } }\n");
    r = run("unnamed.jts --camera nowhere --width 4 --height 4");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("the scene has no camera named \"nowhere\" (its cameras: \"top\" and 2 "
                         "without a name)"),
              std::string::npos)
        << r.err;
    write("alone.jts", "cameras { perspective_camera { } }\n");
    r = run("alone.jts --camera nowhere --width 4 --height 4");
    EXPECT_NE(r.err.find("(its cameras: 1 without a name)"), std::string::npos) << r.err;
}

// A render of hours must not end in "cannot write": a missing folder or a
// folder in the way is found before the render starts.
TEST_F(Cli, AnOutputThatCannotBeWrittenStopsBeforeTheRender) {
    test::ProgramRun r = run("scene.jts -o no/such/folder/out.bmp");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("jtracer-cli: cannot write 'no/such/folder/out.bmp': No such file or "
                         "directory; nothing was rendered"),
              std::string::npos)
        << r.err;
    fs::create_directory(dir / "taken.bmp");
    r = run("scene.jts -o taken.bmp");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("cannot write 'taken.bmp': it is a directory; nothing was rendered"),
              std::string::npos)
        << r.err;
    // Each frame's file, which may be in a folder of its own, before its render.
    fs::create_directory(dir / "f0");
    r = run("scene.jts --frames 2 -o 'f%d/shot.bmp'");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("cannot write 'f1/shot.bmp': No such file or directory; frames 0..0 "
                         "were written"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("frame 1, clock"), std::string::npos) << r.err;
    EXPECT_EQ(outputs(), (std::vector<std::string>{"f0", "taken.bmp"}));
    EXPECT_TRUE(fs::exists(dir / "f0" / "shot.bmp"));
    // A rerun with --skip-existing wrote none of the frames it kept.
    fs::create_directory(dir / "f1");
    r = run("scene.jts --frames 3 --skip-existing -o 'f%d/shot.bmp'");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("cannot write 'f2/shot.bmp': No such file or directory; frames 0..1 "
                         "are there (1 written, 1 kept)\n"),
              std::string::npos)
        << r.err;
    r = run("scene.jts --frames 3 --skip-existing -o 'f%d/shot.bmp'");
    EXPECT_NE(r.err.find("; frames 0..1 were kept, already there\n"), std::string::npos) << r.err;
}

// A folder on a read-only file system (a render share mounted ro) was said to
// need to be writable, sending the user to chmod a folder that is not at
// fault: the file system is.
TEST_F(Cli, AReadOnlyFileSystemIsNotBlamedOnTheFolder) {
    fs::create_directory(dir / "ro");
    // A mount namespace of its own: the read-only mount ends with the shell.
    const std::string mount = "unshare -rm sh -c 'mount -t tmpfs -o ro none ro && ";
    if (run_shell(mount + "true'").code != 0)
        GTEST_SKIP() << "cannot mount a file system in a namespace of its own here";
    test::ProgramRun r = run_shell(mount + "\"$0\" scene.jts -o ro/out.bmp' '" JT_CLI "'");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(r.err,
              "jtracer-cli: cannot write 'ro/out.bmp': Read-only file system; nothing was "
              "rendered\n");
}

// A sequence's -o without --frames writes one image under that very name:
// said, since the field shows a sequence was meant.
TEST_F(Cli, AFrameNumberFieldWithoutFramesWarns) {
    test::ProgramRun r = run("scene.jts -o 'shot-%04d.png'");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("jtracer-cli: warning: -o/--output 'shot-%04d.png' has a frame number "
                         "field, but without --frames N one image is written under that very "
                         "name"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(outputs(), std::vector<std::string>{"shot-%04d.png"});
    r = run("scene.jts -o 'full-100%.png'");
    EXPECT_EQ(r.err.find("frame number field"), std::string::npos) << r.err;
}

TEST_F(Cli, CheckValidatesAndWritesNothing) {
    test::ProgramRun r = run("--check scene.jts");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(outputs().empty());
    write("bad.jts", "scene { sphere { radius 2; } }\n");
    r = run("--check bad.jts");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("bad.jts:1:"), std::string::npos) << r.err;
    EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, SceneErrorsExitOneAndWriteNothing) {
    write("syntax.jts", "render_settings { width: 10; height: 10 }\n");
    test::ProgramRun r = run("syntax.jts");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("syntax.jts:1:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("error:"), std::string::npos) << r.err;

    std::string no_size = small_scene;
    no_size.replace(no_size.find("width: 32; height: 18;"), 22, "");
    write("nosize.jts", no_size);
    r = run("nosize.jts -o out.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    // The check says how to set it; the command line adds its own way.
    EXPECT_NE(r.err.find("the image width is 0: set 'width' in render_settings or pass --width"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(outputs().empty());
    // --width/--height fill in what the scene left out.
    EXPECT_EQ(run("-q nosize.jts -o out.bmp --width 8 --height 6").code, 0);
}

TEST_F(Cli, ALensWithOneSampleWarnsUnlessSamplesArePassed) {
    std::string lens = small_scene;
    lens.replace(lens.find("aspect: 1.7778; }"), 17, "aspect: 1.7778; aperture: 0.1; }");
    write("lens.jts", lens);
    test::ProgramRun r = run("--progress none lens.jts -o out.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("lens.jts:4:110: warning:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("warning: camera \"front\": 'aperture' 0.1 blurs nothing "
                         "while 'samples' is 1"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("set 'samples' to 16 or more or pass --samples"), std::string::npos)
        << r.err;
    // --samples 1 is what the warning is about: it does not suggest the flag.
    r = run("--progress none lens.jts -o out.bmp --samples 1");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("set 'samples' to 16 or more"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("pass --samples"), std::string::npos) << r.err;
    r = run("--progress none lens.jts -o out.bmp --samples 4");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("aperture"), std::string::npos) << r.err;
}

TEST_F(Cli, UsageErrorsExitTwo) {
    EXPECT_EQ(run("").code, 2);
    EXPECT_EQ(run("scene.jts --width 0").code, 2);
    EXPECT_EQ(run("scene.jts --samples 2000").code, 2);
    EXPECT_EQ(run("scene.jts --frobnicate").code, 2);
    test::ProgramRun r = run("scene.jts --threads lots");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--help"), std::string::npos) << r.err;
    EXPECT_TRUE(outputs().empty());
}

// A size too large for a BMP asked for on the command line is the command
// line's error: located in the file it pointed at the `height: 18` the flags
// replaced, and spoke of a BMP when the output was a PNG.
TEST_F(Cli, ASizeTooLargeFromTheFlagsIsAUsageError) {
    test::ProgramRun r = run("scene.jts --width 40000 --height 40000 -o huge.png");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("jtracer-cli: --width/--height: a 40000 x 40000 image does not fit in a "
                         "BMP file (4 GiB at most), the largest image JTracer renders whatever "
                         "the output format"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("scene.jts:"), std::string::npos) << r.err;
    r = run("scene.jts --width 65535 --check");
    EXPECT_EQ(r.code, 0) << "65535 x 18 fits: " << r.err;
    write("tall.jts", small_scene.substr(0, small_scene.find("height: 18;")) + "height: 65535;" +
                          small_scene.substr(small_scene.find("height: 18;") + 11));
    r = run("tall.jts --width 65535 --check");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--width: a 65535 x 65535 image"), std::string::npos) << r.err;
    write("huge.jts", small_scene.substr(0, small_scene.find("width: 32;")) + "width: 65535;" +
                          small_scene.substr(small_scene.find("width: 32;") + 10));
    r = run("huge.jts --height 65535 --width 65535");
    EXPECT_EQ(r.code, 2) << r.err;
    // The scene's own size stays the scene's error, at its line.
    r = run("tall.jts --check");
    EXPECT_EQ(r.code, 0) << "32 x 65535 fits: " << r.err;
    r = run("huge.jts --height 65535");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(outputs().empty());
}

// An empty file name (a script's unset variable: -o "$OUT") is the command
// line's error, found before rendering; it was a write error after it, and
// --junit '' said "cannot write an image".
TEST_F(Cli, EmptyFileNamesAreUsageErrors) {
    write("ref.bmp", "");
    for (const std::string args :
         {"scene.jts -o ''", "scene.jts --expect ''",
          "scene.jts -o a.png --expect ref.bmp --junit ''", "diff ref.bmp ref.bmp -o ''",
          "diff ref.bmp ref.bmp --junit ''"}) {
        test::ProgramRun r = run(args);
        EXPECT_EQ(r.code, 2) << args << ": " << r.err;
        EXPECT_NE(r.err.find(": needs a file name, not an empty string"), std::string::npos)
            << args << ": " << r.err;
    }
    EXPECT_EQ(outputs(), std::vector<std::string>{"ref.bmp"});
}

TEST_F(Cli, IoErrorsExitThreeAndWriteNothing) {
    test::ProgramRun r = run("missing.jts");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("missing.jts"), std::string::npos) << r.err;
    r = run("scene.jts -o no/such/dir/out.bmp");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("no/such/dir/out.bmp"), std::string::npos) << r.err;
    EXPECT_TRUE(outputs().empty());
}

// A named pipe as the scene is read once something writes it; a read that
// waits says what for, rather than looking hung. A writer that is there at
// once goes unremarked.
TEST_F(Cli, ASceneFromAPipeThatWaitsSaysWhatFor) {
    ASSERT_EQ(run_shell("mkfifo pipe.jts").code, 0);
    test::ProgramRun r =
        run_shell("(sleep 2; cat scene.jts > pipe.jts) & '" JT_CLI "' -q pipe.jts -o out.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("jtracer-cli: waiting for the scene from the pipe 'pipe.jts': it is "
                         "read once something writes it and closes it"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(exists("out.bmp"));
    r = run_shell("cat scene.jts | '" JT_CLI "' -q /dev/stdin -o piped.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(test::read_file(dir / "piped.bmp"), test::read_file(dir / "out.bmp"));
}

// Symbolic links that loop are named, link by link, wherever the loop is: the
// scene, a folder on its path, the output, an image map.
TEST_F(Cli, ACycleOfSymbolicLinksIsNamedLinkByLink) {
    fs::create_symlink("b.jts", dir / "a.jts");
    fs::create_symlink("a.jts", dir / "b.jts");
    test::ProgramRun r = run("a.jts -o out.bmp");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("cannot read 'a.jts': a cycle of symbolic links: 'a.jts' -> 'b.jts' -> "
                         "'a.jts'"),
              std::string::npos)
        << r.err;
    fs::create_symlink("up", dir / "down");
    fs::create_symlink("down", dir / "up");
    r = run("up/scene.jts -o out.bmp");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("a cycle of symbolic links: 'up' -> 'down' -> 'up'"), std::string::npos)
        << r.err;
    fs::create_symlink("twin.bmp", dir / "out.bmp");
    fs::create_symlink("out.bmp", dir / "twin.bmp");
    r = run("scene.jts -o out.bmp");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("cannot write 'out.bmp': a cycle of symbolic links: 'out.bmp' -> "
                         "'twin.bmp' -> 'out.bmp'"),
              std::string::npos)
        << r.err;
    write("mapped.jts", R"(
render_settings { width: 8; height: 8; }
scene { sphere { center: <0, 0, 0>; radius: 1; material { image_map: "twin.bmp"; } } }
)");
    r = run("mapped.jts -o mapped.bmp");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("'twin.bmp' -> 'out.bmp' -> 'twin.bmp'"), std::string::npos) << r.err;
}

// A picture named by the scene that is a device is an error at its string,
// not a read that never ends.
TEST_F(Cli, DeviceAsImageMapOrSkyIsAnErrorAtItsString) {
    write("device.jts", R"(render_settings { width: 8; height: 8; background_map: "/dev/zero"; }
cameras { perspective_camera { position: <0, 0, 5>; } }
scene { sphere { material { image_map: "/dev/urandom"; } } }
)");
    test::ProgramRun r =
        run_shell(std::string(test::memory_cap) + "timeout 60 '" JT_CLI "' device.jts");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("device.jts:1:56: error: background_map: cannot read '/dev/zero': it is "
                         "a device, not a file"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("device.jts:3:40: error: image_map: cannot read '/dev/urandom'"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, ExistingOutputSurvivesAFailedRender) {
    write("keep.bmp", "precious");
    write("bad.jts", "scene { sphere { radius: -1; } }\n");
    EXPECT_EQ(run("bad.jts -o keep.bmp").code, 1);
    std::ifstream in(dir / "keep.bmp");
    std::string text;
    in >> text;
    EXPECT_EQ(text, "precious");
}

// A script's or CI's log gets no progress unless it asks; a terminal gets the bar.
TEST_F(Cli, ProgressShowsOnATerminalOnlyUnlessAsked) {
    const std::string render = "scene.jts --width 640 --height 360 --samples 4 ";
    test::ProgramRun r = run(render);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("ETA"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("rendering:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Mrays/s"), std::string::npos) << "the summary still shows: " << r.err;

    r = run(render + "--progress bar");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("ETA"), std::string::npos) << r.err;
    r = run(render + "--progress bar -q");
    EXPECT_EQ(r.err, "");
    r = run(render + "--progress sometimes");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--progress"), std::string::npos) << r.err;

    // script(1) gives the program a terminal as its stderr.
    if (run_shell("command -v script").code != 0) GTEST_SKIP() << "no script(1) here";
    r = run_shell("script -qec \"'" JT_CLI "' " + render + "\" /dev/null");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("ETA"), std::string::npos) << r.out;
}

TEST_F(Cli, HelpAndVersion) {
    test::ProgramRun r = run("--help");
    EXPECT_EQ(r.code, 0);
    std::string help = r.out + r.err;
    EXPECT_NE(help.find("Example"), std::string::npos) << help;
    EXPECT_NE(help.find("--samples"), std::string::npos) << help;
    r = run("--version");
    EXPECT_EQ(r.code, 0);
    // The project version from CMake, then the git revision when built from git.
    EXPECT_EQ(r.out, "jtracer-cli " + std::string(jt::version_string()) + "\n");
    EXPECT_EQ(std::string(jt::version_string()).rfind(JT_VERSION_STRING, 0), 0u);
}

// CLI11's range check said "Value 2.5 not in range 1 to 1000000" of a number
// that is in range but not whole, and an unknown option was reported as a
// missing one.
TEST_F(Cli, UsageErrorsNameTheOptionAndWhatItExpects) {
    test::ProgramRun r = run("scene.jts --frames 2.5");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err,
              "jtracer-cli: --frames: '2.5' is not a whole number (expected 1 to 1000000)\n"
              "Run 'jtracer-cli --help' for the options.\n");
    r = run("scene.jts --width abc");
    EXPECT_NE(r.err.find("--width: 'abc' is not a whole number (expected 1 to 65535)"),
              std::string::npos)
        << r.err;
    r = run("scene.jts --width 0");
    EXPECT_NE(r.err.find("--width: 0 is out of range (expected 1 to 65535)"), std::string::npos)
        << r.err;
    r = run("--bogus");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("jtracer-cli: unknown option '--bogus'\n"), std::string::npos) << r.err;
    EXPECT_TRUE(outputs().empty());
}

// `jtracer-cli /dev/stdin < fifo`: reopening /dev/stdin opened the named pipe
// anew, which waits for a writer though the one that filled it had gone.
TEST_F(Cli, ASceneOnStandardInputFromANamedPipeIsRead) {
    ASSERT_EQ(run_shell("mkfifo p").code, 0);
    test::ProgramRun r = run_shell("timeout 30 '" JT_CLI
                                   "' /dev/stdin -q -o out.bmp < p & "
                                   "cat scene.jts > p; wait $!; echo \"code $?\"");
    EXPECT_NE(r.out.find("code 0"), std::string::npos) << r.out << r.err;
    EXPECT_TRUE(fs::exists(dir / "out.bmp"));
}

}  // namespace
}  // namespace jt
