// Bad input as a new user would type it: every class of malformed scene, every
// file that cannot be read or written, sizes that cannot be allocated. Each
// must give a clear message and the documented exit code, leave an existing
// output byte-identical and leave no temporary file behind.

#include "cli_sandbox.hpp"

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <fstream>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

const std::string camera =
    "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n";

struct MalformedScene {
    const char* what;
    std::string text;
    std::string location;  // the LINE:COL the first error must point at
};

std::vector<MalformedScene> malformed_scenes() {
    return {
        {"lexical: unclosed string", "render_settings { filename: \"abc; }\n", "1:29"},
        {"lexical: malformed number", "render_settings { width: 1.2.3; }\n", "1:26"},
        {"lexical: stray character", "render_settings { width: 10; @ }\n", "1:30"},
        {"lexical: NUL byte", std::string("render_settings { width: 10;\0 }\n", 32), "1:29"},
        {"syntax: missing ';'", "render_settings {\n  width: 10\n}\n", "2:12"},
        {"syntax: unclosed block", "render_settings { width: 10;\n", "1:1"},
        {"syntax: unknown block", "rendr_settings { }\n", "1:1"},
        {"syntax: stray '}'", camera + "}\n", "2:1"},
        {"kinds: string for a number", "render_settings { width: \"big\"; }\n", "1:26"},
        {"kinds: vector for a number", "render_settings { width: <1, 2, 3>; }\n", "1:26"},
        {"kinds: number for a vector", camera + "scene { sphere { center: 4; radius: 1; } }\n",
         "2:26"},
        {"ranges: negative width", "render_settings { width: -1; }\n", "1:26"},
        {"ranges: negative radius", camera + "scene { sphere { radius: -1; } }\n", "2:26"},
        {"ranges: 1e400", "render_settings { width: 1e400; }\n", "1:26"},
        {"ranges: nan spelled out", camera + "scene { sphere { radius: nan; } }\n", "2:26"},
        {"ranges: inf spelled out", camera + "scene { sphere { radius: inf; } }\n", "2:26"},
        {"ranges: negative light radius", camera + "scene { point_light { radius: -1; } }\n",
         "2:31"},
        {"ranges: no shadow samples", camera + "scene { point_light { shadow_samples: 0; } }\n",
         "2:39"},
        {"ranges: too many shadow samples",
         camera + "scene { point_light { radius: 1; shadow_samples: 1025; } }\n", "2:50"},
        {"ranges: negative aperture",
         "cameras { perspective_camera { look_at: <0, 0, -1>; aperture: -1; } }\n", "1:63"},
        {"ranges: focus distance 0",
         "cameras { perspective_camera { look_at: <0, 0, -1>; focus_distance: 0; } }\n", "1:69"},
        {"ranges: smooth_angle -1",
         camera + "scene { mesh { smooth_angle: -1; file: \"m.obj\"; } }\n", "2:30"},
        {"ranges: smooth_angle 181",
         camera + "scene { mesh { smooth_angle: 181; file: \"m.obj\"; } }\n", "2:30"},
        {"kinds: string for smooth_angle",
         camera + "scene { mesh { smooth_angle: \"x\"; file: \"m.obj\"; } }\n", "2:30"},
        {"validation: look_at equals position",
         "render_settings { width: 8; height: 8; }\n"
         "cameras { perspective_camera { position: <1, 2, 3>; look_at: <1, 2, 3>; } }\n",
         "2:62"},
        {"validation: width 0", "render_settings { width: 0; height: 8; }\n" + camera, "1:26"},
        // Language 1.3 (docs/language.md §15).
        {"names: unknown name", camera + "scene { sphere { radius: r; } }\n", "2:26"},
        {"names: used before its definition",
         camera + "scene { sphere { radius: r; } }\ndefine r = 1;\n", "2:26"},
        {"names: defined twice", "define r = 1;\ndefine r = 2;\n" + camera, "2:8"},
        {"names: reserved", "define pi = 3;\n" + camera, "1:8"},
        {"names: define inside a block", camera + "scene { define r = 1; }\n", "2:9"},
        {"names: missing '='", "define r 1;\n" + camera, "1:10"},
        {"names: material as a value",
         "material m { }\n" + camera + "scene { sphere { radius: m; } }\n", "3:26"},
        {"names: value as a material",
         "define r = 1;\n" + camera + "scene { sphere { material: r; } }\n", "3:28"},
        {"names: two named materials",
         "material m { }\n" + camera + "scene { sphere { material: m; material: m; } }\n", "3:31"},
        {"names: named material inside a primitive",
         camera + "scene { sphere { material m { } } }\n", "2:18"},
        {"include: missing file", "include \"other.jts\";\n" + camera, "1:9"},
        {"include: a cycle", camera + "include \"bad.jts\";\n", "2:9"},
        {"expressions: division by zero", camera + "scene { sphere { radius: 1 / (1 - 1); } }\n",
         "2:28"},
        {"expressions: sqrt of a negative", camera + "scene { sphere { radius: sqrt(-4); } }\n",
         "2:26"},
        {"expressions: vector times vector",
         camera + "scene { sphere { center: <1, 0, 0> * <1, 0, 0>; } }\n", "2:36"},
        {"expressions: wrong arguments", camera + "scene { sphere { radius: pow(2); } }\n", "2:26"},
        {"expressions: not finite", camera + "scene { sphere { radius: 1e300 * 1e300; } }\n",
         "2:32"},
        {"expressions: unclosed parenthesis", camera + "scene { sphere { radius: (1 + 2; } }\n",
         "2:32"},
        {"expressions: too deep",
         camera + "scene { sphere { radius: " + std::string(300, '(') + "1" +
             std::string(300, ')') + "; } }\n",
         "2:282"},
        {"expressions: string in arithmetic",
         "render_settings { filename: \"a\" + \"b\"; }\n" + camera, "1:29"},
        {"validation: image over 4 GiB",
         "render_settings { width: 65535; height: 65535; }\n" + camera, "1:"},
    };
}

// True when some line of `err` reads "FILE:LINE:COL: error: MESSAGE".
// (Checked by hand: GCC 12 warns falsely inside <regex> under the sanitizers.)
bool has_located_error(const std::string& err, const std::string& file) {
    auto digits = [&](std::size_t& at) {
        const std::size_t start = at;
        while (at < err.size() && std::isdigit(static_cast<unsigned char>(err[at]))) ++at;
        return at > start;
    };
    for (std::size_t at = err.find(file + ":"); at != std::string::npos;
         at = err.find(file + ":", at + 1)) {
        std::size_t i = at + file.size() + 1;
        if (digits(i) && err[i] == ':' && digits(++i) && err.compare(i, 9, ": error: ") == 0 &&
            i + 9 < err.size() && err[i + 9] != '\n')
            return true;
    }
    return false;
}

using BadInput = CliSandbox;

TEST_F(BadInput, EveryClassOfMalformedSceneIsLocatedAndExitsOne) {
    const std::string precious = "precious bytes\n";
    for (const MalformedScene& scene : malformed_scenes()) {
        SCOPED_TRACE(scene.what);
        write_file(dir / "bad.jts", scene.text);
        write_file(dir / "keep.bmp", precious);
        ProgramRun r = run({"bad.jts", "-o", "keep.bmp"});
        EXPECT_EQ(r.code, 1) << r.err;
        EXPECT_EQ(r.err.find("bad.jts:"), 0u) << r.err;
        EXPECT_NE(r.err.find("bad.jts:" + scene.location), std::string::npos) << r.err;
        EXPECT_TRUE(has_located_error(r.err, "bad.jts")) << r.err;
        EXPECT_EQ(read_file(dir / "keep.bmp"), precious);
        EXPECT_TRUE(temporary_files().empty());
    }
}

TEST_F(BadInput, SceneWithoutCameraIsAnErrorAboutTheWholeFile) {
    write_file(dir / "bad.jts", "render_settings { width: 8; height: 8; }\n");
    ProgramRun r = run({"bad.jts", "-o", "out.bmp"});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("bad.jts: error: every render needs a camera"), std::string::npos)
        << r.err;
    EXPECT_FALSE(has_located_error(r.err, "bad.jts")) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.bmp"));
}

// A mesh with materials "file" whose material library or texture cannot be
// used: an error at its `file` string (line 3, column 22) naming that file,
// exit 1, nothing written. The same model with "scene" renders.
TEST_F(BadInput, ModelMaterialFilesThatCannotBeUsedAreLocatedAtTheFileString) {
    const std::string precious = "precious bytes\n";
    const std::string triangle = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nusemtl x\nf 1 2 3\n";
    fs::create_directories(dir / "scene");
    write_file(dir / "outside.png", "\x89PNG\r\n\x1a\n");
    struct Case {
        const char* what;
        std::string mtllib, mtl;  // the OBJ's library line and the library's text
        std::string named;        // what the error must name
    };
    const std::vector<Case> cases = {
        {"missing library", "mtllib none.mtl", "", "none.mtl' cannot be read (no such file)"},
        {"library outside", "mtllib ../secret.mtl", "", "outside the folder"},
        {"library is a folder", "mtllib lib.mtl", "", "lib.mtl', which is a folder"},
        {"missing texture", "mtllib m.mtl", "newmtl x\nmap_Kd -clamp on gone.png\n",
         "its texture 'gone.png': cannot read"},
        {"texture outside", "mtllib m.mtl", "newmtl x\nmap_Kd ../outside.png\n",
         "its texture '../outside.png' lies outside the folder"},
        {"texture not a picture", "mtllib m.mtl", "newmtl x\nmap_Kd m.obj\n",
         "its texture 'm.obj': '"},
        {"texture truncated", "mtllib m.mtl", "newmtl x\nmap_Kd cut.png\n",
         "its texture 'cut.png': '"},
        {"Kd of four numbers", "mtllib m.mtl", "newmtl x\nKd 1 0 0 0\n",
         "has a Kd that is not one"},
        {"Kd infinite", "mtllib m.mtl", "newmtl x\nKd 1e999\n", "has a Kd that is not one"},
    };
    write_file(dir / "secret.mtl", "newmtl x\nKd 1 0 0\n");
    fs::create_directories(dir / "scene/lib.mtl");
    write_file(dir / "scene/cut.png", "\x89PNG\r\n\x1a\n\0\0\0\rIHDR");
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        write_file(dir / "scene/m.obj", c.mtllib + "\n" + triangle);
        write_file(dir / "scene/m.mtl", c.mtl);
        for (const char* materials : {"file", "scene"}) {
            write_file(dir / "scene/bad.jts", camera +
                                                  "render_settings { width: 4; height: 4; }\n"
                                                  "scene { mesh { file: \"m.obj\"; materials: \"" +
                                                  materials + "\"; } }\n");
            write_file(dir / "keep.bmp", precious);
            ProgramRun r = run({"scene/bad.jts", "-o", "keep.bmp"});
            if (std::string(materials) == "scene") {
                EXPECT_EQ(r.code, 0) << r.err;
                continue;
            }
            EXPECT_EQ(r.code, 1) << r.err;
            EXPECT_EQ(r.err.find("scene/bad.jts:3:22: error: "), 0u) << r.err;
            EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
            EXPECT_EQ(read_file(dir / "keep.bmp"), precious);
            EXPECT_TRUE(temporary_files().empty());
        }
    }
}

// Root reads and writes through any permission bits, so as root the CLI runs
// as 'nobody' for these (run_unprivileged); the test is skipped only when even
// that cannot be arranged.
bool unprivileged_possible() {
    return ::getuid() != 0 || ::getpwnam("nobody") != nullptr;
}

class UnusableFiles : public CliSandbox {
  protected:
    const std::string precious = "precious bytes\n";
    void SetUp() override {
        CliSandbox::SetUp();
        write_file(dir / "keep.bmp", precious);
    }
    // Runs, expects exit 3 with a message naming `named`, and nothing changed.
    void expect_io_error(const std::vector<std::string>& args, const std::string& named,
                         const std::string& reason, bool unprivileged = false) {
        const std::vector<std::string> before = files();
        ProgramRun r = unprivileged ? run_unprivileged(args) : run(args);
        EXPECT_EQ(r.code, 3) << r.err;
        EXPECT_EQ(r.err.rfind("jtracer-cli: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("'" + named + "'"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected: " << r.err;
        EXPECT_EQ(read_file(dir / "keep.bmp"), precious);
        EXPECT_EQ(files(), before);
        EXPECT_TRUE(temporary_files().empty());
    }
};

TEST_F(UnusableFiles, MissingSceneFile) {
    expect_io_error({"missing.jts", "-o", "keep.bmp"}, "missing.jts", "no such file");
}

TEST_F(UnusableFiles, DirectoryAsScene) {
    fs::create_directory(dir / "scenes");
    expect_io_error({"scenes", "-o", "keep.bmp"}, "scenes", "is a directory");
}

TEST_F(UnusableFiles, UnreadableScene) {
    fs::copy_file(dir / "scene.jts", dir / "locked.jts");
    fs::permissions(dir / "locked.jts", fs::perms::none);
    if (!unprivileged_possible()) GTEST_SKIP() << "root, and no user 'nobody' to run as";
    expect_io_error({"locked.jts", "-o", "keep.bmp"}, "locked.jts", "ermission denied", true);
}

TEST_F(UnusableFiles, OutputInAMissingDirectory) {
    expect_io_error({"scene.jts", "-o", "no/such/dir/out.bmp"}, "no/such/dir/out.bmp",
                    "No such file or directory");
}

TEST_F(UnusableFiles, OutputIsADirectory) {
    fs::create_directory(dir / "images");
    expect_io_error({"scene.jts", "-o", "images"}, "images", "is a directory");
    EXPECT_TRUE(fs::is_empty(dir / "images"));
}

TEST_F(UnusableFiles, OutputInAnUnwritableDirectory) {
    fs::create_directory(dir / "locked");
    fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec |
                                        fs::perms::others_read | fs::perms::others_exec);
    if (!unprivileged_possible()) GTEST_SKIP() << "root, and no user 'nobody' to run as";
    expect_io_error({"scene.jts", "-o", "locked/out.bmp"}, "locked/out.bmp", "ermission denied",
                    true);
    EXPECT_TRUE(fs::is_empty(dir / "locked"));
}

TEST_F(UnusableFiles, FullDevice) {
    struct stat before {};
    if (::stat("/dev/full", &before) != 0 || !S_ISCHR(before.st_mode))
        GTEST_SKIP() << "/dev/full is not a character device here";
    expect_io_error({"scene.jts", "-o", "/dev/full"}, "/dev/full", "No space left on device");
    // Writing in place, never renaming over the device (which root could do).
    struct stat after {};
    ASSERT_EQ(::stat("/dev/full", &after), 0);
    EXPECT_TRUE(S_ISCHR(after.st_mode));
    EXPECT_EQ(after.st_rdev, before.st_rdev);
}

using HugeImages = CliSandbox;

TEST_F(HugeImages, SizesOutOfRangeOnTheCommandLineAreUsageErrors) {
    for (std::vector<std::string> args :
         {std::vector<std::string>{"--width", "2000000000", "--height", "2000000000"},
          {"--width", "99999999999999999999"},
          {"--height", "-3"}}) {
        args.insert(args.begin(), "scene.jts");
        ProgramRun r = run(args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_NE(r.err.find(" is out of range (expected 1 to "), std::string::npos) << r.err;
        EXPECT_EQ(files(), std::vector<std::string>{"scene.jts"});
    }
}

// Asked for by the flags, it is their error (exit 2), not one located at the
// scene's own width or height, which they replaced.
TEST_F(HugeImages, ImageBeyondTheBmpLimitIsAUsageError) {
    ProgramRun r = run({"scene.jts", "--width", "65535", "--height", "65535", "-o", "big.png"});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--width/--height: a 65535 x 65535 image does not fit"), std::string::npos)
        << r.err;
    EXPECT_EQ(files(), std::vector<std::string>{"scene.jts"});
}

std::uint64_t memory_available() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key, unit;
    std::uint64_t kib = 0;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024;
    return 0;
}

TEST_F(HugeImages, ImageTooLargeForMemoryIsRefusedBeforeRendering) {
    // 65535 x 21000 pixels with running sums: over 40 GiB.
    const std::uint64_t needed = 65535ull * 21000 * 33;
    if (memory_available() == 0 || memory_available() > needed)
        GTEST_SKIP() << "this machine could hold the image; the test would render it";
    ProgramRun r = run({"scene.jts", "--width", "65535", "--height", "21000", "--samples", "1024",
                        "-o", "big.bmp"});
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("needs about"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
    EXPECT_EQ(files(), std::vector<std::string>{"scene.jts"});

    // A small region of that frame, written alone, needs little memory and renders.
    r = run({"scene.jts", "--width", "65535", "--height", "21000", "--samples", "4", "--region",
             "0,0,16,16", "--region-output", "-o", "part.bmp", "-q"});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "part.bmp"));
}

}  // namespace
}  // namespace jt::test
