// The CLI under hard resource limits, as a shared or locked-down machine
// imposes them: an address space of 1 GiB (ulimit -v), 32 open files (ulimit
// -n), an output folder on a read-only file system. Each gives a clear message
// and exit 3 with nothing written, or works; never a crash. Release builds
// only: the sanitizers reserve terabytes of address space, so ulimit -v
// cannot apply to them (CMakeLists.txt).

#include "cli_sandbox.hpp"

#include "jtracer/bmp.hpp"

#include <unistd.h>

#include <fstream>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

constexpr long address_space_kib = 1024 * 1024;  // 1 GiB

class ResourceLimits : public CliSandbox {
  protected:
    // jtracer-cli in `dir` under `limits` (shell ulimit options).
    ProgramRun run_limited(const std::string& limits, const std::string& args) const {
        return run_shell("ulimit " + limits + " && exec '" JT_CLI "' " + args);
    }
    ProgramRun run_in_one_gib(const std::string& args) const {
        return run_limited("-v " + std::to_string(address_space_kib), args);
    }
    // Exit 3 with one line that says `message`, and no file written.
    void expect_out_of_memory(const ProgramRun& r, const std::string& message) const {
        EXPECT_EQ(r.signal, 0) << r.err;
        EXPECT_EQ(r.code, 3) << r.err;
        EXPECT_EQ(r.err.rfind("jtracer-cli: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected: " << r.err;
        EXPECT_FALSE(exists("out.bmp"));
        EXPECT_TRUE(temporary_files().empty());
    }
};

TEST_F(ResourceLimits, TenMillionPrimitivesInOneGibAreOutOfMemory) {
    // The shortest sphere the language has (every property defaulted), 90 MB of text.
    {
        std::ofstream out(dir / "huge.jts", std::ios::binary);
        out << "render_settings { width: 32; height: 18; }\n"
               "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n"
               "scene {\n";
        const std::string block = [] {
            std::string lines;
            for (int i = 0; i < 1000; ++i) lines += "sphere{}\n";
            return lines;
        }();
        for (int i = 0; i < 10'000; ++i) out << block;
        out << "}\n";
    }
    ProgramRun r = run_in_one_gib("huge.jts -q -o out.bmp");
    fs::remove(dir / "huge.jts");
    expect_out_of_memory(r, "cannot read 'huge.jts': out of memory (the scene is too large");
}

TEST_F(ResourceLimits, ImageAtTheSizeLimitInOneGibIsRefusedBeforeRendering) {
    // The largest frame a BMP holds (65535 x 21845 is 4 GiB of pixels), with the
    // most samples: refused from its size before anything is allocated.
    for (const char* samples : {"1", "1024"}) {
        SCOPED_TRACE(samples);
        ProgramRun r = run_in_one_gib("scene.jts --width 65535 --height 21845 --samples " +
                                      std::string(samples) + " -q -o out.bmp");
        expect_out_of_memory(r, "of memory, more than the 1.0 GiB available");
        EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
    }
}

TEST_F(ResourceLimits, PictureClaimingTenBillionTexelsIsRefusedFromItsHeaderInOneGib) {
    const std::string picture = "claims-100000x100000.png";
    fs::copy_file(fs::path(JT_SOURCE_DIR) / "tests/hardening/regressions/image_map" / picture,
                  dir / picture);
    write_file(dir / "map.jts",
               "render_settings { width: 8; height: 8; }\n"
               "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n"
               "scene { sphere { material { image_map: \"" +
                   picture + "\"; } } }\n");
    ProgramRun r = run_in_one_gib("map.jts -o out.bmp");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(
        r.err.rfind("map.jts:3:40: error: image_map: '" + picture + "': the image is too large", 0),
        0u)
        << r.err;
    EXPECT_FALSE(exists("out.bmp"));
}

TEST_F(ResourceLimits, MeshOfSixMillionTrianglesInOneGibIsOutOfMemory) {
    // 48 MB of OBJ; Assimp alone needs over 1 GiB for it.
    {
        std::ofstream out(dir / "huge.obj", std::ios::binary);
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        const std::string faces = [] {
            std::string block;
            for (int i = 0; i < 1000; ++i) block += "f 1 2 3\n";
            return block;
        }();
        for (int i = 0; i < 6000; ++i) out << faces;
    }
    write_file(dir / "mesh.jts",
               "render_settings { width: 8; height: 8; }\n"
               "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n"
               "scene { mesh { file: \"huge.obj\"; } }\n");
    ProgramRun r = run_in_one_gib("mesh.jts -o out.bmp");
    fs::remove(dir / "huge.obj");
    expect_out_of_memory(r, "out of memory");
    EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
}

TEST_F(ResourceLimits, TwoThousandCopiesOfOneModelRenderInOneGib) {
    // 40 million triangles if each copy had its own; one model instanced 2000
    // times takes about what one copy does.
    fs::copy_file(fs::path(JT_SOURCE_DIR) / "scenes/models/knot.ply", dir / "knot.ply");
    std::string scene =
        "render_settings { width: 64; height: 36; ambient_light: <0.3, 0.3, 0.3>; }\n"
        "cameras { perspective_camera { position: <0, 0, 60>; look_at: <0, 0, 0>; "
        "aspect: 1.7777777777777777; } }\n"
        "scene { point_light { position: <10, 10, 80>; intensity: <1, 1, 1>; }\n";
    for (int i = 0; i < 2000; ++i)
        scene +=
            "mesh { file: \"knot.ply\"; material { pigment: <1, 0.6, 0.2>; ambient: "
            "<0.3, 0.3, 0.3>; } transform { scale: <0.3, 0.3, 0.3>; translate: <" +
            std::to_string(i % 50 - 25) + ", " + std::to_string(i / 50 - 20) + ", 0>; } }\n";
    write_file(dir / "copies.jts", scene + "}\n");
    ProgramRun r = run_in_one_gib("copies.jts -q -o out.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    const Expected<Image8> image = read_bmp(dir / "out.bmp");
    ASSERT_TRUE(image) << image.error().message;
    int lit = 0;  // pixels where a knot is
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x) lit += image->pixel(x, y)[0] > 0;
    EXPECT_GT(lit, image->width * image->height / 10);
}

TEST_F(ResourceLimits, ThirtyTwoOpenFilesAreEnoughForAScenePastThatManyImageMaps) {
    // 40 pictures, each opened, read and closed once.
    std::string scene =
        "render_settings { width: 64; height: 36; }\n"
        "cameras { perspective_camera { position: <0, 0, 30>; look_at: <0, 0, 0>; } }\n"
        "scene { point_light { position: <0, 10, 30>; intensity: <1, 1, 1>; }\n";
    for (int i = 0; i < 40; ++i) {
        Image8 picture(2, 2);
        picture.pixel(i % 2, 0)[0] = static_cast<std::uint8_t>(6 * i);
        const std::string name = "map" + std::to_string(i) + ".bmp";
        ASSERT_TRUE(write_bmp(dir / name, picture));
        scene += "sphere { center: <" + std::to_string(i % 8 * 3 - 10) + ", " +
                 std::to_string(i / 8 * 3 - 6) + ", 0>; material { image_map: \"" + name +
                 "\"; } }\n";
    }
    write_file(dir / "maps.jts", scene + "}\n");
    ProgramRun free_run = run({"maps.jts", "-q", "-o", "free.bmp"});
    ASSERT_EQ(free_run.code, 0) << free_run.err;
    ProgramRun r = run_limited("-n 32", "maps.jts -q -o limited.bmp");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(read_file(dir / "limited.bmp"), read_file(dir / "free.bmp"));
}

TEST_F(ResourceLimits, OutputOnAReadOnlyFileSystemIsAnIoError) {
    // A read-only mount exists only inside a private mount namespace of the
    // command, so nothing is left mounted whatever happens.
    if (::getuid() != 0) GTEST_SKIP() << "mounting a read-only file system needs root";
    fs::create_directory(dir / "readonly");
    const std::string mount =
        "unshare --mount --propagation private sh -c '"
        "mount -t tmpfs -o ro tmpfs readonly && exec \"$0\" \"$@\"' ";
    ProgramRun probe = run_shell(mount + "true");
    if (probe.code != 0) GTEST_SKIP() << "cannot mount a file system here: " << probe.err;
    ProgramRun r = run_shell(mount + "'" JT_CLI "' scene.jts -o readonly/out.bmp");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(r.err.rfind("jtracer-cli: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("'readonly/out.bmp'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Read-only file system"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line expected: " << r.err;
    EXPECT_TRUE(fs::is_empty(dir / "readonly"));
}

}  // namespace
}  // namespace jt::test
