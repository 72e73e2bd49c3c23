// The model reader is a module (core/scene/src/io/model_reader.hpp) that
// jtracer-cli opens on the first mesh: a scene without one renders when the
// module cannot be found, and one with a mesh fails at the mesh's file string
// with why the module did not load, exit code 1, no image.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt {
namespace {

namespace fs = std::filesystem;

const std::string kWithoutMesh = R"(render_settings { width: 4; height: 4; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }
scene {
    sphere { radius: 1; material { pigment: <1, 0, 0>; diffuse: <1, 1, 1>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)";

const std::string kWithMesh = R"(render_settings { width: 4; height: 4; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }
scene {
    mesh {
        file: "quad.obj";
        material { pigment: <1, 0, 0>; diffuse: <1, 1, 1>; }
    }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
)";

class ModelReaderModule : public test::ScratchTest {
  protected:
    void SetUp() override {
        test::write_file(dir / "without.jts", kWithoutMesh);
        test::write_file(dir / "with.jts", kWithMesh);
        test::write_file(dir / "quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
        // A copy of the program whose RUNPATH leads nowhere from its new place.
        fs::create_directories(dir / "elsewhere/bin");
        fs::copy_file(JT_CLI, dir / "elsewhere/bin/jtracer-cli");
    }

    // The copy, with `library_path` as LD_LIBRARY_PATH and `fake_version` as
    // JT_FAKE_VERSION (fake_model_reader.cpp) when given.
    test::ProgramRun run_copy(const std::string& scene, const std::string& library_path = "",
                              const std::string& fake_version = "") {
        std::string line = library_path.empty() ? "" : "LD_LIBRARY_PATH='" + library_path + "' ";
        if (!fake_version.empty()) line += "JT_FAKE_VERSION='" + fake_version + "' ";
        return run_shell(line + "elsewhere/bin/jtracer-cli -q " + scene + " -o out.bmp");
    }

    // The error line of a run on with.jts, at the mesh's file string.
    void expect_error_at_file(const test::ProgramRun& r, const std::string& reason) {
        EXPECT_EQ(r.code, 1) << r.err;
        EXPECT_EQ(r.signal, 0) << r.err;
        EXPECT_NE(r.err.find("with.jts:5:15: error: mesh 1: cannot load the model reader"),
                  std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "out.bmp"));
    }
};

TEST_F(ModelReaderModule, TheProgramFindsItInTheBuildTree) {
    EXPECT_EQ(run_shell("'" JT_CLI "' -q with.jts -o out.bmp").code, 0);
    EXPECT_TRUE(fs::exists(dir / "out.bmp"));
}

TEST_F(ModelReaderModule, AProgramWithoutItRendersASceneWithoutAMesh) {
    const test::ProgramRun r = run_copy("without.jts");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "out.bmp"));
}

TEST_F(ModelReaderModule, AMissingOneIsAnErrorAtTheMeshsFile) {
    const test::ProgramRun r = run_copy("with.jts");
    expect_error_at_file(r, ": libjtracer_model_reader.so is in none of the folders searched (" +
                                (dir / "elsewhere/core/scene").string());
    // Not the working folder, which CMake's padding of a RUNPATH would name.
    EXPECT_EQ(r.err.find(", ."), std::string::npos) << r.err;
}

TEST_F(ModelReaderModule, ABrokenOneIsAnErrorAtTheMeshsFile) {
    fs::create_directories(dir / "broken");
    test::write_file(dir / "broken/libjtracer_model_reader.so", std::string(100, 'x'));
    expect_error_at_file(
        run_copy("with.jts", (dir / "broken").string()),
        ": " + (dir / "broken/libjtracer_model_reader.so").string() + ": invalid ELF header");
}

TEST_F(ModelReaderModule, OneOfAnotherVersionIsAnErrorAtTheMeshsFile) {
    fs::create_directories(dir / "other");
    fs::copy_file(JT_FAKE_MODEL_READER, dir / "other/libjtracer_model_reader.so");
    expect_error_at_file(run_copy("with.jts", (dir / "other").string(), "0.0.1"),
                         "libjtracer_model_reader.so: it is from JTracer 0.0.1, this program "
                         "from " JT_VERSION_STRING "\n");
}

TEST_F(ModelReaderModule, OneOfTheSameVersionWithOtherTypesIsAnErrorAtTheMeshsFile) {
    fs::create_directories(dir / "other");
    fs::copy_file(JT_FAKE_MODEL_READER, dir / "other/libjtracer_model_reader.so");
    expect_error_at_file(
        run_copy("with.jts", (dir / "other").string()),
        "libjtracer_model_reader.so: it is from another build of JTracer " JT_VERSION_STRING
        " (its types differ from this program's)\n");
}

}  // namespace
}  // namespace jt
