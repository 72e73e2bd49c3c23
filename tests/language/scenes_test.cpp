// Every scene under scenes/ parses and validates without a single diagnostic,
// and survives a serialize/parse round trip unchanged.

#include "jtracer/scene_file.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/source_serializer.hpp"
#include "jtracer/validate.hpp"

#include "test_util.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <tuple>

namespace jt {
namespace {

std::vector<std::filesystem::path> scene_files() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(
             std::filesystem::path(JT_SOURCE_DIR) / "scenes")) {
        // A `parts` folder holds files that scenes include, not scenes.
        if (entry.is_regular_file() && entry.path().extension() == ".jts" &&
            entry.path().parent_path().filename() != "parts")
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(Scenes, ThereAreTheShowcaseAndEveryManualExample) {
    auto files = scene_files();
    EXPECT_GE(files.size(), 19u);
    EXPECT_TRUE(
        std::filesystem::exists(std::filesystem::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts"));
}

TEST(Scenes, EveryFileParsesAndValidatesWithNoDiagnostics) {
    for (const auto& path : scene_files()) {
        const Expected<LoadedScene> read = load_scene_file(path);
        ASSERT_TRUE(read) << read.error().message;
        const LoadedScene& loaded = *read;
        auto diagnostics = check_scene(loaded);
        EXPECT_EQ(format_diagnostics(diagnostics, loaded), "");
        const Scene& s = loaded.parsed.scene;
        EXPECT_FALSE(s.cameras.empty()) << path;
        EXPECT_GT(s.settings.width, 0) << path;
        EXPECT_FALSE(s.lights.empty()) << path;
        EXPECT_FALSE(s.primitives.empty()) << path;
    }
}

TEST(Scenes, EveryFileRoundTripsThroughTheSerializer) {
    for (const auto& path : scene_files()) {
        const LoadedScene loaded = load_scene_file(path).value();
        std::string text = serialize_scene(loaded.parsed.scene);
        ParseResult again = parse_scene(text);
        EXPECT_EQ(test::brief(again.diagnostics), "") << path << "\n" << text;
        EXPECT_TRUE(again.scene == loaded.parsed.scene) << path << "\n" << text;
        // Canonical: serializing the re-read scene gives the same text.
        EXPECT_EQ(serialize_scene(again.scene), text) << path;
    }
}

// Kept as written where the text uses names or includes: the same scene
// again, read from the file's folder, and for a file without definitions or
// includes, the canonical text itself.
TEST(Scenes, EveryFileRoundTripsThroughTheSourceSerializer) {
    for (const auto& path : scene_files()) {
        const LoadedScene loaded = load_scene_file(path).value();
        const std::string text = serialize_scene(loaded.parsed.scene, {loaded.text, loaded.parsed});
        ParseResult again = parse_scene(text, loaded.options);
        EXPECT_EQ(test::brief(again.diagnostics), "") << path << "\n" << text;
        EXPECT_TRUE(again.scene == loaded.parsed.scene) << path << "\n" << text;
        EXPECT_EQ(again.source.definitions.size(), loaded.parsed.source.definitions.size());
        // Every include is kept, and reads the same files again.
        EXPECT_EQ(again.source.files.size(), loaded.parsed.source.files.size()) << path;
        EXPECT_EQ(serialize_scene(again.scene, {text, again}), text) << path;
        if (loaded.parsed.source.definitions.empty() && loaded.parsed.source.files.empty()) {
            EXPECT_EQ(text, serialize_scene(loaded.parsed.scene)) << path;
        }
    }
}

// scenes/split/main.jts keeps its two includes where the canonical layout
// puts what they give: the definitions first, the objects first in `scene`.
TEST(Scenes, TheSplitSceneKeepsItsIncludes) {
    const LoadedScene loaded =
        load_scene_file(std::filesystem::path(JT_SOURCE_DIR) / "scenes" / "split" / "main.jts")
            .value();
    const std::string text = serialize_scene(loaded.parsed.scene, {loaded.text, loaded.parsed});
    EXPECT_TRUE(
        text.starts_with("# Written by JTracer.\n"
                         "\n"
                         "include \"parts/materials.jts\";\n"
                         "\n"
                         "render_settings {\n"))
        << text;
    EXPECT_NE(text.find("scene {\n"
                        "    include \"parts/objects.jts\";\n"
                        "    point_light {\n"),
              std::string::npos)
        << text;
    for (const char* inlined : {"define ", "material ", "sphere", "plane"})
        EXPECT_EQ(text.find(inlined), std::string::npos) << inlined << "\n" << text;
    const ParseResult again = parse_scene(text, loaded.options);
    EXPECT_EQ(test::brief(again.diagnostics), "") << text;
    EXPECT_TRUE(again.scene == loaded.parsed.scene) << text;
}

TEST(Showcase, UsesEveryFeature) {
    const LoadedScene loaded =
        load_scene_file(std::filesystem::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts").value();
    const Scene& s = loaded.parsed.scene;
    auto count = [&](auto shape) {
        return std::count_if(s.primitives.begin(), s.primitives.end(), [&](const Primitive& p) {
            return std::holds_alternative<decltype(shape)>(p.shape);
        });
    };
    EXPECT_GE(count(Sphere{}), 3);
    EXPECT_GE(count(Plane{}), 1);
    EXPECT_GE(count(Cylinder{}), 1);
    EXPECT_GE(s.lights.size(), 2u);
    EXPECT_GE(s.settings.recurse_depth, 3);
    ASSERT_GE(s.cameras.size(), 2u);
    EXPECT_FALSE(s.cameras[0].name.empty());
    EXPECT_FALSE(s.cameras[1].name.empty());
    bool rotation = false, non_uniform_scale = false, mirror = false, specular = false;
    for (const Primitive& p : s.primitives) {
        for (const TransformOp& op : p.transforms) {
            rotation |= op.kind != TransformKind::translate && op.kind != TransformKind::scale;
            non_uniform_scale |= op.kind == TransformKind::scale &&
                                 (op.vector.x != op.vector.y || op.vector.y != op.vector.z);
        }
        mirror |= p.material.finish->reflection >= 0.5;
        specular |= p.material.finish->specular != Colour(0);
    }
    EXPECT_TRUE(rotation);
    EXPECT_TRUE(non_uniform_scale);
    EXPECT_TRUE(mirror);
    EXPECT_TRUE(specular);
    std::set<std::tuple<double, double, double>> light_colours;
    for (const PointLight& l : s.lights)
        light_colours.insert({l.intensity.x, l.intensity.y, l.intensity.z});
    EXPECT_GE(light_colours.size(), 2u);
}

}  // namespace
}  // namespace jt
