// serialize_scene(scene, {text, parsed}): canonical text that keeps the
// text's definitions, named materials, names and expressions, and reads back
// as the same scene (docs/language.md §15.2, §15.3).

#include "jtracer/source_serializer.hpp"
#include "jtracer/serializer.hpp"

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace jt {
namespace {

using test::brief;
using test::parse_clean;

// `text` parsed, serialised with its source after `edit` changed the scene,
// and checked to read back (with no diagnostics) as the edited scene.
template <class Edit>
std::string reserialized(std::string_view text, Edit edit, const ParseOptions& options = {}) {
    const ParseResult parsed = parse_scene(text, options);
    EXPECT_TRUE(parsed.ok()) << brief(parsed.diagnostics);
    Scene scene = parsed.scene;
    edit(scene);
    const std::string out = serialize_scene(scene, {text, parsed, options.defines});
    const ParseResult again = parse_scene(out);
    EXPECT_EQ(brief(again.diagnostics), "") << out;
    EXPECT_TRUE(again.scene == scene) << out;
    return out;
}

std::string reserialized(std::string_view text) {
    return reserialized(text, [](Scene&) {});
}

Sphere& sphere(Scene& scene, std::size_t i = 0) {
    return std::get<Sphere>(scene.primitives.at(i).shape);
}

constexpr std::string_view kNamed =
    "# A comment, dropped.\n"
    "define w = 64;\n"
    "define out = \"x.bmp\";\n"
    "render_settings { width: w; height: w * 3 / 4; filename: out; }\n"
    "define r = 2;\n"
    "material glossy { reflection: 0.5; pigment: <1, 0, 0> * r / 2; }\n"
    "cameras { perspective_camera { position: <0, 1, 5> * r; fov: 40; } }\n"
    "scene {\n"
    "    sphere { radius: r; center: <0, r,\n"
    "             -1>; material { diffuse: <1, 1, 1> * 0.5; } material: glossy; }\n"
    "    sphere { radius: 1; transform { translate: <r, 0, 0>; yrotate: 90; } }\n"
    "    point_light { position: <0, 10, 0>; intensity: <1, 1, 1> / r; }\n"
    "}\n";

TEST(SourceSerializer, KeepsDefinitionsNamedMaterialsNamesAndExpressions) {
    EXPECT_EQ(reserialized(kNamed),
              "# Written by JTracer.\n"
              "\n"
              "define w = 64;\n"
              "define out = \"x.bmp\";\n"
              "define r = 2;\n"
              "material glossy {\n"
              "    pigment: <1, 0, 0> * r / 2;\n"
              "    reflection: 0.5;\n"
              "}\n"
              "\n"
              "render_settings {\n"
              "    width: w;\n"
              "    height: w * 3 / 4;\n"
              "    recurse_depth: 0;\n"
              "    filename: out;\n"
              "    background: <0, 0, 0>;\n"
              "    ambient_light: <0, 0, 0>;\n"
              "}\n"
              "\n"
              "cameras {\n"
              "    perspective_camera {\n"
              "        name: \"\";\n"
              "        position: <0, 1, 5> * r;\n"
              "        look_at: <0, 0, -1>;\n"
              "        up: <0, 1, 0>;\n"
              "        aspect: 1;\n"
              "        fov: 40;\n"
              "    }\n"
              "}\n"
              "\n"
              "scene {\n"
              "    sphere {\n"
              "        center: <0, r,\n"
              "             -1>;\n"
              "        radius: r;\n"
              "        material: glossy;\n"
              "        material {\n"
              "            diffuse: <1, 1, 1> * 0.5;\n"
              "        }\n"
              "    }\n"
              "    sphere {\n"
              "        center: <0, 0, 0>;\n"
              "        radius: 1;\n"
              "        material {\n"
              "            pigment: <0, 0, 0>;\n"
              "            ambient: <0, 0, 0>;\n"
              "            diffuse: <0, 0, 0>;\n"
              "            specular: <0, 0, 0>;\n"
              "            diffuse_k: 1;\n"
              "            specular_k: 64;\n"
              "            reflection: 0;\n"
              "        }\n"
              "        transform {\n"
              "            translate: <r, 0, 0>;\n"
              "            yrotate: 90;\n"
              "        }\n"
              "    }\n"
              "    point_light {\n"
              "        position: <0, 10, 0>;\n"
              "        intensity: <1, 1, 1> / r;\n"
              "    }\n"
              "}\n");
}

TEST(SourceSerializer, ItsTextIsAFixedPoint) {
    const std::string once = reserialized(kNamed);
    EXPECT_EQ(reserialized(once), once);
}

TEST(SourceSerializer, AValueChangedSinceParsingIsWrittenAsItsLiteral) {
    const std::string out = reserialized(kNamed, [](Scene& s) {
        sphere(s).radius = 3;  // was r
        s.cameras[0].fov = 50;
        s.lights[0].intensity = {0.25, 0.5, 1};      // was <1, 1, 1> / r
        s.primitives[1].transforms[0].vector.x = 7;  // was <r, 0, 0>
        s.settings.height = 10;                      // was w * 3 / 4
    });
    EXPECT_NE(out.find("        radius: 3;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("        center: <0, r,\n"), std::string::npos) << out;  // unchanged
    EXPECT_NE(out.find("        fov: 50;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("        intensity: <0.25, 0.5, 1>;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("            translate: <7, 0, 0>;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("            yrotate: 90;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("    height: 10;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("    width: w;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("define r = 2;\n"), std::string::npos) << out;
}

TEST(SourceSerializer, AChangeToANamedMaterialsValueGoesIntoThePrimitivesOwnBlock) {
    const std::string out = reserialized(kNamed, [](Scene& s) {
        s.primitives[0].material.reflection = 0;       // the named material's 0.5
        s.primitives[0].material.diffuse = {1, 1, 1};  // its own <1, 1, 1> * 0.5
    });
    EXPECT_NE(out.find("        material: glossy;\n"
                       "        material {\n"
                       "            diffuse: <1, 1, 1>;\n"
                       "            reflection: 0;\n"
                       "        }\n"),
              std::string::npos)
        << out;
    // The shared material stays as it was.
    EXPECT_NE(out.find("    reflection: 0.5;\n"), std::string::npos) << out;
}

TEST(SourceSerializer, ANamedMaterialWithNothingOfItsOwnWritesNoBlock) {
    const std::string out = reserialized(
        "material m { checker: <0, 0, 1>; ior: 1.5; }\n"
        "scene { plane { material: m; } }\n");
    EXPECT_NE(out.find("        material: m;\n    }\n"), std::string::npos) << out;
}

TEST(SourceSerializer, AnUnsetValueOverANamedMaterialsSetOneDropsTheName) {
    const std::string out = reserialized(
        "define big = 2;\n"
        "material m { checker: <0, 0, 1>; checker_size: big; }\n"
        "scene { plane { material: m; material { diffuse_k: big; } } }\n",
        [](Scene& s) { s.primitives[0].material.checker.reset(); });
    EXPECT_EQ(out.find("material: m;"), std::string::npos) << out;
    EXPECT_NE(out.find("            diffuse_k: big;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("            checker_size: 2;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("material m {\n"), std::string::npos) << out;  // still defined
}

TEST(SourceSerializer, RepeatsAndSeveralMaterialBlocksKeepTheValueThatWins) {
    const std::string out = reserialized(
        "define r = 2;\n"
        "scene { sphere { radius: r; radius: r + 1; material { pigment: <r, 0, 0> / 4; }\n"
        "                 material { pigment: <0, r, 0> / 4; reflection: r / 4; } } }\n");
    EXPECT_NE(out.find("        radius: r + 1;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("            pigment: <0, r, 0> / 4;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("            reflection: r / 4;\n"), std::string::npos) << out;
    EXPECT_EQ(out.find("<r, 0, 0>"), std::string::npos) << out;
}

TEST(SourceSerializer, BlocksAddedRemovedOrReshapedAreWrittenAsLiterals) {
    const std::string text =
        "define r = 2;\n"
        "scene { sphere { radius: r; } sphere { radius: r * 2; } }\n";
    // The second sphere removed: the first keeps its name.
    std::string out = reserialized(text, [](Scene& s) { s.primitives.pop_back(); });
    EXPECT_NE(out.find("radius: r;"), std::string::npos) << out;
    // The first removed: the second, now first, is compared with what the
    // first was, and is written as a literal.
    out = reserialized(text, [](Scene& s) { s.primitives.erase(s.primitives.begin()); });
    EXPECT_NE(out.find("radius: 4;"), std::string::npos) << out;
    // Another shape in its place, and one more at the end.
    out = reserialized(text, [](Scene& s) {
        s.primitives[0].shape = Cylinder{};
        s.primitives.push_back(Primitive{Sphere{}, {}, {}});
        s.lights.push_back(PointLight{});
        s.cameras.push_back(test::named_camera("added"));
    });
    EXPECT_NE(out.find("radius: r * 2;"), std::string::npos) << out;
    // Transform operations added after the text's.
    out = reserialized(
        "define a = 30;\nscene { sphere { transform { yrotate: a; } transform { xrotate: -a; } } "
        "}\n",
        [](Scene& s) {
            s.primitives[0].transforms.push_back({TransformKind::zrotate, {}, 5});
        });
    EXPECT_NE(out.find("            yrotate: a;\n"
                       "            xrotate: -a;\n"
                       "            zrotate: 5;\n"),
              std::string::npos)
        << out;
}

TEST(SourceSerializer, DefineValuesFromTheCommandLineStandInTheText) {
    ParseOptions options;
    options.defines = {{"r", "3"}, {"extra", "<1, 0, 0> * 2"}, {"r", "4"}};
    const std::string out = reserialized(
        "define r = 2;\nscene { sphere { radius: r; center: extra; } }\n", [](Scene&) {}, options);
    EXPECT_EQ(out.find("define r = 2;"), std::string::npos) << out;
    EXPECT_NE(out.find("define extra = <1, 0, 0> * 2;\ndefine r = 4;\n"), std::string::npos) << out;
    // Read with the same --define values, it means the same too.
    const ParseResult again = parse_scene(out, options);
    EXPECT_TRUE(again.ok());
    EXPECT_TRUE(again.scene == parse_scene(out).scene);
}

TEST(SourceSerializer, ClockStaysAName) {
    ParseOptions options;
    options.clock = 0.5;
    const std::string text = "scene { sphere { center: <0, clock, 0>; } }\n";
    const ParseResult parsed = parse_scene(text, options);
    const std::string out = serialize_scene(parsed.scene, {text, parsed});
    EXPECT_NE(out.find("center: <0, clock, 0>;"), std::string::npos) << out;
    EXPECT_TRUE(parse_scene(out, options).scene == parsed.scene) << out;
}

TEST(SourceSerializer, ATextWithoutNamesGivesTheCanonicalText) {
    const std::string text =
        "render_settings { width: 2.9; background: <2, 0.5, -1>; }\n"
        "cameras { perspective_camera { active_camera: \"c\"; } }\n"
        "scene { sphere { radius: 1.50; material { reflection: 1e0; } transform { xrotate: -90; "
        "} } }\n";
    const ParseResult parsed = parse_scene(text);
    EXPECT_TRUE(parsed.ok());
    EXPECT_EQ(serialize_scene(parsed.scene, {text, parsed}), serialize_scene(parsed.scene));
}

TEST(SourceSerializer, ATextWithErrorsOrNoSourceMapGivesTheCanonicalText) {
    const std::string broken = "define r = 2;\nscene { sphere { radius: r; center: q; } }\n";
    const ParseResult with_errors = parse_scene(broken);
    EXPECT_FALSE(with_errors.ok());
    EXPECT_EQ(serialize_scene(with_errors.scene, {broken, with_errors}),
              serialize_scene(with_errors.scene));
    const std::string text = "define r = 2;\nscene { sphere { radius: r; } }\n";
    const ParseResult unmapped = parse_scene(text, {.source_map = false});
    const std::string out = serialize_scene(unmapped.scene, {text, unmapped});
    EXPECT_EQ(out, serialize_scene(unmapped.scene));
    EXPECT_NE(out.find("radius: 2;"), std::string::npos);
}

}  // namespace
}  // namespace jt

namespace jt {
namespace {

// What included files wrote is written in place of their include, from each
// file's own text; a file name written in an included file (relative to its
// folder) is written as the value the scene holds.
TEST(SourceSerializer, IncludedFilesAreWrittenInPlaceFromTheirOwnText) {
    const test::ScratchDir scratch("source_serializer_include");
    const std::filesystem::path& dir = scratch.path();
    std::filesystem::create_directories(dir / "parts");
    test::write_file(dir / "parts" / "defs.jts",
                     "define tex = \"wood.png\";\n"
                     "define r = 3;\n"
                     "material wood { image_map: tex; pigment: <1, 1, 1> / r; }\n");
    test::write_file(dir / "parts" / "balls.jts",
                     "sphere { radius: r * 2; material: wood; }\n"
                     "sphere { radius: r; material { image_map: tex; } }\n");
    const std::string text =
        "include \"parts/defs.jts\";\n"
        "scene { include \"parts/balls.jts\"; sphere { radius: r / 2; } }\n";
    ParseOptions options;
    options.main_file = (dir / "main.jts").string();
    const ParseResult parsed = parse_scene(text, options);
    ASSERT_TRUE(parsed.ok()) << brief(parsed.diagnostics);
    ASSERT_EQ(parsed.scene.primitives.at(1).material.image_map, "parts/wood.png");
    const std::string out = serialize_scene(parsed.scene, {text, parsed});
    EXPECT_EQ(out.find("include"), std::string::npos) << out;
    for (const char* written :
         {"define tex = \"wood.png\";\n", "define r = 3;\n", "    image_map: \"parts/wood.png\";\n",
          "    pigment: <1, 1, 1> / r;\n", "        radius: r * 2;\n", "        material: wood;\n",
          "            image_map: \"parts/wood.png\";\n", "        radius: r / 2;\n"})
        EXPECT_NE(out.find(written), std::string::npos) << written << "\n" << out;
    const ParseResult again = parse_scene(out, options);
    EXPECT_EQ(brief(again.diagnostics), "") << out;
    EXPECT_TRUE(again.scene == parsed.scene) << out;
    EXPECT_EQ(serialize_scene(again.scene, {out, again}), out);
}

}  // namespace
}  // namespace jt
