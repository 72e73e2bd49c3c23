// jtracer-cli --region / --region-output and jtracer-merge end to end: parts
// rendered separately merge to the exact bytes of a whole render.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include "jtracer/bmp.hpp"
#include "jtracer/region.hpp"
#include "jtracer/region_file.hpp"

namespace jt {
namespace {

using test::ProgramRun;

const std::string cli = "'" JT_CLI "' ";
const std::string merge = "'" JT_MERGE "' ";
const std::string showcase = "'" JT_SOURCE_DIR "/scenes/showcase.jts' ";
const std::string manual = "'" JT_SOURCE_DIR "/scenes/manual/transform.jts' ";

class RegionCli : public test::ScratchTest {
  protected:
    // Renders `scene` whole and as the given parts, merges, and compares bytes.
    void expect_parts_merge_to_whole(const std::string& scene, const std::string& size,
                                     const std::vector<std::string>& regions) {
        ProgramRun whole = run_shell(cli + scene + size + " -q -o whole.bmp");
        ASSERT_EQ(whole.code, 0) << whole.err;
        std::string names;
        for (std::size_t i = 0; i < regions.size(); ++i) {
            std::string name = "part" + std::to_string(i) + ".bmp";
            ProgramRun r = run_shell(cli + scene + size + " -q --region " + regions[i] +
                                     " --region-output -o " + name);
            ASSERT_EQ(r.code, 0) << regions[i] << ": " << r.err;
            names += " " + name;
        }
        ProgramRun m = run_shell(merge + "-o merged.bmp" + names);
        ASSERT_EQ(m.code, 0) << m.err;
        EXPECT_NE(m.err.find("from " + std::to_string(regions.size()) + " parts"),
                  std::string::npos)
            << m.err;
        EXPECT_EQ(test::read_file(dir / "merged.bmp"), test::read_file(dir / "whole.bmp"))
            << "merged parts must equal the whole render byte for byte";
    }
};

TEST_F(RegionCli, ShowcasePartsMergeToTheWholeImage) {
    // Uneven cuts that do not follow the renderer's 32-pixel tiles.
    expect_parts_merge_to_whole(showcase, "--width 161 --height 97 --samples 2",
                                {"0,0,161,13", "0,13,50,97", "50,13,161,60", "50,60,161,97"});
}

TEST_F(RegionCli, ManualScenePartsMergeToTheWholeImage) {
    expect_parts_merge_to_whole(manual, "--width 120 --height 90",
                                {"0,0,60,90", "60,0,120,45", "60,45,120,90"});
}

TEST_F(RegionCli, RegionPartIsTheWholeImagesPixelsFromTheTopLeft) {
    ASSERT_EQ(run_shell(cli + showcase + "--width 80 --height 60 -q -o whole.bmp").code, 0);
    ProgramRun r =
        run_shell(cli + showcase + "--width 80 --height 60 -q --region 10,5,30,25 -o full.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    const Expected<Image8> whole_file = read_bmp(dir / "whole.bmp");
    const Expected<Image8> full_file = read_bmp(dir / "full.bmp");
    ASSERT_TRUE(whole_file) << whole_file.error().message;
    ASSERT_TRUE(full_file) << full_file.error().message;
    const Image8& whole = *whole_file;
    const Image8& full = *full_file;
    ASSERT_EQ(full.width, 80) << "without --region-output the image keeps its full size";
    // Rows 5..24 from the top are Image8 rows 35..54.
    const PixelRect rect{10, 35, 30, 55};
    EXPECT_EQ(crop_image(full, rect), crop_image(whole, rect));
    EXPECT_EQ(full.pixel(9, 40)[0] + full.pixel(9, 40)[1] + full.pixel(9, 40)[2], 0);
    EXPECT_EQ(full.pixel(20, 34)[0] + full.pixel(20, 34)[1] + full.pixel(20, 34)[2], 0);
}

TEST_F(RegionCli, MalformedRegionIsAUsageError) {
    for (const char* region : {"1,2,3", "a,b,c,d", "10,0,5,5", "-1,0,5,5"}) {
        ProgramRun r =
            run_shell(cli + showcase + "--width 40 --height 30 -o out.bmp --region " + region);
        EXPECT_EQ(r.code, 2) << region;
        EXPECT_NE(r.err.find("--region"), std::string::npos) << r.err;
        EXPECT_FALSE(exists("out.bmp"));
    }
}

TEST_F(RegionCli, RegionOutsideTheImageIsAUsageErrorSayingWhichBound) {
    ProgramRun r =
        run_shell(cli + showcase + "--width 40 --height 30 -q -o out.bmp --region 0,0,40,31");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("reaches past the bottom edge of the 40x30 image (Y1 may be at most 30)"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(exists("out.bmp"));
}

TEST_F(RegionCli, RegionOutputNeedsARegionAndABmpName) {
    ProgramRun r = run_shell(cli + showcase + "--region-output -o out.bmp");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("needs --region"), std::string::npos) << r.err;
    r = run_shell(cli + showcase + "--region 0,0,4,4 --region-output -o out.png");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("writes a BMP"), std::string::npos) << r.err;
    EXPECT_FALSE(exists("out.bmp"));
    EXPECT_FALSE(exists("out.png"));
}

TEST_F(RegionCli, MergeRefusesGapsOverlapsAndForeignFilesWritingNothing) {
    const std::string size = "--width 40 --height 30 -q --region-output ";
    ASSERT_EQ(run_shell(cli + showcase + size + "--region 0,0,40,15 -o top.bmp").code, 0);
    ASSERT_EQ(run_shell(cli + showcase + size + "--region 0,15,40,30 -o bottom.bmp").code, 0);
    ASSERT_EQ(run_shell(cli + showcase + size + "--region 0,10,40,20 -o middle.bmp").code, 0);
    ASSERT_EQ(run_shell(cli + showcase + "--width 40 --height 30 -q -o plain.bmp").code, 0);

    ProgramRun gap = run_shell(merge + "-o out.bmp top.bmp");
    EXPECT_EQ(gap.code, 1);
    EXPECT_NE(gap.err.find("no part covers pixel 0,15"), std::string::npos) << gap.err;
    ProgramRun overlap = run_shell(merge + "-o out.bmp top.bmp bottom.bmp middle.bmp");
    EXPECT_EQ(overlap.code, 1);
    EXPECT_NE(overlap.err.find("overlaps"), std::string::npos) << overlap.err;
    ProgramRun plain = run_shell(merge + "-o out.bmp top.bmp plain.bmp");
    EXPECT_EQ(plain.code, 3);
    EXPECT_NE(plain.err.find("plain.bmp"), std::string::npos) << plain.err;
    EXPECT_NE(plain.err.find("no region record"), std::string::npos) << plain.err;
    ProgramRun missing = run_shell(merge + "-o out.bmp top.bmp nowhere.bmp");
    EXPECT_EQ(missing.code, 3);
    EXPECT_NE(missing.err.find("nowhere.bmp"), std::string::npos) << missing.err;
    EXPECT_FALSE(exists("out.bmp"));

    ProgramRun usage = run_shell(merge + "top.bmp");
    EXPECT_EQ(usage.code, 2) << "no -o";
}

// `jtracer-merge -o parts/frame.bmp parts/*.bmp` run twice names its own
// output as a part; -o over a part would lose it for the next merge.
TEST_F(RegionCli, MergeRefusesAnOutputThatIsAlsoAPart) {
    const std::string size = "--width 40 --height 30 -q --region-output ";
    ASSERT_EQ(run_shell(cli + showcase + size + "--region 0,0,40,15 -o top.bmp").code, 0);
    ASSERT_EQ(run_shell(cli + showcase + size + "--region 0,15,40,30 -o bottom.bmp").code, 0);
    const std::string top = test::read_file(dir / "top.bmp");
    ProgramRun r = run_shell(merge + "-o ./top.bmp top.bmp bottom.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("is also a part (top.bmp)"), std::string::npos) << r.err;
    EXPECT_EQ(test::read_file(dir / "top.bmp"), top);
    EXPECT_EQ(run_shell(merge + "-o frame.bmp top.bmp bottom.bmp").code, 0);
    r = run_shell(merge + "-o '' top.bmp bottom.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("-o/--output: needs a file name"), std::string::npos) << r.err;
}

TEST_F(RegionCli, MergeWritesADashOutputToStandardOutput) {
    const std::string size = "--width 40 --height 30 -q ";
    ASSERT_EQ(run_shell(cli + showcase + size + "-o whole.bmp").code, 0);
    ASSERT_EQ(run_shell(cli + showcase + size + "--region-output --region 0,0,40,15 -o a.bmp").code,
              0);
    ASSERT_EQ(
        run_shell(cli + showcase + size + "--region-output --region 0,15,40,30 -o b.bmp").code, 0);
    ProgramRun r = run_shell(merge + "-q -o - a.bmp b.bmp | cat > piped.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "-"));
    EXPECT_EQ(test::read_file(dir / "piped.bmp"), test::read_file(dir / "whole.bmp"));
    // A failed write names standard output as the user did, not /dev/stdout.
    r = run_shell(merge + "-q -o - a.bmp b.bmp > /dev/full");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(r.err, "jtracer-merge: cannot write standard output: No space left on device\n");
}

// As jtracer-cli before a render: a frame that cannot be written is found
// before the parts (gigabytes, for a large frame) are read.
// As jtracer-cli: a frame is not written to a terminal, where it would be lost.
TEST_F(RegionCli, MergeRefusesATerminalAsItsOutput) {
    if (run_shell("command -v script").code != 0) GTEST_SKIP() << "no script(1) here";
    ASSERT_EQ(run_shell(cli + showcase +
                        "--width 8 --height 4 -q --region-output --region 0,0,8,4 -o a.bmp")
                  .code,
              0);
    ProgramRun r = run_shell("script -qec \"" + merge + "-o - a.bmp\" /dev/null");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("standard output is a terminal"), std::string::npos) << r.out;
}

// A glob such as band* picked up the temporary file a killed write left
// (band1.bmp.tmp-XXXXXX) and the merge failed on it as a truncated BMP; a
// part named twice under two spellings was reported as overlapping itself.
TEST_F(RegionCli, MergeNamesALeftoverTemporaryFileAndAPartGivenTwice) {
    const std::string size = "--width 16 --height 8 -q --region-output ";
    ASSERT_EQ(run_shell(cli + showcase + size + "--region 0,0,16,4 -o band0.bmp").code, 0);
    ASSERT_EQ(run_shell(cli + showcase + size + "--region 0,4,16,8 -o band1.bmp").code, 0);
    test::write_file(dir / "band1.bmp.tmp-a1B2c3", "BM");
    ProgramRun r = run_shell(merge + "-o frame.bmp band*");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("'band1.bmp.tmp-a1B2c3' is the temporary file of a write that never "
                         "finished"),
              std::string::npos)
        << r.err;
    r = run_shell(merge + "-o frame.bmp band0.bmp ./band0.bmp band1.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("'band0.bmp' and './band0.bmp' are the same file, given twice"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(exists("frame.bmp"));
    r = run_shell(merge + "-o frame.bmp band*.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
}

TEST_F(RegionCli, MergeFindsAnUnwritableFrameBeforeReadingTheParts) {
    ProgramRun r = run_shell(merge + "-o missing/frame.bmp no-such-part.bmp");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("cannot write 'missing/frame.bmp': No such file or directory; no part "
                         "was read"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("no-such-part.bmp"), std::string::npos) << r.err;
}

TEST_F(RegionCli, MergeRefusesPartsOfDifferentFrameSizes) {
    ASSERT_EQ(run_shell(cli + showcase +
                        "--width 40 --height 30 -q --region-output --region "
                        "0,0,40,15 -o a.bmp")
                  .code,
              0);
    ASSERT_EQ(run_shell(cli + showcase +
                        "--width 40 --height 31 -q --region-output --region "
                        "0,15,40,31 -o b.bmp")
                  .code,
              0);
    ProgramRun r = run_shell(merge + "-o out.bmp a.bmp b.bmp");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("b.bmp is a part of a 40x31 frame, but a.bmp of a 40x30 one"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(exists("out.bmp"));
}

// Parts of one frame size but of different renders merged into a frame
// with seams no message warned of: each part now carries a fingerprint of
// what it was rendered from, and the merge names both files and what differs.
TEST_F(RegionCli, MergeRefusesPartsOfDifferentRenders) {
    const std::string size = "--width 40 --height 30 -q --region-output ";
    const std::string top = "--region 0,0,40,15 -o top.bmp";
    ASSERT_EQ(run_shell(cli + showcase + size + top).code, 0);
    struct Case {
        std::string args, difference;
    };
    for (const Case& c : std::vector<Case>{
             {showcase + size + "--samples 2", "samples 2 and 1"},
             {showcase + size + "--clock 0.5", "clock 0.5 and 0"},
             {manual + size, "the scene's content differs"},
         }) {
        ASSERT_EQ(run_shell(cli + c.args + " --region 0,15,40,30 -o bottom.bmp").code, 0) << c.args;
        ProgramRun r = run_shell(merge + "-o out.bmp top.bmp bottom.bmp");
        EXPECT_EQ(r.code, 1) << c.args << ": " << r.err;
        EXPECT_NE(r.err.find("bottom.bmp and top.bmp are parts of different renders: "),
                  std::string::npos)
            << c.args << ": " << r.err;
        EXPECT_NE(r.err.find(c.difference), std::string::npos) << c.args << ": " << r.err;
        EXPECT_FALSE(exists("out.bmp")) << c.args;
    }
    // The same render, whatever else differs (threads, the part's name), merges.
    ASSERT_EQ(run_shell(cli + showcase + size + "--threads 1 --region 0,15,40,30 -o b2.bmp").code,
              0);
    ProgramRun r = run_shell(merge + "-o out.bmp top.bmp b2.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("note:"), std::string::npos) << r.err;
}

// Parts of two frames of an animation were said to differ first in the
// scene's content, "another scene, another version of it", when the clock
// that animates the scene was the difference.
TEST_F(RegionCli, MergeNamesTheClockFirstForPartsOfTwoFrames) {
    test::write_file(dir / "moving.jts", R"(
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1.3333; } }
scene { sphere { radius: 1 + clock; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } } }
render_settings { width: 8; height: 6; ambient_light: <1, 1, 1>; }
)");
    const std::string part = cli + "moving.jts -q --region-output --frames 2 ";
    ASSERT_EQ(run_shell(part + "--region 0,0,8,3 -o a%d.bmp").code, 0);
    ASSERT_EQ(run_shell(part + "--region 0,3,8,6 -o b%d.bmp").code, 0);
    ProgramRun r = run_shell(merge + "-o out.bmp a0.bmp b1.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("b1.bmp and a0.bmp are parts of different renders: clock 1 and 0; the "
                         "scene's content differs"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("...: the clock animates it, or another scene"), std::string::npos)
        << r.err;
    EXPECT_FALSE(exists("out.bmp"));
}

// The scene's content is its values once the defines are applied: another
// value is another render, the same value written otherwise is not.
TEST_F(RegionCli, MergeComparesTheSceneAfterItsDefines) {
    test::write_file(dir / "defined.jts", R"(
define r = 1;
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1.3333; } }
scene { sphere { radius: r; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } } }
render_settings { width: 8; height: 6; ambient_light: <1, 1, 1>; }
)");
    const std::string part = cli + "defined.jts -q --region-output ";
    ASSERT_EQ(run_shell(part + "--region 0,0,8,3 -o a.bmp").code, 0);
    ASSERT_EQ(run_shell(part + "--define r=1.5 --region 0,3,8,6 -o b.bmp").code, 0);
    ASSERT_EQ(run_shell(part + "--define r=2/2 --region 0,3,8,6 -o c.bmp").code, 0);
    ProgramRun r = run_shell(merge + "-o ab.bmp a.bmp b.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("the scene's content differs"), std::string::npos) << r.err;
    r = run_shell(merge + "-o ac.bmp a.bmp c.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
}

// Each value of a primitive counts, down to its finish and its transform, and
// a value's spelling does not: 0.5 and 1/2 are one render.
TEST_F(RegionCli, MergeComparesEveryValueOfAPrimitive) {
    test::write_file(dir / "valued.jts", R"(
define k = 0.5;
define m = 0;
define t = 0;
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1.3333; } }
scene {
    sphere { radius: 1; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; diffuse_k: k;
                                   map_size: 1 + m; }
             transform { xrotate: t; } }
}
render_settings { width: 8; height: 6; ambient_light: <1, 1, 1>; }
)");
    const std::string part = cli + "valued.jts -q --region-output ";
    ASSERT_EQ(run_shell(part + "--region 0,0,8,3 -o a.bmp").code, 0);
    for (const std::string define : {"k=0.25", "m=1", "t=1e-9"}) {
        ASSERT_EQ(run_shell(part + "--define " + define + " --region 0,3,8,6 -o b.bmp").code, 0);
        ProgramRun r = run_shell(merge + "-o ab.bmp a.bmp b.bmp");
        EXPECT_EQ(r.code, 1) << define << ": " << r.err;
        EXPECT_NE(r.err.find("the scene's content differs"), std::string::npos) << r.err;
    }
    ASSERT_EQ(run_shell(part + "--define k=1/2 --define t=0*5 --region 0,3,8,6 -o c.bmp").code, 0);
    ProgramRun r = run_shell(merge + "-o ac.bmp a.bmp c.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
}

// A file the scene names is part of what was rendered: an image map changed
// between two parts' renders is another render.
TEST_F(RegionCli, MergeRefusesPartsRenderedWithAChangedImageMap) {
    test::write_file(dir / "mapped.jts", R"(
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1.3333; } }
scene {
    plane { normal: <0, 0, 1>; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>;
                                          image_map: "map.bmp"; } }
}
render_settings { width: 8; height: 6; ambient_light: <1, 1, 1>; }
)");
    Image8 map(2, 2);
    ASSERT_TRUE(write_bmp(dir / "map.bmp", map));
    ASSERT_EQ(run_shell(cli + "mapped.jts -q --region-output --region 0,0,8,3 -o a.bmp").code, 0);
    map.pixel(0, 0)[0] = 200;
    ASSERT_TRUE(write_bmp(dir / "map.bmp", map));
    ProgramRun r = run_shell(cli + "mapped.jts -q --region-output --region 0,3,8,6 -o b.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    r = run_shell(merge + "-o out.bmp a.bmp b.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("the scene's content differs"), std::string::npos) << r.err;
}

// Parts written before the fingerprint (a version 1 record) still merge among
// themselves, with a note; mixed with fingerprinted ones they are refused.
TEST_F(RegionCli, PartsWithoutAFingerprintMergeAloneWithANote) {
    Image8 pixels(4, 1);
    ASSERT_TRUE(write_region_bmp(dir / "old0.bmp", pixels, {4, 2, {0, 0, 4, 1}}));
    ASSERT_TRUE(write_region_bmp(dir / "old1.bmp", pixels, {4, 2, {0, 1, 4, 2}}));
    ProgramRun r = run_shell(merge + "-o out.bmp old0.bmp old1.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("note: the parts carry no render fingerprint"), std::string::npos)
        << r.err;
    ASSERT_EQ(run_shell(cli + showcase +
                        "--width 4 --height 2 -q --region-output --region "
                        "0,1,4,2 -o new1.bmp")
                  .code,
              0);
    r = run_shell(merge + "-o mixed.bmp old0.bmp new1.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("old0.bmp carries no render fingerprint"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("render old0.bmp again"), std::string::npos) << r.err;
    EXPECT_FALSE(exists("mixed.bmp"));
}

// A region job array rerun with --skip-existing keeps a part only when it is
// this region of this render: a part of another render under the name (a
// stale part from an earlier version of the scene) is rendered again.
TEST_F(RegionCli, SkipExistingKeepsOnlyAPartOfThisRender) {
    const std::string part =
        cli + showcase + "--width 40 --height 30 --region-output --region 0,0,40,15 -o p.bmp ";
    ASSERT_EQ(run_shell(part + "-q --samples 2").code, 0);
    const std::string two_samples = test::read_file(dir / "p.bmp");
    ProgramRun r = run_shell(part + "--skip-existing");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find(
                  "p.bmp is there, but it is this region of another render (differing in samples)"),
              std::string::npos)
        << r.err;
    EXPECT_NE(test::read_file(dir / "p.bmp"), two_samples);
    r = run_shell(part + "--skip-existing");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("kept p.bmp: already there and complete"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("wrote"), std::string::npos) << r.err;
    // Another region under the name says so, and which region it holds.
    r = run_shell(cli + showcase +
                  "--width 40 --height 30 --region-output --region 0,15,40,30 -o p.bmp "
                  "--skip-existing");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("p.bmp is there, but it holds another region (0,0,40,15 of a 40x30 "
                         "frame)"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace jt
