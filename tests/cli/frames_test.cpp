// jtracer-cli --frames and --frame-range (docs/language.md §15.4).

#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace jt {
namespace {

namespace fs = std::filesystem;

// A sphere whose radius grows with clock; `name` is the scene's filename.
const std::string growing_scene = R"(
define name = "seq.bmp";
cameras { perspective_camera { position: <0, 0, 6>; look_at: <0, 0, 0>; } }
scene {
    sphere { radius: 0.5 + clock; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } }
}
render_settings { width: 24; height: 24; filename: name; ambient_light: <1, 1, 1>; }
)";

class CliFrames : public test::ScratchTest {
  protected:
    void SetUp() override { test::write_file(dir / "scene.jts", growing_scene); }

    test::ProgramRun run(const std::string& args) { return run_shell("'" JT_CLI "' " + args); }

    std::string bytes(const std::string& name) { return test::read_file(dir / name); }

    static int count(const std::string& text, const std::string& what) {
        int n = 0;
        for (std::size_t at = text.find(what); at != std::string::npos;
             at = text.find(what, at + 1))
            ++n;
        return n;
    }
};

// Frame f of N has clock f / (N - 1), written back as the shortest decimal.
TEST_F(CliFrames, EveryFrameEqualsItsClockRenderedAlone) {
    test::ProgramRun r = run("scene.jts --frames 4 -o 'shot-%04d.png'");
    ASSERT_EQ(r.code, 0) << r.err;
    const char* clocks[] = {"0", "0.3333333333333333", "0.6666666666666666", "1"};
    for (int f = 0; f < 4; ++f) {
        const std::string alone = "alone-" + std::to_string(f) + ".png";
        ASSERT_EQ(run(std::string("-q scene.jts --clock ") + clocks[f] + " -o " + alone).code, 0);
        const std::string frame = "shot-000" + std::to_string(f) + ".png";
        ASSERT_TRUE(fs::exists(dir / frame)) << frame;
        EXPECT_EQ(bytes(frame).substr(0, 4), "\x89PNG");
        EXPECT_EQ(bytes(frame), bytes(alone)) << frame;
    }
    EXPECT_NE(bytes("shot-0000.png"), bytes("shot-0003.png"));
    EXPECT_FALSE(fs::exists(dir / "shot-0004.png"));
    EXPECT_NE(r.err.find("(frame 1, clock 0.3333333333333333)"), std::string::npos) << r.err;
}

TEST_F(CliFrames, ADefineOfClockIsEvaluatedPerFrame) {
    ASSERT_EQ(run("-q scene.jts --frames 3 --define 'name=\"x.bmp\"' -o 'd%d.bmp'").code, 0);
    ASSERT_EQ(run("-q scene.jts --frames 3 -o 'e%d.bmp' --define 'name=clock'").code, 1);
    ASSERT_EQ(run("-q scene.jts --clock 0.5 -o half.bmp").code, 0);
    EXPECT_EQ(bytes("d1.bmp"), bytes("half.bmp"));
    EXPECT_FALSE(fs::exists(dir / "e0.bmp"));
}

// As for one image: frame 1 of `-o 'scene%d.jts'` would be written over
// scene1.jts, the scene being rendered, before any frame is.
TEST_F(CliFrames, AFrameThatIsTheSceneFileIsRefused) {
    test::write_file(dir / "scene1.jts", growing_scene);
    test::ProgramRun r = run("-q scene1.jts --frames 3 -o 'scene%d.jts'");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(bytes("scene1.jts"), growing_scene) << "the scene file was replaced by frame 1";
}

// -o - is standard output, which cannot hold a file a frame: the refusal
// speaks of it as the user wrote it, not of /dev/stdout, a name they never
// gave.
TEST_F(CliFrames, StandardOutputIsRefusedInTheUsersWords) {
    test::ProgramRun r = run("scene.jts --frames 3 -o -");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("-o/--output: - (standard output) takes one image"), std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("/dev/stdout"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
    // A name the user wrote is still quoted as written.
    r = run("scene.jts --frames 3 -o /dev/stdout");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("'/dev/stdout' has no frame number field"), std::string::npos) << r.err;
}

// A scene made by a script and given through a pipe (a named pipe, or bash's
// `<(m4 shot.jts.m4)`): its text can be read once only. The sequence read it again
// for every frame of a scene that reads clock, and frame 1 found it empty:
// "every render needs a camera", exit 1.
TEST_F(CliFrames, ASceneFromAPipeIsReadOnce) {
    ASSERT_EQ(run("-q scene.jts --frames 3 -o 'file-%d.png'").code, 0);
    ASSERT_EQ(run_shell("mkfifo pipe.jts").code, 0);
    test::ProgramRun r = run_shell("cat scene.jts > pipe.jts & timeout -k 5 60 '" JT_CLI
                                   "' --frames 3 -o 'pipe-%d.png' pipe.jts");
    ASSERT_EQ(r.code, 0) << r.err;
    for (int f = 0; f < 3; ++f) {
        const std::string n = std::to_string(f);
        EXPECT_EQ(bytes("pipe-" + n + ".png"), bytes("file-" + n + ".png")) << "frame " << f;
    }
    // --check reads every frame too.
    r = run_shell("cat scene.jts > pipe.jts & timeout -k 5 60 '" JT_CLI
                  "' --check --frames 3 pipe.jts");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("pipe.jts: no errors in frames 0..2"), std::string::npos) << r.err;
}

// A rerun after a lost node renders only the frames not already there and
// whole: a frame cut short (a copy interrupted, a disk that filled) or of
// another size is rendered again, and the output says which were kept.
TEST_F(CliFrames, SkipExistingRendersOnlyWhatIsMissingOrIncomplete) {
    ASSERT_EQ(run("-q scene.jts --frames 5 -o 'f%d.png'").code, 0);
    std::vector<std::string> first;
    for (int f = 0; f < 5; ++f) first.push_back(bytes("f" + std::to_string(f) + ".png"));
    fs::remove(dir / "f1.png");
    test::write_file(dir / "f2.png", first[2].substr(0, first[2].size() / 2));  // cut short
    std::string damaged = first[3];
    damaged[damaged.size() / 2] ^= 0x01;  // a flipped bit in the pixels
    test::write_file(dir / "f3.png", damaged);
    ASSERT_EQ(run("-q scene.jts --width 20 --clock 0 -o f4.png").code, 0);  // another size
    test::ProgramRun r = run("scene.jts --frames 5 -o 'f%d.png' --skip-existing");
    ASSERT_EQ(r.code, 0) << r.err;
    for (int f = 0; f < 5; ++f)
        EXPECT_EQ(bytes("f" + std::to_string(f) + ".png"), first[static_cast<std::size_t>(f)]) << f;
    EXPECT_NE(r.err.find("kept f0.png (frame 0): already there and complete"), std::string::npos)
        << r.err;
    EXPECT_EQ(count(r.err, "kept f"), 1) << r.err;
    EXPECT_NE(r.err.find("wrote f1.png (frame 1"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("f2.png is there, but it is cut short"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("f3.png is there, but it is damaged"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("f4.png is there, but it is 20x24, not 24x24"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("wrote 4 frames and kept 1 already there in "), std::string::npos)
        << r.err;

    // Every frame there: nothing rendered, and said so; -q says nothing.
    r = run("scene.jts --frames 5 -o 'f%d.png' --skip-existing");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "kept f"), 5) << r.err;
    EXPECT_NE(r.err.find("kept all 5 frames, already there"), std::string::npos) << r.err;
    r = run("-q scene.jts --frames 5 -o 'f%d.png' --skip-existing");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

// A kept frame is not even prepared: a rerun in a folder the frames are all
// in finds nothing to write, so a read-only folder is no error.
TEST_F(CliFrames, SkipExistingKeepsFramesInAReadOnlyFolder) {
    fs::create_directory(dir / "out");
    ASSERT_EQ(run("-q scene.jts --frames 2 -o 'out/f%d.bmp'").code, 0);
    fs::permissions(dir / "out",
                    fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                    fs::perm_options::remove);
    test::ProgramRun r = run("-q scene.jts --frames 2 -o 'out/f%d.bmp' --skip-existing");
    fs::permissions(dir / "out", fs::perms::owner_write, fs::perm_options::add);
    EXPECT_EQ(r.code, 0) << r.err;
}

// Where keeping an earlier file means nothing, --skip-existing is refused
// before anything is read or rendered.
TEST_F(CliFrames, SkipExistingIsRefusedWhereItMeansNothing) {
    for (const auto& [args, why] : std::vector<std::pair<std::string, std::string>>{
             {"scene.jts -o - --skip-existing", "standard output (-o -) holds no earlier image"},
             {"scene.jts -o /dev/null --skip-existing", "'/dev/null' is a device or a pipe"},
             {"scene.jts --check --skip-existing", "not with --check"},
             {"scene.jts -o a.bmp --expect a.bmp --skip-existing", "not with --expect"},
             {"scene.jts --frames 2 -o 'r%d.bmp' --region 0,0,4,4 --skip-existing",
              "with --region, needs --region-output"},
         }) {
        test::ProgramRun r = run(args);
        EXPECT_EQ(r.code, 2) << args << ": " << r.err;
        EXPECT_NE(r.err.find("--skip-existing: " + why), std::string::npos)
            << args << ": " << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "r0.bmp"));
}

TEST_F(CliFrames, OneFrameHasClockZero) {
    ASSERT_EQ(run("-q scene.jts --frames 1 -o 'one-%d.bmp'").code, 0);
    ASSERT_EQ(run("-q scene.jts -o zero.bmp").code, 0);
    EXPECT_EQ(bytes("one-0.bmp"), bytes("zero.bmp"));
}

TEST_F(CliFrames, PatternFieldsAndPercentSigns) {
    ASSERT_EQ(run("-q scene.jts --frames 2 -o '%%_%09d_%%.bmp'").code, 0);
    EXPECT_TRUE(fs::exists(dir / "%_000000001_%.bmp"));
    ASSERT_EQ(run("-q scene.jts --frames 11 --frame-range 10..10 -o 'p%d.bmp'").code, 0);
    EXPECT_TRUE(fs::exists(dir / "p10.bmp"));
    ASSERT_EQ(run("-q scene.jts --frames 2 -o 'q%01d.bmp'").code, 0);
    EXPECT_TRUE(fs::exists(dir / "q1.bmp"));
}

TEST_F(CliFrames, BadPatternsExitTwoNamingTheOption) {
    for (const char* pattern :
         {"shot.png", "shot-%d-%d.png", "shot-%x.png", "shot-%0d.png", "shot-%00d.png",
          "shot-%4d.png", "shot-%010d.png", "shot-%", "%s.png", "100%.png"}) {
        test::ProgramRun r = run(std::string("scene.jts --frames 3 -o '") + pattern + "'");
        EXPECT_EQ(r.code, 2) << pattern << "\n" << r.err;
        EXPECT_NE(r.err.find("-o/--output"), std::string::npos) << pattern << "\n" << r.err;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// The message quotes the field as printf reads it, not four characters
// whatever they are ('%4d.', '%s.p'), and never half a UTF-8 character.
TEST_F(CliFrames, ABadFieldIsQuotedAlone) {
    const std::pair<const char*, const char*> cases[] = {
        {"shot-%4d.png", "'%4d' is not"},
        {"%s.png", "'%s' is not"},
        {"shot-%010d.png", "'%010d' is not"},
        {"shot-%ld.png", "'%ld' is not"},
        {"shot-%", "'%' is not"},
        {"100%.png", "'%.p' is not"},
        {"shot-%\u00e9.png", "'%\u00e9' is not"},
        {"shot-%4\u20ac.png", "'%4\u20ac' is not"},
    };
    for (const auto& [pattern, quoted] : cases) {
        test::ProgramRun r = run(std::string("scene.jts --frames 3 -o '") + pattern + "'");
        EXPECT_EQ(r.code, 2) << pattern << "\n" << r.err;
        EXPECT_NE(r.err.find(quoted), std::string::npos) << pattern << "\n" << r.err;
    }
}

TEST_F(CliFrames, OptionRulesExitTwoNamingTheOption) {
    const std::pair<const char*, const char*> cases[] = {
        {"--frames 3 --clock 0.5 -o 'a%d.bmp'", "--clock"},
        {"--frame-range 0..1 -o a.bmp", "--frame-range"},
        {"--frames 4 --frame-range 2..4 -o 'a%d.bmp'", "--frame-range"},
        {"--frames 4 --frame-range 3..1 -o 'a%d.bmp'", "--frame-range"},
        {"--frames 4 --frame-range 1 -o 'a%d.bmp'", "--frame-range"},
        {"--frames 4 --frame-range -1..2 -o 'a%d.bmp'", "--frame-range"},
        {"--frames 4 --frame-range a..b -o 'a%d.bmp'", "--frame-range"},
        {"--frames 0 -o 'a%d.bmp'", "--frames"},
        {"--frames 2 -o 'a%d.png' --expect ref.png", "--expect"},
    };
    for (const auto& [args, option] : cases) {
        test::ProgramRun r = run(std::string("scene.jts ") + args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(option), std::string::npos) << args << "\n" << r.err;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// Without -o: "-" and four digits before the extension of the last path
// component; never a % field; always a BMP.
TEST_F(CliFrames, TheScenesFilenameIsNumbered) {
    fs::create_directory(dir / "out.d");
    ASSERT_EQ(run("-q scene.jts --frames 2").code, 0);
    EXPECT_TRUE(fs::exists(dir / "seq-0000.bmp"));
    EXPECT_TRUE(fs::exists(dir / "seq-0001.bmp"));
    ASSERT_EQ(run("-q scene.jts --frames 2 --define 'name=\"out.d/plain\"'").code, 0);
    EXPECT_TRUE(fs::exists(dir / "out.d/plain-0001"));
    ASSERT_EQ(run("-q scene.jts --frames 2 --define 'name=\"a%d.png\"'").code, 0);
    ASSERT_TRUE(fs::exists(dir / "a%d-0001.png"));
    EXPECT_EQ(bytes("a%d-0001.png").substr(0, 2), "BM");
    ASSERT_EQ(run("-q scene.jts --frames 12000 --frame-range 11999..11999").code, 0);
    EXPECT_TRUE(fs::exists(dir / "seq-11999.bmp"));
}

TEST_F(CliFrames, ARangeRendersOnlyItsFramesAndTheSameBytes) {
    ASSERT_EQ(run("-q scene.jts --frames 6 -o 'all-%d.bmp'").code, 0);
    ASSERT_EQ(run("-q scene.jts --frames 6 --frame-range 2..3 -o 'part-%d.bmp'").code, 0);
    for (int f : {0, 1, 4, 5})
        EXPECT_FALSE(fs::exists(dir / ("part-" + std::to_string(f) + ".bmp")));
    for (int f : {2, 3})
        EXPECT_EQ(bytes("part-" + std::to_string(f) + ".bmp"),
                  bytes("all-" + std::to_string(f) + ".bmp"));
}

// The radius reaches 0 at frame 2 of 5 (clock 0.5): an error there, with its
// frame; the frames before it stay.
TEST_F(CliFrames, AnErrorAtOneFrameNamesItAndKeepsEarlierFrames) {
    std::string text = growing_scene;
    text.replace(text.find("0.5 + clock"), 11, "sqrt(0.5 - clock)");
    test::write_file(dir / "shrinking.jts", text);
    test::ProgramRun r = run("shrinking.jts --frames 5 -o 'f%d.bmp'");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("shrinking.jts:5:22: error: 'radius' must be greater than 0"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("note: at frame 2 (clock = 0.5)\n"), std::string::npos) << r.err;
    for (int f : {0, 1}) EXPECT_TRUE(fs::exists(dir / ("f" + std::to_string(f) + ".bmp")));
    EXPECT_FALSE(fs::exists(dir / "f2.bmp"));
    EXPECT_FALSE(fs::exists(dir / "f3.bmp"));
    EXPECT_FALSE(fs::exists(dir / "f4.bmp"));
    // --check sees it too, and writes nothing.
    test::ProgramRun check = run("--check shrinking.jts --frames 5 -o 'c%d.bmp'");
    EXPECT_EQ(check.code, 1) << check.err;
    EXPECT_NE(check.err.find("note: at frame 2 (clock = 0.5)"), std::string::npos) << check.err;
    EXPECT_FALSE(fs::exists(dir / "c0.bmp"));
}

// An included file's clock is read per frame too, and its error quoted from it.
TEST_F(CliFrames, AnIncludedFilesErrorIsLocatedInIt) {
    test::write_file(dir / "ball.jts", "sphere { radius: 0.5 - clock; }\n");
    std::string text = growing_scene;
    text.replace(text.find("    sphere {"), 4, "    include \"ball.jts\";\n    ");
    test::write_file(dir / "main.jts", text);
    test::ProgramRun r = run("main.jts --frames 3 -o 'i%d.bmp'");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("ball.jts:1:18: error: 'radius' must be greater than 0"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("sphere { radius: 0.5 - clock; }"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("note: at frame 1 (clock = 0.5)"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir / "i0.bmp"));
    EXPECT_FALSE(fs::exists(dir / "i1.bmp"));
}

TEST_F(CliFrames, AWarningOfEveryFrameIsPrintedOnce) {
    std::string text = growing_scene;
    text.replace(text.find("pigment: <1, 1, 1>"), 18, "pigment: <2, 1, 1>");
    test::write_file(dir / "clipped.jts", text);
    test::ProgramRun r = run("clipped.jts --frames 3 -o 'w%d.bmp'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "warning:"), 1) << r.err;
    // Named with the frame it was first seen at, and not again after.
    EXPECT_EQ(count(r.err, "note: at frame"), 1) << r.err;
    EXPECT_NE(r.err.find("note: at frame 0 (clock = 0)\n"), std::string::npos) << r.err;
    EXPECT_EQ(count(r.err, "wrote w"), 3) << r.err;
    test::ProgramRun quiet = run("-q clipped.jts --frames 3 -o 'w%d.bmp'");
    ASSERT_EQ(quiet.code, 0);
    EXPECT_EQ(quiet.err, "");
}

// A warning of some frames only says at which: the scale reaches 0 at frame 2
// of 3 (clock 1), and a value that changes with the clock is warned of at each
// frame it changes, each time with its frame.
TEST_F(CliFrames, AWarningOfSomeFramesNamesThem) {
    std::string text = growing_scene;
    text.replace(text.find("ambient: <1, 1, 1>; }"), 21,
                 "ambient: <1, 1, 1>; } transform { scale: <1, 1, 1 - clock>; }");
    test::write_file(dir / "flattened.jts", text);
    test::ProgramRun r = run("flattened.jts --frames 3 -o 'z%d.bmp'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "warning:"), 1) << r.err;
    const std::size_t warning = r.err.find("warning: 'scale' <1, 1, 0> has a zero component");
    ASSERT_NE(warning, std::string::npos) << r.err;
    const std::size_t note = r.err.find("note: at frame 2 (clock = 1)\n");
    EXPECT_NE(note, std::string::npos) << r.err;
    EXPECT_GT(note, warning) << r.err;
    EXPECT_LT(note, r.err.find("wrote z2.bmp")) << r.err;
    EXPECT_EQ(count(r.err, "note:"), 1) << r.err;

    text = growing_scene;
    text.replace(text.find("pigment: <1, 1, 1>"), 18, "pigment: <1 + clock, 1, 1>");
    test::write_file(dir / "brighter.jts", text);
    r = run("brighter.jts --frames 3 -o 'p%d.bmp'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "warning: 'pigment'"), 2) << r.err;
    EXPECT_NE(r.err.find("note: at frame 1 (clock = 0.5)\n"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("note: at frame 2 (clock = 1)\n"), std::string::npos) << r.err;
    EXPECT_EQ(count(r.err, "note:"), 2) << r.err;
    // Quiet drops warnings, and their notes with them.
    EXPECT_EQ(run("-q brighter.jts --frames 3 -o 'p%d.bmp'").err, "");
}

// A scene that never reads clock renders the same image at every frame.
TEST_F(CliFrames, ASceneWithoutClockGivesEqualFrames) {
    std::string text = growing_scene;
    text.replace(text.find("0.5 + clock"), 11, "0.75");
    test::write_file(dir / "still.jts", text);
    ASSERT_EQ(run("-q still.jts --frames 3 -o 's%d.bmp'").code, 0);
    ASSERT_EQ(run("-q still.jts -o alone.bmp").code, 0);
    for (int f : {0, 1, 2}) EXPECT_EQ(bytes("s" + std::to_string(f) + ".bmp"), bytes("alone.bmp"));
}

TEST_F(CliFrames, ProgressLogCoversTheSequence) {
    // Frames short enough that none alone reaches the log's first second, but
    // not the whole sequence, with room to spare (a sequence done within that
    // second logs nothing): about 3 s in a release build on 2 cores.
    test::ProgramRun r = run(
        "scene.jts --frames 30 --width 480 --height 320 --samples 32 --progress log -o 'g%d.bmp'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("wrote 30 frames in"), std::string::npos) << r.err;
    // One log over the sequence: its percentages only go up.
    std::vector<int> percents;
    std::istringstream lines(r.err);
    for (std::string line; std::getline(lines, line);)
        if (line.starts_with("rendering: ")) percents.push_back(std::stoi(line.substr(11)));
    ASSERT_FALSE(percents.empty()) << r.err;
    EXPECT_TRUE(std::is_sorted(percents.begin(), percents.end())) << r.err;
    EXPECT_EQ(std::adjacent_find(percents.begin(), percents.end()), percents.end()) << r.err;
}

}  // namespace
}  // namespace jt
