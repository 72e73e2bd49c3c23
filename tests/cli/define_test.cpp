// jtracer-cli --define and --clock (docs/language.md §15.2, §15.4).

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/bmp.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace jt {
namespace {

namespace fs = std::filesystem;

// A sphere whose radius is r + clock, in a frame that shows its size.
const std::string sized_scene = R"(
define r = 0.5;
define name = "from_scene.bmp";
cameras { perspective_camera { position: <0, 0, 6>; look_at: <0, 0, 0>; } }
scene {
    sphere { radius: r + clock; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } }
}
render_settings { width: 24; height: 24; filename: name; ambient_light: <1, 1, 1>; }
)";

class CliDefine : public test::ScratchTest {
  protected:
    void SetUp() override { test::write_file(dir / "scene.jts", sized_scene); }

    test::ProgramRun run(const std::string& args) { return run_shell("'" JT_CLI "' " + args); }

    // The lit pixels of an image the test wrote.
    int lit(const std::string& name) {
        const Expected<Image8> image = read_bmp(dir / name);
        EXPECT_TRUE(image) << name;
        if (!image) return -1;
        return static_cast<int>(
            std::count_if(image->rgb.begin(), image->rgb.end(), [](auto v) { return v != 0; }));
    }

    std::string bytes(const std::string& name) { return test::read_file(dir / name); }
};

TEST_F(CliDefine, DefineOverridesTheFilesValueWithANote) {
    test::ProgramRun small = run("scene.jts -o small.bmp");
    ASSERT_EQ(small.code, 0) << small.err;
    test::ProgramRun big = run("scene.jts -o big.bmp --define r=1.5");
    ASSERT_EQ(big.code, 0) << big.err;
    EXPECT_NE(big.err.find("scene.jts:2:8: note: 'r' is set by --define; this definition is "
                           "ignored"),
              std::string::npos)
        << big.err;
    EXPECT_GT(lit("big.bmp"), lit("small.bmp"));
    // The same value written in the file gives the same bytes.
    std::string text = sized_scene;
    text.replace(text.find("r = 0.5"), 7, "r = 1.5");
    test::write_file(dir / "edited.jts", text);
    ASSERT_EQ(run("-q edited.jts -o edited.bmp").code, 0);
    EXPECT_EQ(bytes("big.bmp"), bytes("edited.bmp"));
}

TEST_F(CliDefine, StringsKeepTheirQuotesAndTheLaterDefineWins) {
    test::ProgramRun r = run("scene.jts --define 'name=\"a.bmp\"' --define 'name=\"b.bmp\"'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "b.bmp"));
    EXPECT_FALSE(fs::exists(dir / "a.bmp"));
    EXPECT_FALSE(fs::exists(dir / "from_scene.bmp"));
    EXPECT_NE(r.err.find("warning: --define name is given more than once"), std::string::npos)
        << r.err;
}

TEST_F(CliDefine, ClockAndExpressionsOfIt) {
    ASSERT_EQ(run("-q scene.jts -o zero.bmp").code, 0);
    ASSERT_EQ(run("-q scene.jts -o one.bmp --clock 1").code, 0);
    ASSERT_EQ(run("-q scene.jts -o half.bmp --clock 0.5 --define 'r=0.5 + clock'").code, 0);
    EXPECT_GT(lit("one.bmp"), lit("zero.bmp"));
    EXPECT_EQ(bytes("one.bmp"), bytes("half.bmp"));  // 0.5 + 0.5 + 0.5 = 1.5 both ways
}

TEST_F(CliDefine, BadDefinesAndClocksExitTwoNamingTheOption) {
    for (const char* args :
         {"--define r", "--define 2r=1", "--define clock=1", "--define pi=3", "--define r=1/0",
          "--define r=q", "--define 'r=<1,2>'", "--clock nan", "--clock x", "--clock inf"}) {
        test::ProgramRun r = run(std::string("scene.jts ") + args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        const std::string option = std::string(args).substr(0, std::string(args).find(' '));
        EXPECT_NE(r.err.find(option), std::string::npos) << args << "\n" << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "from_scene.bmp"));
}

// A value of the clock that fails at every clock the command renders is a
// bad value, as one that fails at any clock (exit 2, nothing written); one
// that fails at some frames only is an error of those frames (exit 1, with
// the frame's note, the frames before written).
TEST_F(CliDefine, AClockValueFailingAtEveryClockRenderedExitsTwo) {
    for (const char* args :
         {"--define r=1/clock", "--clock 0.5 --define 'r=1/(clock - clock)'",
          "--check --define r=1/clock", "--frames 1 -o 'a%d.bmp' --define r=1/clock",
          "info --define r=1/clock", "--frames 3 -o 'a%d.bmp' --define 'r=sqrt(-1 - clock)'",
          "--frames 3 --frame-range 1..2 -o 'a%d.bmp' --define 'r=asin(2 + clock)'"}) {
        const bool info = std::string_view(args).starts_with("info ");
        test::ProgramRun r = run(info ? std::string("info scene.jts ") + (args + 5)
                                      : std::string("scene.jts ") + args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("--define: the value of r: at column "), std::string::npos)
            << args << "\n"
            << r.err;
        EXPECT_EQ(r.err.find("note: at frame"), std::string::npos) << args << "\n" << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "from_scene.bmp"));
    EXPECT_FALSE(fs::exists(dir / "a0.bmp"));
    EXPECT_FALSE(fs::exists(dir / "a1.bmp"));

    test::ProgramRun some =
        run("scene.jts --frames 3 -o 'b%d.bmp' --define 'r=abs(1/(clock - 0.5))'");
    EXPECT_EQ(some.code, 1) << some.err;
    EXPECT_NE(some.err.find("division by zero"), std::string::npos) << some.err;
    EXPECT_NE(some.err.find("note: at frame 1 (clock = 0.5)"), std::string::npos) << some.err;
    EXPECT_TRUE(fs::exists(dir / "b0.bmp"));
    EXPECT_FALSE(fs::exists(dir / "b1.bmp"));
    // A range that holds only the failing frame is a part of that sequence:
    // its error is the frame's, as the whole sequence would report it.
    test::ProgramRun part = run(
        "scene.jts --frames 3 --frame-range 1..1 -o 'c%d.bmp' --define 'r=abs(1/(clock - 0.5))'");
    EXPECT_EQ(part.code, 1) << part.err;
    EXPECT_NE(part.err.find("note: at frame 1 (clock = 0.5)"), std::string::npos) << part.err;
    EXPECT_EQ(run("-q scene.jts -o d.bmp --clock 2 --define r=1/clock").code, 0);
}

TEST_F(CliDefine, ANameTheSceneNeverDefinesIsAWarning) {
    test::ProgramRun r = run("scene.jts --define other=1");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: --define other: the scene defines no 'other'"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace jt
