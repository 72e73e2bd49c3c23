// jtracer-mpi under mpirun: the CLI's bytes with any number of ranks, one
// message for a bad scene, and a clean failure when a rank dies.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace jt {
namespace {

using test::ProgramRun;

const std::string cli = "'" JT_CLI "' ";
const std::string showcase = "'" JT_SOURCE_DIR "/scenes/showcase.jts' ";
const std::string manual = "'" JT_SOURCE_DIR "/scenes/manual/cylinder.jts' ";
const std::string mesh = "'" JT_SOURCE_DIR "/scenes/mesh.jts' ";

// mpirun as CI runs it: as root, more ranks than cores. OpenMPI's own
// allocations outlive MPI_Finalize, many in plugins already unloaded (which no
// suppression can name), so under LeakSanitizer leak checking is off for the
// ranks of these tests only; AddressSanitizer's other checks stay on.
std::string mpirun(int ranks, const std::string& env = "") {
    return "env ASAN_OPTIONS=detect_leaks=0 " + env +
           " '" JT_MPIEXEC "' --oversubscribe --allow-run-as-root -np " + std::to_string(ranks) +
           (env.empty() ? "" : " -x " + env.substr(0, env.find('='))) + " '" JT_MPI "' ";
}

// The same, with mpirun's own binding options (mpirun() leaves its default).
std::string mpirun_bound(int ranks, const std::string& binding) {
    return "env ASAN_OPTIONS=detect_leaks=0 '" JT_MPIEXEC "' --oversubscribe --allow-run-as-root " +
           binding + " -np " + std::to_string(ranks) + " '" JT_MPI "' ";
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

class Mpi : public test::ScratchTest {
  protected:
    void expect_same_bytes_as_cli(const std::string& scene, const std::string& settings,
                                  const std::string& tile_size,
                                  std::initializer_list<int> rank_counts) {
        ProgramRun single = run_shell(cli + scene + settings + " -q -o cli.bmp");
        ASSERT_EQ(single.code, 0) << single.err;
        for (int ranks : rank_counts) {
            const std::string name = "mpi" + std::to_string(ranks) + ".bmp";
            ProgramRun r = run_shell(mpirun(ranks) + scene + settings + " --tile-size " +
                                     tile_size + " -q --stats -o " + name);
            ASSERT_EQ(r.code, 0) << r.err;
            EXPECT_NE(r.err.find("stats: " + std::to_string(ranks) + " ranks"), std::string::npos)
                << r.err;
            EXPECT_EQ(test::read_file(dir / name), test::read_file(dir / "cli.bmp"))
                << ranks << " ranks must give jtracer-cli's bytes";
        }
    }

    // The files in `dir` other than the scene a test wrote.
    std::vector<std::string> outputs() const {
        std::vector<std::string> names = files();
        std::erase(names, "bad.jts");
        return names;
    }
};

TEST_F(Mpi, ShowcaseMatchesTheCliByteForByte) {
    // Small tiles, so that every rank gets several in an order that varies.
    expect_same_bytes_as_cli(showcase, "--width 150 --height 90 --samples 2", "16", {1, 3});
}

TEST_F(Mpi, ManualSceneMatchesTheCliByteForByte) {
    expect_same_bytes_as_cli(manual, "--width 96 --height 64", "32", {2, 4});
}

TEST_F(Mpi, MeshSceneMatchesTheCliByteForByte) {
    // Every rank opens the model reader module as jtracer-cli does.
    expect_same_bytes_as_cli(mesh, "--width 96 --height 54", "32", {2});
}

// A scene that renders in no time, for tests of what happens around the
// render (its file named as an output).
constexpr const char* kEightPixelScene =
    "render_settings { width: 8; height: 8; }\n"
    "cameras { perspective_camera { position: <0, 0, 5>; } }\n";

TEST_F(Mpi, BadSceneIsReportedOnceAndEveryRankFails) {
    test::write_file(dir / "bad.jts", "scene { sphere { radius: -1; } }\n");
    ProgramRun r = run_shell(mpirun(3) + "bad.jts -o out.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(count(r.err, "bad.jts:1:26: error: 'radius' must be greater than 0"), 1u) << r.err;
    EXPECT_TRUE(outputs().empty());
}

// --check, as jtracer-cli's: the scene validated (each frame's with --frames)
// and reported once, nothing written; a bad scene exits 1.
TEST_F(Mpi, CheckValidatesOnceAndWritesNothing) {
    test::write_file(dir / "good.jts", kEightPixelScene);
    ProgramRun r = run_shell(mpirun(3) + "--check good.jts -o out.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "good.jts: no errors\n"), 1u) << r.err;
    r = run_shell(mpirun(2) + "--check good.jts --frames 3");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "good.jts: no errors in frames 0..2"), 1u) << r.err;
    test::write_file(dir / "bad.jts", "scene { sphere { radius: -1; } }\n");
    r = run_shell(mpirun(3) + "--check bad.jts -o out.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(count(r.err, "bad.jts:1:26: error: 'radius' must be greater than 0"), 1u) << r.err;
    r = run_shell(mpirun(2) + "--check good.jts --skip-existing -o out.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "--skip-existing: not with --check"), 1u) << r.err;
    // A region file under a scene's filename.png: refused as the render
    // (and jtracer-cli --check) refuses it, with and without --frames.
    test::write_file(dir / "png.jts",
                     "render_settings { width: 8; height: 8; filename: \"png.png\"; }\n"
                     "cameras { perspective_camera { position: <0, 0, 5>; } }\n");
    for (const char* frames : {"", "--frames 2 "}) {
        r = run_shell(mpirun(2) + "--check png.jts --region 0,0,8,2 --region-output " + frames);
        EXPECT_EQ(r.code, 2) << frames << r.err;
        EXPECT_EQ(count(r.err, "png.jts:1:50: error: --region-output writes a BMP"), 1u) << r.err;
        EXPECT_EQ(count(r.err, "no errors"), 0u) << r.err;
    }
    std::vector<std::string> left = outputs();
    std::erase(left, "good.jts");
    std::erase(left, "png.jts");
    EXPECT_TRUE(left.empty()) << left.front();
}

// --region and --region-output, as jtracer-cli's: the same bytes for the
// window (alone, or in a black frame), a part jtracer-merge joins to a part
// jtracer-cli rendered, and --skip-existing keeping a part of the same render.
TEST_F(Mpi, ARegionIsRenderedAsTheCliRendersIt) {
    const std::string frame = "--width 96 --height 64 -q ";
    ASSERT_EQ(run_shell(cli + showcase + frame + "-o full.bmp").code, 0);
    ASSERT_EQ(run_shell(cli + showcase + frame + "--region 10,20,70,64 -o cli_window.bmp").code, 0);
    ASSERT_EQ(
        run_shell(cli + showcase + frame + "--region 0,20,96,64 --region-output -o bottom.bmp")
            .code,
        0);
    ASSERT_EQ(
        run_shell(cli + showcase + frame + "--region 0,0,96,20 --region-output -o cli_top.bmp")
            .code,
        0);
    ProgramRun r = run_shell(mpirun(3) + showcase + frame +
                             "--tile-size 16 --region 10,20,70,64 -o mpi_window.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(test::read_file(dir / "mpi_window.bmp"), test::read_file(dir / "cli_window.bmp"));
    r = run_shell(mpirun(3) + showcase + frame +
                  "--tile-size 16 --region 0,0,96,20 --region-output -o top.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(test::read_file(dir / "top.bmp"), test::read_file(dir / "cli_top.bmp"));
    r = run_shell("'" JT_MERGE "' -q -o merged.bmp top.bmp bottom.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(test::read_file(dir / "merged.bmp"), test::read_file(dir / "full.bmp"));
    r = run_shell(mpirun(2) + showcase + "--width 96 --height 64 --region 0,0,96,20 " +
                  "--region-output --skip-existing -o top.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "kept top.bmp: already there and complete"), 1u) << r.err;
    // The rules of jtracer-cli, said once.
    r = run_shell(mpirun(2) + showcase + frame + "--region-output -o part.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "--region-output: needs --region"), 1u) << r.err;
    r = run_shell(mpirun(2) + showcase + frame + "--region 0,0,96,90 -o part.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "--region: region 0,0,96,90 reaches past the bottom edge"), 1u) << r.err;
    EXPECT_FALSE(exists("part.bmp"));
}

// -o naming the scene file wrote the image over it, as jtracer-cli's did.
TEST_F(Mpi, AnOutputThatIsTheSceneFileIsRefusedOnce) {
    const std::string text = kEightPixelScene;
    test::write_file(dir / "self.jts", text);
    ProgramRun r = run_shell(mpirun(2) + "self.jts -o ./self.jts");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "'./self.jts' is the scene file itself"), 1u) << r.err;
    EXPECT_EQ(test::read_file(dir / "self.jts"), text);
}

// A named pipe as the scene: every rank opened it, one got the text and the
// others waited for theirs forever.
TEST_F(Mpi, APipedSceneWithManyRanksIsRefused) {
    ASSERT_EQ(run_shell("mkfifo scene.fifo").code, 0);
    ProgramRun r = run_shell("timeout 60 " + mpirun(2) + "scene.fifo -o out.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "'scene.fifo' is a pipe or a device, which only one of the 2 ranks"), 1u)
        << r.err;
    EXPECT_FALSE(exists("out.bmp"));
}

// CLI11 checked required options before unknown ones, and worded its errors
// its own way ("--output is required" for a mistyped option).
TEST_F(Mpi, MergeUsageErrorsNameTheOptionAndWhatItExpects) {
    const std::string merge = "'" JT_MERGE "' ";
    ProgramRun r = run_shell(merge + "--bogus");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err,
              "jtracer-merge: unknown option '--bogus'\n"
              "Run 'jtracer-merge --help' for the options.\n");
    r = run_shell(merge + "-o out.bmp");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(count(r.err, "jtracer-merge: missing PARTS\n"), 1u) << r.err;
    r = run_shell(merge + "a.bmp");
    EXPECT_EQ(count(r.err, "jtracer-merge: missing -o/--output FILE\n"), 1u) << r.err;
    r = run_shell(merge + "a.bmp -o");
    EXPECT_EQ(count(r.err, "jtracer-merge: -o/--output: needs FILE after it\n"), 1u) << r.err;
    r = run_shell(merge + "-o x.bmp -o y.bmp a.bmp");
    EXPECT_EQ(count(r.err, "jtracer-merge: -o/--output: given more than once"), 1u) << r.err;
}

// -o shot.jpg gives a BMP, as jtracer-cli's does, but jtracer-cli warns that
// image viewers and upload forms will take it for a JPEG; jtracer-mpi did not.
TEST_F(Mpi, AnOutputNamingAnotherImageFormatWarnsAsTheCliDoes) {
    ProgramRun r = run_shell(mpirun_bound(2, "--bind-to none") + showcase +
                             "--width 40 --height 30 -o shot.jpg");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(test::read_file(dir / "shot.jpg").substr(0, 2), "BM");
    EXPECT_EQ(count(r.err, "jtracer-mpi: warning: -o/--output 'shot.jpg' is written as a BMP"), 1u)
        << r.err;
    r = run_shell(mpirun(2) + showcase + "--width 40 --height 30 -q -o shot.jpg");
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// A frame of the range whose file is the scene file: refused before any frame
// is written, as by jtracer-cli, not once the frames before it were.
TEST_F(Mpi, AFrameThatIsTheSceneFileIsRefusedBeforeAnyFrame) {
    const std::string text = kEightPixelScene;
    test::write_file(dir / "s-3.jts", text);
    ProgramRun r = run_shell(mpirun(2) + "s-3.jts -q --frames 5 -o 's-%d.jts'");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "frame 3's file 's-3.jts' is the scene file itself"), 1u) << r.err;
    EXPECT_NE(r.err.find("; no frame was written"), std::string::npos) << r.err;
    EXPECT_EQ(files(), std::vector<std::string>{"s-3.jts"});
    EXPECT_EQ(test::read_file(dir / "s-3.jts"), text);
}

// A sphere that grows with clock, over many small tiles, so that tiles handed
// out twice at the end of one frame are still on their way when it stops.
const std::string growing = R"(
cameras { perspective_camera { position: <0, 0, 6>; look_at: <0, 0, 0>; aspect: 1.5; } }
scene {
    sphere { radius: 0.5 + clock; material { pigment: <1, 0.5, 0.2>; ambient: <1, 1, 1>; } }
}
render_settings { width: 96; height: 64; filename: "seq.bmp"; ambient_light: <1, 1, 1>; }
)";

TEST_F(Mpi, EveryFrameOfASequenceMatchesTheCli) {
    test::write_file(dir / "seq.jts", growing);
    ProgramRun single = run_shell(cli + "-q seq.jts --frames 5 -o 'cli-%d.png'");
    ASSERT_EQ(single.code, 0) << single.err;
    ProgramRun r = run_shell(mpirun(3) + "seq.jts --frames 5 --tile-size 16 -o 'mpi-%d.png'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "wrote mpi-"), 5u) << r.err;
    for (int f = 0; f < 5; ++f) {
        const std::string n = std::to_string(f);
        EXPECT_EQ(test::read_file(dir / ("mpi-" + n + ".png")),
                  test::read_file(dir / ("cli-" + n + ".png")))
            << "frame " << f;
    }
    EXPECT_NE(test::read_file(dir / "mpi-0.png"), test::read_file(dir / "mpi-4.png"));
    // A range, named after the scene's filename.
    r = run_shell(mpirun(2) + "seq.jts -q --frames 5 --frame-range 3..4 --tile-size 16");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "seq-0002.bmp"));
    ASSERT_EQ(run_shell(cli + "-q seq.jts --clock 0.75 -o alone.bmp").code, 0);
    EXPECT_EQ(test::read_file(dir / "seq-0003.bmp"), test::read_file(dir / "alone.bmp"));
    EXPECT_TRUE(std::filesystem::exists(dir / "seq-0004.bmp"));
}

// jtracer-cli's --skip-existing, for a farm's rerun of an MPI job: rank 0
// keeps the frames already there and complete on its machine, and the
// workers do not even prepare them.
TEST_F(Mpi, SkipExistingRendersOnlyWhatIsMissingOrIncomplete) {
    test::write_file(dir / "seq.jts", growing);
    ASSERT_EQ(run_shell(cli + "-q seq.jts --frames 5 -o 'cli-%d.png'").code, 0);
    ProgramRun r = run_shell(mpirun(2) + "seq.jts -q --frames 5 --tile-size 16 -o 'f%d.png'");
    ASSERT_EQ(r.code, 0) << r.err;
    std::filesystem::remove(dir / "f1.png");
    const std::string whole = test::read_file(dir / "f3.png");
    test::write_file(dir / "f3.png", whole.substr(0, whole.size() / 2));  // a copy cut short
    r = run_shell(mpirun(3) + "seq.jts --frames 5 --tile-size 16 -o 'f%d.png' --skip-existing");
    ASSERT_EQ(r.code, 0) << r.err;
    for (int f = 0; f < 5; ++f) {
        const std::string n = std::to_string(f);
        EXPECT_EQ(test::read_file(dir / ("f" + n + ".png")),
                  test::read_file(dir / ("cli-" + n + ".png")))
            << "frame " << f;
    }
    EXPECT_EQ(count(r.err, "kept f"), 3u) << r.err;
    EXPECT_EQ(count(r.err, "kept f2.png (frame 2): already there and complete"), 1u) << r.err;
    EXPECT_EQ(count(r.err, "wrote f1.png (frame 1"), 1u) << r.err;
    EXPECT_EQ(count(r.err, "jtracer-mpi: note: f3.png is there, but it is cut short"), 1u) << r.err;
    EXPECT_EQ(count(r.err, "wrote 2 frames and kept 3 already there in "), 1u) << r.err;
    // Every frame there: no rank prepares any (rank 1's set-up would take a
    // minute), and the job ends at once.
    const auto start = std::chrono::steady_clock::now();
    r = run_shell("timeout 120 " + mpirun(2, "JT_MPI_TEST_SLOW_SETUP_RANK=1") +
                  "seq.jts --frames 5 -o 'f%d.png' --skip-existing");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_LT(seconds, 40.0) << r.err;
    EXPECT_EQ(count(r.err, "kept all 5 frames, already there"), 1u) << r.err;
    // One image, kept; where nothing can be kept, refused as by jtracer-cli.
    r = run_shell(mpirun(2) + "seq.jts -o f0.png --skip-existing");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "kept f0.png: already there and complete\n");
    r = run_shell(mpirun(2) + "seq.jts -o /dev/null --skip-existing");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "--skip-existing: '/dev/null' is a device or a pipe"), 1u) << r.err;
}

TEST_F(Mpi, ProgressCoversTheWholeSequence) {
    // Frames short enough that none alone reaches the log's first second, but
    // not the whole sequence: 60 frames of about 0.05 s each, well past the
    // first second on a quiet machine too.
    test::write_file(dir / "seq.jts", growing);
    ProgramRun r = run_shell(
        mpirun(2) +
        "seq.jts --frames 60 --width 480 --height 320 --samples 16 --progress log -o 'p%d.bmp'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, "wrote p"), 60u) << r.err;
    EXPECT_EQ(count(r.err, "wrote 60 frames in"), 1u) << r.err;
    // One log over the sequence: its percentages only go up.
    std::vector<int> percents;
    std::istringstream lines(r.err);
    for (std::string line; std::getline(lines, line);)
        if (line.starts_with("rendering: ")) percents.push_back(std::stoi(line.substr(11)));
    ASSERT_FALSE(percents.empty()) << r.err;
    EXPECT_TRUE(std::is_sorted(percents.begin(), percents.end())) << r.err;
    EXPECT_EQ(std::adjacent_find(percents.begin(), percents.end()), percents.end()) << r.err;
}

TEST_F(Mpi, AnErrorAtOneFrameEndsEveryRankOnce) {
    std::string text = growing;
    text.replace(text.find("0.5 + clock"), 11, "0.5 - clock");
    test::write_file(dir / "bad.jts", text);
    ProgramRun r = run_shell("timeout 120 " + mpirun(3) + "bad.jts -q --frames 3 -o 'f%d.bmp'");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(count(r.err, "note: at frame 1 (clock = 0.5)"), 1u) << r.err;
    EXPECT_EQ(outputs(), std::vector<std::string>{"f0.bmp"});
}

TEST_F(Mpi, SequenceUsageErrorsAreReportedOnce) {
    for (const char* args : {"--frames 3 --clock 1 -o 'a%d.bmp'", "--frames 3 -o a.bmp",
                             "--frame-range 0..1 -o a.bmp"}) {
        ProgramRun r = run_shell(mpirun(2) + showcase + args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        EXPECT_EQ(count(r.err, "Run 'jtracer-mpi --help'"), 1u) << args << "\n" << r.err;
    }
}

TEST_F(Mpi, MissingSceneFileIsReportedOnce) {
    ProgramRun r = run_shell(mpirun(2) + "nowhere.jts -o out.bmp");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(count(r.err, "nowhere.jts"), 1u) << r.err;
    EXPECT_TRUE(outputs().empty());
}

TEST_F(Mpi, UsageErrorIsReportedOnce) {
    ProgramRun r = run_shell(mpirun(2) + showcase + "--samples 0");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "--samples"), 1u) << r.err;
}

TEST_F(Mpi, UnwritableOutputIsAnIoError) {
    ProgramRun r = run_shell(mpirun(2) + showcase + "--width 40 --height 30 -q -o nowhere/out.bmp");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(count(r.err, "cannot write"), 1u) << r.err;
    EXPECT_TRUE(outputs().empty());
}

// Rank 0 found a folder it cannot write in only once every rank had rendered
// the frame: a farm's hours lost to a typo in -o.
TEST_F(Mpi, UnwritableOutputIsFoundBeforeTheRender) {
    ProgramRun r = run_shell(mpirun(2) + showcase +
                             "--width 40 --height 30 --progress log -o nowhere/out.bmp");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(count(r.err, "cannot write 'nowhere/out.bmp'"), 1u) << r.err;
    EXPECT_NE(r.err.find("; nothing was rendered\n"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("rendering:"), std::string::npos) << r.err;
    // In a sequence, each frame's own folder, before that frame.
    test::write_file(dir / "seq.jts", growing);
    std::filesystem::create_directory(dir / "f0");
    r = run_shell(mpirun(2) + "seq.jts -q --frames 2 -o 'f%d/shot.bmp'");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(count(r.err, "cannot write 'f1/shot.bmp'"), 1u) << r.err;
    EXPECT_NE(r.err.find("; frames 0..0 were written\n"), std::string::npos) << r.err;
    EXPECT_TRUE(exists("f0/shot.bmp"));
    // A rerun with --skip-existing wrote none of the frames it kept.
    std::filesystem::create_directory(dir / "f1");
    r = run_shell(mpirun(2) + "seq.jts -q --frames 3 --skip-existing -o 'f%d/shot.bmp'");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("; frames 0..1 are there (1 written, 1 kept)\n"), std::string::npos)
        << r.err;
    r = run_shell(mpirun(2) + "seq.jts -q --frames 3 --skip-existing -o 'f%d/shot.bmp'");
    EXPECT_NE(r.err.find("; frames 0..1 were kept, already there\n"), std::string::npos) << r.err;
}

// OpenMPI gives a rank a terminal of its own as standard output, whatever
// mpirun's is redirected to: `-o - > out.bmp` was refused as "standard output
// is a terminal ... redirect standard output to a file", which it was.
TEST_F(Mpi, ADashOutputUnderMpirunIsRefusedForWhatItIs) {
    const std::string settings = "--width 40 --height 30 ";
    ASSERT_EQ(run_shell(cli + showcase + settings + "-q -o cli.bmp").code, 0);
    // Run alone, without a launcher, standard output is the user's own; it is
    // named so, not as /dev/stdout.
    ProgramRun r = run_shell("env ASAN_OPTIONS=detect_leaks=0 '" JT_MPI "' " + showcase + settings +
                             "-o - > alone.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("wrote standard output: 40x30"), std::string::npos) << r.err;
    EXPECT_EQ(test::read_file(dir / "alone.bmp"), test::read_file(dir / "cli.bmp"));
    r = run_shell(mpirun(2) + showcase + settings + "-q -o - > out.bmp");
    if (r.code == 0) {
        // A launcher that hands the ranks a pipe: the image goes through.
        EXPECT_EQ(test::read_file(dir / "out.bmp"), test::read_file(dir / "cli.bmp"));
        return;
    }
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(count(r.err, "- (standard output) cannot carry the image under mpirun"), 1u) << r.err;
    EXPECT_EQ(r.err.find("is a terminal"), std::string::npos) << r.err;
}

TEST_F(Mpi, DeadRankFailsTheRunWithoutAPartialFile) {
    const std::string settings = "--width 160 --height 96 ";
    ProgramRun single = run_shell(cli + showcase + settings + "-q -o cli.bmp");
    ASSERT_EQ(single.code, 0) << single.err;
    const auto start = std::chrono::steady_clock::now();
    ProgramRun r = run_shell("timeout 120 " + mpirun(3, "JT_MPI_TEST_ABORT_RANK=1") + showcase +
                             settings + "--tile-size 16 -q -o out.bmp");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(r.code, 0) << r.err;
    EXPECT_NE(r.code, 124) << "timed out: the run hung";
    EXPECT_LT(seconds, 60.0);
    // OpenMPI names the rank that died; rank 0 says it wrote nothing (when it
    // is not killed before it can).
    EXPECT_TRUE(r.err.find("exited on signal 6") != std::string::npos ||
                r.err.find("nothing was written") != std::string::npos)
        << r.err;
    // The others may have rendered the dead rank's tiles again and finished the
    // frame: an image is then complete. No temporary file is ever left.
    std::vector<std::string> left = outputs();
    std::erase(left, "cli.bmp");
    if (!left.empty()) {
        EXPECT_EQ(left, std::vector<std::string>{"out.bmp"});
        EXPECT_EQ(test::read_file(dir / "out.bmp"), test::read_file(dir / "cli.bmp"));
    }
}

// The jtracer-mpi rank 0 whose folder is `folder`: the process that writes
// the image, which a farm's signal (a dropped ssh connection, a scheduler's
// SIGTERM) reaches first when jtracer-mpi runs alone or mpirun passes it on.
pid_t rank_zero_in(const std::filesystem::path& folder) {
    const std::filesystem::path place = std::filesystem::canonical(folder);
    const std::filesystem::path program = std::filesystem::canonical(JT_MPI);
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::error_code error;
        if (std::filesystem::read_symlink(entry.path() / "cwd", error) != place || error) continue;
        if (std::filesystem::read_symlink(entry.path() / "exe", error) != program || error)
            continue;
        const std::string environment = test::read_file(entry.path() / "environ");
        if (environment.find(std::string("OMPI_COMM_WORLD_RANK=0") + '\0') != std::string::npos)
            return static_cast<pid_t>(std::stol(name));
    }
    return -1;
}

// SIGHUP (a dropped ssh connection), SIGINT and SIGTERM stop jtracer-mpi as
// they stop jtracer-cli: the shared handler, its exit codes, its message and
// no temporary file. SIGHUP ended rank 0 on the spot, so that one arriving
// during the write left the temporary file beside the image.
TEST_F(Mpi, StopSignalsEndTheRunAsTheCliDoes) {
    for (const int signal : {SIGHUP, SIGTERM}) {
        test::RunningProgram render(
            {{"env", "ASAN_OPTIONS=detect_leaks=0", JT_MPIEXEC, "--oversubscribe",
              "--allow-run-as-root", "-np", "2", JT_MPI, JT_SOURCE_DIR "/scenes/showcase.jts", "-o",
              "out.bmp", "--samples", "64", "--threads", "1", "--progress", "log"},
             dir});
        ASSERT_GT(render.pid(), 0);
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (render.err_so_far().find("rendering:") == std::string::npos &&
               std::chrono::steady_clock::now() < give_up)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        ASSERT_NE(render.err_so_far().find("rendering:"), std::string::npos)
            << "the render never reported progress: " << render.err_so_far();
        const pid_t rank_zero = rank_zero_in(dir);
        ASSERT_GT(rank_zero, 0) << "no rank 0 found";
        ASSERT_EQ(::kill(rank_zero, signal), 0);
        ProgramRun r = render.finish();
        const std::string name = signal == SIGHUP ? "SIGHUP" : "SIGTERM";
        EXPECT_EQ(r.code, 128 + signal) << r.err;
        EXPECT_EQ(count(r.err, "jtracer-mpi: interrupted by " + name + "; nothing was written"), 1u)
            << r.err;
        EXPECT_TRUE(files().empty()) << files().front();
    }
}

TEST_F(Mpi, RankBoundToFewerCpusThanTheMachineSaysSo) {
    if (std::thread::hardware_concurrency() < 2)
        GTEST_SKIP() << "needs a machine of 2 CPUs or more";
    const std::string scene = showcase + "--width 32 --height 18 -o out.bmp ";
    const std::string warning = "CPUs (bound by mpirun, or by taskset); pass --bind-to none";
    // Bound by taskset and left so by mpirun: each rank may use one CPU.
    ProgramRun r = run_shell("taskset -c 0 " + mpirun_bound(2, "--bind-to none") + scene);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, warning), 2u) << r.err;
    EXPECT_NE(r.err.find("rank 1 on "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("may run on only 1 of the machine's "), std::string::npos) << r.err;
    // Bound by mpirun itself, one core a rank.
    r = run_shell(mpirun_bound(2, "--bind-to core") + scene);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, warning), 2u) << r.err;
    // Unbound: no warning; quiet: none either.
    r = run_shell(mpirun_bound(2, "--bind-to none") + scene);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count(r.err, warning), 0u) << r.err;
    r = run_shell("taskset -c 0 " + mpirun_bound(2, "--bind-to none") + scene + "-q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

}  // namespace
}  // namespace jt
