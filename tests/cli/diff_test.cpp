// `jtracer-cli diff A B` and `jtracer-cli scene.jts --expect REF` end to end:
// identical, slightly different, different and unreadable images, the
// tolerance flags, the heat map and the exit codes (0 within, 1 outside,
// 2 usage, 3 I/O). Also the hidden --list-cameras the completions use.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include "jtracer/bmp.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/png.hpp"
#include "memory_cap.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace jt {
namespace {

using test::ProgramRun;

const std::string cli = "'" JT_CLI "'";

// A 40x20 gradient, so that every pixel differs from its neighbours.
Image8 gradient() {
    Image8 image(40, 20);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(6 * x);
            p[1] = static_cast<std::uint8_t>(12 * y);
            p[2] = static_cast<std::uint8_t>(100 + x + y);
        }
    return image;
}

// A scratch folder in which jtracer-cli runs; out() is the last run's stdout.
class CliFolder : public test::ScratchTest {
  protected:
    ProgramRun run(const std::string& line) {
        ProgramRun r = run_shell(line);
        last_out = r.out;
        return r;
    }
    const std::string& out() const { return last_out; }

  private:
    std::string last_out;
};

class Diff : public CliFolder {
  protected:
    void SetUp() override {
        ASSERT_TRUE(write_png(dir / "a.png", gradient()));
        ASSERT_TRUE(write_bmp(dir / "a.bmp", gradient()));
    }
    ProgramRun diff(const std::string& args) { return run(cli + " diff " + args); }
    void write_png_file(const std::string& name, const Image8& image) {
        ASSERT_TRUE(write_png(dir / name, image));
    }
};

TEST_F(Diff, IdenticalImagesInAnyMixOfFormats) {
    ProgramRun r = diff("a.png a.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
    const std::string text = out();
    EXPECT_NE(text.find("a.png: 40x20"), std::string::npos) << text;
    EXPECT_NE(text.find("a.bmp: 40x20"), std::string::npos) << text;
    EXPECT_NE(text.find("max channel difference: 0"), std::string::npos) << text;
    EXPECT_NE(text.find("pixels over threshold 0: 0 of 800 (0.0000%"), std::string::npos) << text;
    EXPECT_NE(text.find("mean absolute error: 0.0000"), std::string::npos) << text;
    EXPECT_NE(text.find("PSNR: inf"), std::string::npos) << text;
    EXPECT_NE(text.find("within the tolerance"), std::string::npos) << text;
}

TEST_F(Diff, SlightlyDifferentPassesOnlyWithinTheTolerance) {
    Image8 b = gradient();
    // 8 pixels (1% of 800) off by 2 in one channel, one pixel off by 6.
    for (int x = 0; x < 8; ++x) b.pixel(x, 3)[1] = static_cast<std::uint8_t>(b.pixel(x, 3)[1] + 2);
    b.pixel(20, 10)[2] = static_cast<std::uint8_t>(b.pixel(20, 10)[2] - 6);
    write_png_file("b.png", b);

    ProgramRun exact = diff("a.png b.png");
    EXPECT_EQ(exact.code, 1) << "exact by default";
    EXPECT_NE(out().find("max channel difference: 6"), std::string::npos) << out();
    EXPECT_NE(out().find("9 of 800 (1.1250%"), std::string::npos) << out();
    EXPECT_NE(out().find("OUTSIDE the tolerance"), std::string::npos) << out();
    // 22 channel levels over 2400 channels; PSNR = 10 log10(255^2 * 2400 / (8 * 4 + 36)).
    EXPECT_NE(out().find("mean absolute error: 0.0092"), std::string::npos) << out();
    EXPECT_NE(out().find("PSNR: 63.61 dB"), std::string::npos) << out();

    EXPECT_EQ(diff("a.png b.png --threshold 2").code, 1) << "the 6 is still over";
    EXPECT_NE(out().find("pixels over threshold 2: 1 of 800"), std::string::npos) << out();
    EXPECT_EQ(diff("a.png b.png --threshold 2 --max-pixels 0.125").code, 0) << out();
    EXPECT_EQ(diff("a.png b.png --threshold 6").code, 0) << out();
    EXPECT_EQ(diff("a.png b.png --max-pixels 1.2").code, 0) << out();
    EXPECT_EQ(diff("a.png b.png --max-pixels 1.1").code, 1) << out();
    EXPECT_EQ(diff("-q a.png b.png").code, 1);
    EXPECT_EQ(out(), "") << "--quiet";
}

TEST_F(Diff, HeatMapMarksTheDifferingPixels) {
    Image8 b = gradient();
    b.pixel(3, 4)[0] = static_cast<std::uint8_t>(b.pixel(3, 4)[0] + 40);
    write_png_file("b.png", b);
    ASSERT_EQ(diff("a.png b.png -o heat.png").code, 1);
    const Expected<Image8> read = read_image(dir / "heat.png");
    ASSERT_TRUE(read);
    const Image8& heat = *read;
    ASSERT_EQ(heat.width, 40);
    ASSERT_EQ(heat.height, 20);
    int marked = 0;
    for (int y = 0; y < heat.height; ++y)
        for (int x = 0; x < heat.width; ++x) {
            const std::uint8_t* p = heat.pixel(x, y);
            const bool grey = p[0] == p[1] && p[1] == p[2] && p[0] <= 85;
            if (!grey) {
                ++marked;
                EXPECT_EQ(x, 3);
                EXPECT_EQ(y, 4);
                EXPECT_EQ(p[0], 255) << "a heat colour";
            }
        }
    EXPECT_EQ(marked, 1);
    // Within the tolerance the heat map is still written (all grey).
    EXPECT_EQ(diff("a.png a.bmp -o same.bmp").code, 0);
    EXPECT_TRUE(exists("same.bmp"));
}

// The heat map is a PNG but for a .bmp name, as diff --help and the manual
// say: a name without an extension (or another) gave a BMP.
TEST_F(Diff, HeatMapIsAPngButForABmpName) {
    for (const auto& [name, magic] :
         std::vector<std::pair<std::string, std::string>>{{"heat", "\x89PNG"},
                                                          {"heat.map", "\x89PNG"},
                                                          {"heat.PNG", "\x89PNG"},
                                                          {"heat.bmp", "BM"},
                                                          {"heat.BMP", "BM"}}) {
        EXPECT_EQ(diff("a.png a.bmp -q -o " + name).code, 0) << name;
        EXPECT_EQ(test::read_file(dir / name).substr(0, magic.size()), magic) << name;
    }
}

// `-o -` wrote a file named "-" with the report on standard output beside
// it, where every other program's `-o -` is standard output.
TEST_F(Diff, ADashHeatMapIsStandardOutput) {
    Image8 b = gradient();
    b.pixel(3, 4)[0] = static_cast<std::uint8_t>(b.pixel(3, 4)[0] + 40);
    write_png_file("b.png", b);
    ProgramRun r = diff("a.png b.png -o - > heat.png");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_FALSE(exists("-"));
    // The report goes to stderr, out of the image's way.
    EXPECT_NE(r.err.find("OUTSIDE the tolerance"), std::string::npos) << r.err;
    const Expected<Image8> heat = read_png(dir / "heat.png");
    ASSERT_TRUE(heat) << heat.error().message;
    EXPECT_EQ(heat->width, 40);
    EXPECT_EQ(heat->pixel(3, 4)[0], 255);
    // A JUnit report names where the heat map went as the user did.
    r = diff("a.png b.png -o - --junit report.xml > heat2.png");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(test::read_file(dir / "report.xml").find("the differences are in standard output"),
              std::string::npos)
        << test::read_file(dir / "report.xml");
    // --json's object and the heat map cannot share standard output.
    r = diff("a.png b.png -o - --json > both.out");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("standard output cannot hold both the heat map and --json"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(test::read_file(dir / "both.out"), "");
    // A full device is named as the user named it.
    r = diff("a.png b.png -o - > /dev/full");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("cannot write standard output: No space left on device"),
              std::string::npos)
        << r.err;
}

// A JUnit report sent to standard output, however it is spelled, while the
// heat map or --json's object goes there too, would make one stream of two
// documents: refused before anything is read. The plain report comes first.
TEST_F(Diff, AJunitReportOnStandardOutputIsNotMixedWithAnotherDocument) {
    Image8 b = gradient();
    b.pixel(1, 1)[1] = static_cast<std::uint8_t>(b.pixel(1, 1)[1] + 30);
    write_png_file("b.png", b);
    for (const std::string junit : {"/dev/stdout", "/dev/fd/1"}) {
        ProgramRun r = diff("a.png b.png -o - --junit " + junit + " | cat > mixed.out");
        EXPECT_NE(r.err.find("--junit: '" + junit +
                             "' is standard output, which already carries the heat map (-o -)"),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(test::read_file(dir / "mixed.out"), "");
        r = diff("a.png b.png --json --junit " + junit + " | cat > mixed.out");
        EXPECT_NE(r.err.find("which already carries --json's object"), std::string::npos) << r.err;
        EXPECT_EQ(test::read_file(dir / "mixed.out"), "");
    }
    // The exit code of the program, not of the pipe's end.
    ProgramRun r =
        run("(" + cli + " diff a.png b.png -o - --junit /dev/stdout; echo $? > code) | cat");
    EXPECT_EQ(test::read_file(dir / "code"), "2\n") << r.err;
    r = diff("a.png b.png --junit /dev/stdout | cat > both.out");
    const std::string both = test::read_file(dir / "both.out");
    EXPECT_EQ(both.find("a.png: 40x20"), 0u) << both;
    EXPECT_NE(both.find("<?xml"), std::string::npos) << both;
    // Standard output sent to /dev/null mixes nothing.
    r = run(cli + " diff a.png b.png --json --junit /dev/null > /dev/null");
    EXPECT_EQ(r.code, 1) << r.err;
}

TEST_F(Diff, DifferentImagesAndDifferentSizes) {
    Image8 black(40, 20);
    write_png_file("black.png", black);
    EXPECT_EQ(diff("a.png black.png --threshold 255 --max-pixels 100").code, 0)
        << "everything tolerated";
    EXPECT_EQ(diff("a.png black.png --threshold 10").code, 1);
    EXPECT_NE(out().find("OUTSIDE"), std::string::npos) << out();

    write_png_file("small.png", Image8(20, 10));
    ProgramRun r = diff("a.png small.png -o heat.png --max-pixels 100");
    EXPECT_EQ(r.code, 1) << "sizes that differ never match";
    EXPECT_NE(out().find("small.png: 20x10"), std::string::npos) << out();
    EXPECT_NE(out().find("the sizes differ"), std::string::npos) << out();
    EXPECT_NE(r.err.find("no heat map"), std::string::npos) << r.err;
    EXPECT_FALSE(exists("heat.png"));
}

TEST_F(Diff, UnreadableImagesAreIoErrors) {
    std::ofstream(dir / "junk.png") << "not an image at all";
    ProgramRun r = diff("a.png junk.png");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("junk.png"), std::string::npos) << r.err;
    r = diff("missing.bmp a.png");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("missing.bmp"), std::string::npos) << r.err;
    r = diff("a.png a.bmp -o no/such/dir/heat.png");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("no/such/dir/heat.png"), std::string::npos) << r.err;
}

// A device never ends: read whole, /dev/zero took all the memory there was.
// The limits keep the test from doing the same should that come back.
TEST_F(Diff, DevicesAreRefusedAtOnce) {
    const std::string limits = std::string(test::memory_cap) + "timeout 60 ";
    for (const std::string args : {"/dev/zero a.png", "a.png /dev/urandom"}) {
        ProgramRun r = run(limits + cli + " diff " + args);
        EXPECT_EQ(r.code, 3) << args << ": " << r.err;
        EXPECT_NE(r.err.find("it is a device, not a file"), std::string::npos)
            << args << ": " << r.err;
    }
    // A pipe is read to its end.
    ProgramRun r = run("cat a.png | " + cli + " diff /dev/stdin a.bmp");
    EXPECT_EQ(r.code, 0) << r.err;
}

// A file larger than any image is refused by its size, at once: read whole,
// a 6 GB sparse file took 6 GB of memory and seconds before "too large".
TEST_F(Diff, AFileLargerThanAnyImageIsRefusedByItsSize) {
    std::filesystem::resize_file(dir / "a.png", 0);
    std::filesystem::resize_file(dir / "a.png", std::uintmax_t{6} << 30);
    ProgramRun r = run(std::string(test::memory_cap) + "timeout 60 " + cli + " diff a.png a.bmp");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("'a.png': it is 6442450944 bytes, larger than any image"),
              std::string::npos)
        << r.err;
}

// A file cut short (an interrupted copy or download) or empty says so, in
// words: stb's "outofdata", and "no 'BM' header" for a BMP whose header is
// there but short, or for an empty file read as a PNG, said otherwise.
TEST_F(Diff, DamagedImagesSayWhatIsWrong) {
    const std::string png = test::read_file(dir / "a.png");
    const std::string bmp = test::read_file(dir / "a.bmp");
    test::write_file(dir / "cut.png", png.substr(0, png.size() / 2));
    test::write_file(dir / "cut.bmp", bmp.substr(0, 2));
    test::write_file(dir / "empty.bmp", "");
    test::write_file(dir / "text.bmp", "scene { }\n");
    const std::pair<const char*, const char*> cases[] = {
        {"cut.png",
         "'cut.png': not a readable PNG: its data ends early (the file is truncated "
         "or damaged)"},
        {"cut.bmp", "'cut.bmp': BMP file is truncated: 2 bytes, fewer than its headers take"},
        {"empty.bmp", "'empty.bmp': the file is empty"},
        {"text.bmp", "'text.bmp': not a BMP file (no 'BM' header)"},
    };
    for (const auto& [name, message] : cases) {
        ProgramRun r = diff(std::string(name) + " a.png");
        EXPECT_EQ(r.code, 3) << name << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << name << ": " << r.err;
    }
}

TEST_F(Diff, UsageErrors) {
    EXPECT_EQ(diff("a.png").code, 2);
    EXPECT_EQ(diff("a.png a.bmp --threshold 256").code, 2);
    EXPECT_EQ(diff("a.png a.bmp --max-pixels -1").code, 2);
    ProgramRun r = diff("a.png a.bmp --bogus");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("jtracer-cli diff --help"), std::string::npos) << r.err;
    EXPECT_EQ(diff("--help").code, 0);
    EXPECT_NE(out().find("Exit codes"), std::string::npos) << out();
}

// A file written over an image compared would lose it: a heat map over the
// reference makes every later comparison against a heat map.
TEST_F(Diff, RefusesToWriteOverTheImagesItCompares) {
    write_png_file("b.png", gradient());
    const std::string before = test::read_file(dir / "a.png");
    for (const std::string args :
         {"a.png b.png -o a.png", "a.png b.png -o ./b.png", "a.png b.png --junit a.png",
          "a.png b.png --junit b.png", "a.png b.png -o h.png --junit h.png"}) {
        ProgramRun r = diff(args);
        EXPECT_EQ(r.code, 2) << args << ": " << r.err;
        EXPECT_NE(r.err.find("would be replaced"), std::string::npos) << args << ": " << r.err;
    }
    EXPECT_EQ(test::read_file(dir / "a.png"), before);
    EXPECT_FALSE(exists("h.png"));
    // A device is written in place and replaces nothing: it may be both.
    ProgramRun r = diff("a.png b.png -o /dev/null --junit /dev/null -q");
    EXPECT_EQ(r.code, 0) << r.err;
}

const std::string scene = R"(
render_settings { width: 24; height: 16; filename: "render.bmp"; }
cameras {
    perspective_camera { name: "Main"; position: <0, 1, 5>; look_at: <0, 0.5, 0>; aspect: 1.5; }
    perspective_camera { name: "High Angle"; position: <0, 6, 0.1>; look_at: <0, 0, 0>; aspect: 1.5; }
}
scene {
    sphere { center: <0, 0.8, 0>; radius: 0.8; material { pigment: <1, 0.2, 0.1>; diffuse: <1, 1, 1>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)";

class Expect : public CliFolder {
  protected:
    void SetUp() override {
        test::write_file(dir / "scene.jts", scene);
        ASSERT_EQ(run(cli + " -q scene.jts -o ref.png").code, 0);
        Expected<Image8> read = read_image(dir / "ref.png");
        ASSERT_TRUE(read);
        reference = *read;
    }
    Image8 reference;
};

TEST_F(Expect, MatchingRenderExitsZero) {
    ProgramRun r = run(cli + " scene.jts -o out.png --expect ref.png");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("matches ref.png"), std::string::npos) << r.err;
    EXPECT_TRUE(exists("out.png"));
    EXPECT_FALSE(exists("out.diff.png"));
}

TEST_F(Expect, DifferingRenderWritesTheRenderAndTheDifferences) {
    Image8 changed = reference;
    for (int x = 0; x < 6; ++x)
        changed.pixel(x, 0)[1] = static_cast<std::uint8_t>(changed.pixel(x, 0)[1] ^ 0x40);
    ASSERT_TRUE(write_png(dir / "changed.png", changed));
    ProgramRun r = run(cli + " scene.jts -o out/render.png --expect changed.png");
    EXPECT_EQ(r.code, 3) << "the folder for the render does not exist: " << r.err;
    std::filesystem::create_directory(dir / "out");
    r = run(cli + " scene.jts -o out/render.png --expect changed.png");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("differs from changed.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("6 of 384"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("out/render.diff.png"), std::string::npos) << r.err;
    const Expected<Image8> render = read_image(dir / "out/render.png");
    ASSERT_TRUE(render);
    EXPECT_EQ(*render, reference);
    const Expected<Image8> heat = read_image(dir / "out/render.diff.png");
    ASSERT_TRUE(heat);
    EXPECT_EQ(heat->width, 24);
    // Tolerated: 6 of 384 pixels is 1.5625%.
    EXPECT_EQ(
        run(cli + " -q scene.jts -o out/render.png --expect changed.png --max-pixels 1.6").code, 0);
    EXPECT_EQ(run(cli + " -q scene.jts -o out/render.png --expect changed.png --threshold 64").code,
              0);
}

// A render sent to a device, to be compared and not kept, has no folder to
// keep a heat map beside it: /dev/null.diff.png would be a file in /dev.
TEST_F(Expect, ARenderToADeviceHasNoHeatMap) {
    Image8 changed = reference;
    changed.pixel(0, 0)[0] = static_cast<std::uint8_t>(changed.pixel(0, 0)[0] ^ 0x40);
    ASSERT_TRUE(write_png(dir / "changed.png", changed));
    ProgramRun r = run(cli + " scene.jts -o /dev/null --expect changed.png");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("differs from changed.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the render went to /dev/null, which has no folder to keep a heat map "
                         "beside it: none was written"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists("/dev/null.diff.png"));
    EXPECT_EQ(run(cli + " -q scene.jts -o /dev/null --expect ref.png").code, 0);
    // Through a pipe, named as the user named it.
    r = run(cli + " scene.jts -o - --expect changed.png | cat > /dev/null");
    EXPECT_NE(r.err.find("the render went to standard output, which has no folder"),
              std::string::npos)
        << r.err;
}

// `-o /dev/stdout > out.png` writes out.png through a link; its heat map goes
// beside it, not into /dev.
TEST_F(Expect, AHeatMapGoesBesideTheFileALinkNames) {
    Image8 changed = reference;
    changed.pixel(0, 0)[0] = static_cast<std::uint8_t>(changed.pixel(0, 0)[0] ^ 0x40);
    ASSERT_TRUE(write_png(dir / "changed.png", changed));
    std::filesystem::create_directory(dir / "renders");
    std::filesystem::create_symlink("renders/out.png", dir / "link.png");
    ProgramRun r = run(cli + " -q scene.jts -o link.png --expect changed.png");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_TRUE(read_image(dir / "renders/out.png").has_value());
    EXPECT_TRUE(read_image(dir / "renders/out.diff.png").has_value()) << r.err;
    EXPECT_FALSE(exists("link.diff.png"));
    // `-o - > out.png`: the heat map beside out.png, and the render named as
    // the user named it, in the messages and the JUnit report alike.
    r = run(cli + " -q scene.jts -o - --expect changed.png --junit report.xml > piped.png");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_TRUE(read_image(dir / "piped.diff.png").has_value()) << r.err;
    EXPECT_NE(r.err.find("the render is in standard output, the differences in "),
              std::string::npos)
        << r.err;
    const std::string report = test::read_file(dir / "report.xml");
    EXPECT_NE(report.find("actual standard output"), std::string::npos) << report;
    EXPECT_EQ(report.find("/dev/stdout"), std::string::npos) << report;
}

// Only a render outside the tolerance has a heat map beside it: one left by
// an earlier failing run goes once the render matches again, or CI keeping
// out/ would show a failure that is no more.
TEST_F(Expect, AHeatMapOfAnEarlierRunGoesOnceTheRenderMatches) {
    Image8 changed = reference;
    changed.pixel(0, 0)[0] = static_cast<std::uint8_t>(changed.pixel(0, 0)[0] ^ 0x80);
    ASSERT_TRUE(write_png(dir / "changed.png", changed));
    ASSERT_EQ(run(cli + " -q scene.jts -o out.png --expect changed.png").code, 1);
    ASSERT_TRUE(exists("out.diff.png"));
    ProgramRun r = run(cli + " scene.jts -o out.png --expect ref.png");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(exists("out.diff.png"));
    EXPECT_NE(r.err.find("removed out.diff.png, the heat map of an earlier run"), std::string::npos)
        << r.err;
    // --update, and a size that differs (which draws none), remove it too.
    ASSERT_EQ(run(cli + " -q scene.jts -o out.png --expect changed.png").code, 1);
    EXPECT_EQ(run(cli + " -q scene.jts -o out.png --expect changed.png --update").code, 0);
    EXPECT_FALSE(exists("out.diff.png"));
    ASSERT_TRUE(write_png(dir / "changed.png", changed));
    ASSERT_EQ(run(cli + " -q scene.jts -o out.png --expect changed.png").code, 1);
    EXPECT_EQ(run(cli + " -q scene.jts --width 12 -o out.png --expect changed.png").code, 1);
    EXPECT_FALSE(exists("out.diff.png"));
}

TEST_F(Expect, SizeMismatchMissingReferenceAndMisuse) {
    ProgramRun r = run(cli + " scene.jts --width 48 -o big.png --expect ref.png");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("48x16"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("24x16"), std::string::npos) << r.err;
    r = run(cli + " scene.jts -o out.png --expect missing.png");
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
    EXPECT_EQ(run(cli + " scene.jts --threshold 2").code, 2) << "needs --expect";
    EXPECT_EQ(run(cli + " scene.jts --check --expect ref.png").code, 2);
    EXPECT_EQ(run(cli + " scene.jts --region 0,0,4,4 --expect ref.png").code, 2);
}

// A render written over its own reference always "matches": a CI job so
// misconfigured would pass whatever the renderer does. The scene file, the
// reference and the report must each stay what they are.
TEST_F(Expect, RefusesOutputsThatWouldReplaceTheSceneOrTheReference) {
    const std::string scene_text = test::read_file(dir / "scene.jts");
    const std::string reference_bytes = test::read_file(dir / "ref.png");
    struct Case {
        std::string args, message;
    };
    for (const Case& c : std::vector<Case>{
             {"scene.jts -o scene.jts", "is the scene file itself"},
             {"scene.jts -o ./scene.jts --width 8", "is the scene file itself"},
             {"scene.jts -o ref.png --expect ref.png", "is the reference given to --expect"},
             {"scene.jts -o ../" + dir.filename().string() + "/ref.png --expect ref.png --update",
              "is the reference given to --expect"},
             {"scene.jts -o new.png --expect new.png", "is the reference given to --expect"},
             {"scene.jts -o out.png --expect out.diff.png", "is where the heat map"},
             {"scene.jts -o out.png --expect ref.png --junit scene.jts", "is the scene file"},
             {"scene.jts --expect ref.png --junit ref.png", "is the reference given"},
             {"scene.jts -o out.png --expect ref.png --junit out.png", "is the image"},
         }) {
        ProgramRun r = run(cli + " " + c.args);
        EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    }
    EXPECT_EQ(test::read_file(dir / "scene.jts"), scene_text);
    EXPECT_EQ(test::read_file(dir / "ref.png"), reference_bytes);
    EXPECT_FALSE(exists("new.png"));
    EXPECT_FALSE(exists("out.png"));

    // The scene's own filename is checked once the scene is read.
    std::string self = scene;
    self.replace(self.find("render.bmp"), 10, "self.jts");
    test::write_file(dir / "self.jts", self);
    ProgramRun r = run(cli + " self.jts");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("the scene's filename 'self.jts' is the scene file itself"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(test::read_file(dir / "self.jts"), self);
    r = run(cli + " scene.jts --expect render.bmp");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("the scene's filename 'render.bmp' is the reference"), std::string::npos)
        << r.err;
    EXPECT_FALSE(exists("render.bmp"));
}

// As `diff` refuses --junit naming its -o: the report would be written over
// the heat map it points to.
TEST_F(Expect, RefusesAJunitReportOnTheStandardOutputThatCarriesTheImage) {
    ProgramRun r = run("(" + cli +
                       " -q scene.jts -o - --expect ref.png --junit /dev/stdout; echo $? > code)"
                       " | cat > m.out");
    EXPECT_EQ(test::read_file(dir / "code"), "2\n") << r.err;
    EXPECT_NE(r.err.find("is standard output, which already carries the image (-o -)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(test::read_file(dir / "m.out"), "");
}

TEST_F(Expect, RefusesAJunitReportThatIsTheHeatMap) {
    Image8 changed = reference;
    changed.pixel(0, 0)[0] = static_cast<std::uint8_t>(changed.pixel(0, 0)[0] ^ 0x80);
    ASSERT_TRUE(write_png(dir / "changed.png", changed));
    ProgramRun r = run(cli + " scene.jts -o out.png --expect changed.png --junit out.diff.png");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("where the heat map"), std::string::npos) << r.err;
    EXPECT_FALSE(exists("out.png")) << "refused before anything is written";
    EXPECT_FALSE(exists("out.diff.png"));
}

// A render that failed after a while is reported with the time it ran, as
// a passed or failed one is: a CI page that charts the times showed an hour's
// render stopped by the job's time limit as 0.000 s.
TEST_F(Expect, AFailedRenderReportsTheTimeItRan) {
    // One thread and many samples of the showcase: interrupted once its
    // progress log says it has rendered a tenth (a signal at a fixed time
    // could come before the render started, on a machine that is slow or
    // busy), so that the render ran for a while when it failed. SIGTERM, as
    // a job's time limit sends: a shell starts a background command with
    // SIGINT ignored, and an ignored signal stays ignored.
    ProgramRun r = run(cli + " '" JT_SOURCE_DIR
                             "/scenes/showcase.jts' -o out.png --samples 64 --threads 1 "
                             "--progress log --expect ref.png --junit report.xml 2> progress.txt & "
                             "pid=$!; for i in $(seq 1200); do "
                             "grep -q 'rendering:' progress.txt && break; sleep 0.1; done; "
                             "kill -TERM $pid; wait $pid");
    ASSERT_EQ(r.code, 143) << r.err;
    const std::string report = test::read_file(dir / "report.xml");
    const std::size_t at = report.find("<testcase ");
    ASSERT_NE(at, std::string::npos) << report;
    const std::size_t time = report.find("time=\"", at);
    ASSERT_NE(time, std::string::npos) << report;
    const double seconds = std::stod(report.substr(time + 6));
    EXPECT_GT(seconds, 0.2) << report;
    EXPECT_LT(seconds, 200.0) << report;
    EXPECT_NE(report.find("interrupted by SIGTERM"), std::string::npos) << report;
}

TEST_F(Expect, ListCamerasPrintsTheNamesOneALine) {
    ASSERT_EQ(run(cli + " --list-cameras scene.jts").code, 0);
    EXPECT_EQ(out(), "Main\nHigh Angle\n");
    // A scene with errors still lists the cameras it has.
    std::ofstream(dir / "broken.jts") << scene << "\nscene { sphere { radius: ; } }\n";
    ASSERT_EQ(run(cli + " --list-cameras broken.jts").code, 0);
    EXPECT_EQ(out(), "Main\nHigh Angle\n");
    EXPECT_EQ(run(cli + " --list-cameras missing.jts").code, 3);
    // Hidden from --help.
    ASSERT_EQ(run(cli + " --help").code, 0);
    EXPECT_EQ(out().find("list-cameras"), std::string::npos);
}

// What the completions of --define offer: the names the scene defines, in
// file order, not its named materials, also when the scene has errors.
TEST_F(Expect, ListDefinesPrintsTheDefinedNamesOneALine) {
    std::ofstream(dir / "named.jts")
        << "define r = 2;\n# define commented = 1;\nmaterial shiny { reflection: 0.5; }\n"
           "define colour_1 = <1, 0, 0> * r;\ndefine out = \"x.png\";\n"
        << scene << "\nscene { sphere { radius: ; } }\n";
    ASSERT_EQ(run(cli + " --list-defines named.jts").code, 0);
    EXPECT_EQ(out(), "r\ncolour_1\nout\n");
    EXPECT_EQ(run(cli + " --list-defines missing.jts").code, 3);
    ASSERT_EQ(run(cli + " --help").code, 0);
    EXPECT_EQ(out().find("list-defines"), std::string::npos);
}

}  // namespace
}  // namespace jt
