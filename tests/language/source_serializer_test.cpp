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
#include <iterator>
#include <random>
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
    return shape_as<Sphere>(scene.primitives.at(i).shape);
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
        s.primitives[0].material.finish.edit().reflection = 0;       // the named material's 0.5
        s.primitives[0].material.finish.edit().diffuse = {1, 1, 1};  // its own <1, 1, 1> * 0.5
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
        [](Scene& s) { s.primitives[0].material.finish.edit().checker.reset(); });
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

// Included files, in a scratch folder beside the main text "main.jts".
class Includes {
  public:
    explicit Includes(std::string_view label) : scratch_(label) {
        options.main_file = (scratch_.path() / "main.jts").string();
    }

    void write(const std::string& path, std::string_view text) const {
        std::filesystem::create_directories((scratch_.path() / path).parent_path());
        test::write_file(scratch_.path() / path, text);
    }

    // `text` read as main.jts, serialised after `edit`, and checked to read
    // back from the same folder, with no diagnostics, as the edited scene,
    // and to serialise again to itself.
    template <class Edit>
    std::string reserialized(std::string_view text, Edit edit) const {
        const ParseResult parsed = parse_scene(text, options);
        EXPECT_TRUE(parsed.ok()) << brief(parsed.diagnostics);
        Scene scene = parsed.scene;
        edit(scene);
        const std::string out = serialize_scene(scene, {text, parsed, options.defines});
        const ParseResult again = parse_scene(out, options);
        EXPECT_EQ(brief(again.diagnostics), "") << out;
        EXPECT_TRUE(again.scene == scene) << out;
        EXPECT_EQ(serialize_scene(again.scene, {out, again, options.defines}), out);
        return out;
    }
    std::string reserialized(std::string_view text) const {
        return reserialized(text, [](Scene&) {});
    }

    ParseOptions options;

  private:
    test::ScratchDir scratch_;
};

std::size_t count(std::string_view text, std::string_view part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string_view::npos;
         at = text.find(part, at + 1))
        ++n;
    return n;
}

constexpr std::string_view kDefs =
    "define tex = \"wood.png\";\n"
    "define r = 3;\n"
    "material wood { image_map: tex; pigment: <1, 1, 1> / r; }\n";
constexpr std::string_view kBalls =
    "sphere { radius: r * 2; material: wood; }\n"
    "sphere { radius: r; material { image_map: tex; } }\n";
constexpr std::string_view kMain =
    "include \"parts/defs.jts\";\n"
    "scene { include \"parts/balls.jts\"; sphere { radius: r / 2; } }\n";

// An include whose files gave what the scene still holds is written as the
// text wrote it, where the first of what it gave goes, and nothing it gave
// is written again.
TEST(SourceSerializer, AnIncludeOfUnchangedContentIsKeptAsWritten) {
    const Includes files("source_serializer_include_kept");
    files.write("parts/defs.jts", kDefs);
    files.write("parts/balls.jts", kBalls);
    const std::string out = files.reserialized(kMain);
    EXPECT_TRUE(
        out.starts_with("# Written by JTracer.\n\ninclude \"parts/defs.jts\";\n\n"
                        "render_settings {\n"))
        << out;
    EXPECT_NE(out.find("scene {\n"
                       "    include \"parts/balls.jts\";\n"
                       "    sphere {\n"
                       "        center: <0, 0, 0>;\n"
                       "        radius: r / 2;\n"),
              std::string::npos)
        << out;
    for (const char* given : {"define", "material wood", "r * 2", "image_map"})
        EXPECT_EQ(out.find(given), std::string::npos) << given << "\n" << out;
}

// What included files wrote is written in place of their include, from each
// file's own text, when a value it gave has changed; a file name written in
// an included file (relative to its folder) is then written as the value the
// scene holds. The other include stays.
TEST(SourceSerializer, AnEditedValueFromAnIncludedFileWritesItsFileOutInPlace) {
    const Includes files("source_serializer_include_edited");
    files.write("parts/defs.jts", kDefs);
    files.write("parts/balls.jts", kBalls);
    const std::string out = files.reserialized(kMain, [](Scene& s) {
        shape_as<Sphere>(s.primitives.at(1).shape).radius = 5;  // was r
    });
    EXPECT_NE(out.find("include \"parts/defs.jts\";\n"), std::string::npos) << out;
    EXPECT_EQ(out.find("parts/balls.jts"), std::string::npos) << out;
    for (const char* written :
         {"        radius: r * 2;\n", "        material: wood;\n", "        radius: 5;\n",
          "            image_map: \"parts/wood.png\";\n", "        radius: r / 2;\n"})
        EXPECT_NE(out.find(written), std::string::npos) << written << "\n" << out;
    // A value the primitive inherits from the included named material,
    // changed: the change goes into the primitive's own block, written in
    // place with its file; the file defining the material stays included.
    const std::string inherited = files.reserialized(kMain, [](Scene& s) {
        s.primitives.at(0).material.finish.edit().reflection = 0.5;
        s.settings.width = 10;
    });
    EXPECT_NE(inherited.find("include \"parts/defs.jts\";\n"), std::string::npos) << inherited;
    EXPECT_EQ(inherited.find("parts/balls.jts"), std::string::npos) << inherited;
    EXPECT_NE(inherited.find("        material: wood;\n"
                             "        material {\n"
                             "            reflection: 0.5;\n"),
              std::string::npos)
        << inherited;
}

// A value a kept include's definition gave, set by --define: the definition
// must take the --define value, so that file is written in place.
TEST(SourceSerializer, ADefineValueFromTheCommandLineWritesItsFileOutInPlace) {
    Includes files("source_serializer_include_define");
    files.write("parts/defs.jts", kDefs);
    files.write("parts/balls.jts", kBalls);
    const std::string text = std::string(kMain);
    const std::string kept = files.reserialized(text);
    files.options.defines = {{"r", "4"}};
    const ParseResult parsed = parse_scene(text, files.options);
    ASSERT_TRUE(parsed.ok()) << brief(parsed.diagnostics);
    const std::string out = serialize_scene(parsed.scene, {text, parsed, files.options.defines});
    EXPECT_EQ(out.find("parts/defs.jts"), std::string::npos) << out;
    EXPECT_NE(out.find("define r = 4;\n"), std::string::npos) << out;
    EXPECT_NE(out.find("    include \"parts/balls.jts\";\n"), std::string::npos) << out;
    files.options.defines.clear();
    const ParseResult again = parse_scene(out, files.options);
    EXPECT_EQ(brief(again.diagnostics), "") << out;
    EXPECT_TRUE(again.scene == parsed.scene) << out;
    EXPECT_NE(kept, out);
}

// A file that includes others is seen through the main text's include: kept
// whole while nothing any of its files gave has changed, written in place
// (its own includes too) when something has.
TEST(SourceSerializer, NestedIncludesAreKeptThroughTheMainTextsInclude) {
    const Includes files("source_serializer_include_nested");
    files.write("parts/all.jts",
                "include \"defs.jts\";\n"
                "render_settings { width: r * 10; }\n"
                "cameras { include \"cams/one.jts\"; }\n");
    files.write("parts/defs.jts", "define r = 3;\n");
    files.write("parts/cams/one.jts", "perspective_camera { fov: r * 10; }\n");
    const std::string text =
        "define before = 1;\n"
        "include \"parts/all.jts\";\n"
        "scene { sphere { radius: r + before; } }\n";
    const std::string out = files.reserialized(text);
    EXPECT_TRUE(
        out.starts_with("# Written by JTracer.\n\n"
                        "define before = 1;\n"
                        "include \"parts/all.jts\";\n"
                        "\n"
                        "scene {\n"))
        << out;
    EXPECT_EQ(count(out, "include"), 1u) << out;
    // The camera of the innermost file changed: everything all.jts gave is
    // written in place.
    const std::string edited = files.reserialized(text, [](Scene& s) { s.cameras[0].fov = 45; });
    EXPECT_EQ(edited.find("include"), std::string::npos) << edited;
    for (const char* written :
         {"define r = 3;\n", "    width: r * 10;\n", "        fov: 45;\n", "cameras {\n"})
        EXPECT_NE(edited.find(written), std::string::npos) << written << "\n" << edited;
}

// An include directly in `scene` or in `cameras` goes there, at the place of
// the first object or camera it gave; when what it gave cannot stand there as
// one run (a light of the main text between its objects and its lights), it
// is written in place.
TEST(SourceSerializer, AnIncludeInsideABlockStandsAtItsFirstBlock) {
    const Includes files("source_serializer_include_block");
    files.write("objects.jts", "plane { distance: 1; }\npoint_light { position: <0, 5, 0>; }\n");
    files.write("cameras.jts", "perspective_camera { name: \"side\"; }\n");
    const std::string out = files.reserialized(
        "cameras { perspective_camera { name: \"front\"; } include \"cameras.jts\"; }\n"
        "scene { sphere { radius: 1; } include \"objects.jts\"; }\n");
    EXPECT_NE(out.find("        name: \"front\";\n"
                       "        position: <0, 0, 0>;\n"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("    }\n    include \"cameras.jts\";\n}\n"), std::string::npos) << out;
    EXPECT_NE(out.find("    }\n    include \"objects.jts\";\n}\n"), std::string::npos) << out;
    EXPECT_EQ(out.find("side"), std::string::npos) << out;
    EXPECT_EQ(out.find("plane"), std::string::npos) << out;
    // objects.jts's plane comes before the main text's light; its light after.
    const std::string split = files.reserialized(
        "scene { point_light { position: <1, 1, 1>; } include \"objects.jts\"; }\n");
    EXPECT_EQ(split.find("include"), std::string::npos) << split;
    EXPECT_NE(split.find("    plane {\n"), std::string::npos) << split;
    // An object added after the ones the include gave comes after it.
    const std::string added =
        files.reserialized("scene { include \"objects.jts\"; }\n", [](Scene& s) {
            s.primitives.push_back(Primitive{Sphere{}, {}, {}});
        });
    EXPECT_EQ(added.find("include"), std::string::npos) << "a light follows the new sphere\n"
                                                        << added;
}

// Each reading of a file included twice is its own include: the one whose
// object changed is written in place, the other stays.
TEST(SourceSerializer, AFileIncludedTwiceIsKeptOrWrittenByReading) {
    const Includes files("source_serializer_include_twice");
    files.write("ball.jts", "sphere { radius: 2; }\n");
    const std::string text = "scene { include \"ball.jts\"; include \"ball.jts\"; }\n";
    const std::string out = files.reserialized(text);
    EXPECT_NE(out.find("scene {\n"
                       "    include \"ball.jts\";\n"
                       "    include \"ball.jts\";\n"
                       "}\n"),
              std::string::npos)
        << out;
    const std::string edited = files.reserialized(
        text, [](Scene& s) { shape_as<Sphere>(s.primitives.at(1).shape).radius = 3; });
    EXPECT_NE(edited.find("scene {\n"
                          "    include \"ball.jts\";\n"
                          "    sphere {\n"),
              std::string::npos)
        << edited;
    EXPECT_EQ(count(edited, "include"), 1u) << edited;
    EXPECT_NE(edited.find("radius: 3;"), std::string::npos) << edited;
    // The object removed: its reading gives nothing that is still there.
    const std::string removed = files.reserialized(text, [](Scene& s) { s.primitives.pop_back(); });
    EXPECT_EQ(count(removed, "include"), 1u) << removed;
}

// A file that gives a whole block stands in its place; an include that gave
// the scene nothing (its objects were in a scene block a later one replaced)
// is dropped.
TEST(SourceSerializer, AnIncludeOfWholeBlocksStandsInTheirPlace) {
    const Includes files("source_serializer_include_whole");
    files.write("setup.jts",
                "render_settings { width: 32; }\n"
                "cameras { perspective_camera { fov: 30; } }\n");
    files.write("world.jts", "scene { sphere { radius: 2; } point_light { } }\n");
    files.write("ball.jts", "sphere { radius: 7; }\n");
    const std::string whole = files.reserialized(
        "scene { include \"ball.jts\"; }\n"
        "include \"setup.jts\";\n"
        "include \"world.jts\";\n");
    EXPECT_EQ(whole,
              "# Written by JTracer.\n"
              "\n"
              "include \"setup.jts\";\n"
              "\n"
              "include \"world.jts\";\n");
    // A camera more: setup.jts's cameras block is no longer all of it.
    const std::string more = files.reserialized("include \"setup.jts\";\n",
                                                [](Scene& s) { s.cameras.push_back(Camera{}); });
    EXPECT_EQ(more.find("include"), std::string::npos) << more;
    EXPECT_NE(more.find("    width: 32;\n"), std::string::npos) << more;
}

// A kept include gives again everything its file holds, blocks a later one
// replaced included. A render_settings block of a file whose include would
// stand after the render_settings in use would replace it on reading the
// result: that include is written in place. One that stands before it is
// kept, the later block replacing its block again.
TEST(SourceSerializer, AnIncludeWithAReplacedBlockIsKeptOnlyBeforeTheOneInUse) {
    Includes files("source_serializer_include_replaced");
    files.write("world.jts",
                "render_settings { width: 10; }\n"
                "scene { sphere { radius: 2; } }\n");
    files.write("defs.jts",
                "define r = 3;\n"
                "render_settings { width: 10; }\n");
    auto reserialized = [&](std::string_view text) {
        const ParseResult parsed = parse_scene(text, files.options);
        EXPECT_TRUE(parsed.ok()) << brief(parsed.diagnostics);
        EXPECT_EQ(parsed.scene.settings.width, 20);
        const std::string out = serialize_scene(parsed.scene, {text, parsed});
        const ParseResult again = parse_scene(out, files.options);
        EXPECT_TRUE(again.ok()) << brief(again.diagnostics) << "\n" << out;
        EXPECT_TRUE(again.scene == parsed.scene) << out;
        EXPECT_EQ(serialize_scene(again.scene, {out, again}), out);
        return out;
    };
    const std::string after =
        reserialized("include \"world.jts\";\nrender_settings { width: 20; }\n");
    EXPECT_EQ(after.find("include"), std::string::npos) << after;
    EXPECT_NE(after.find("        radius: 2;\n"), std::string::npos) << after;
    const std::string before = reserialized(
        "include \"defs.jts\";\nrender_settings { width: 20; }\n"
        "scene { sphere { radius: r; } }\n");
    EXPECT_TRUE(
        before.starts_with("# Written by JTracer.\n\ninclude \"defs.jts\";\n\n"
                           "render_settings {\n"))
        << before;
}

// Main texts made of every kind of include (nested, twice, in a replaced
// block, a file of whole blocks, of objects and lights, of a named material
// with a file name), read with and without a --define, then edited each way
// the serializer must notice: every result reads back as the edited scene
// and serialises to itself, and the unedited ones keep includes.
TEST(SourceSerializer, IncludesOfEveryKindReadBackAsTheEditedScene) {
    Includes files("source_serializer_include_every_kind");
    files.write("defs.jts", "define r = 2;\nmaterial m { pigment: <1, 0, 0>; }\n");
    files.write("nest.jts", "include \"defs.jts\";\nrender_settings { width: r * 4; }\n");
    files.write("ball.jts", "sphere { radius: r; material: m; transform { scale: r; } }\n");
    files.write("lamp.jts", "point_light { position: <0, 5, 0>; }\n");
    files.write("both.jts", "plane { distance: 1; }\npoint_light { }\n");
    files.write("cam.jts", "perspective_camera { fov: 30; }\n");
    files.write("settings.jts", "render_settings { width: 16; }\n");
    files.write("world.jts",
                "render_settings { width: 8; }\n"
                "scene { sphere { radius: 1; } include \"lamp.jts\"; }\n");
    files.write("camblock.jts",
                "cameras { perspective_camera { fov: 40; } include \"cam.jts\"; }\n");
    files.write("empty.jts", "");
    files.write("d/deep.jts", "include \"../both.jts\";\nsphere { radius: 9; }\n");
    files.write("d/tex.jts", "sphere { radius: 1; material { image_map: \"t.png\"; } }\n");
    files.write("d/mats.jts", "material tm { image_map: \"t.png\"; }\n");
    constexpr std::string_view kStart[] = {"include \"defs.jts\";\n",
                                           "define r = 2;\nmaterial m { pigment: <1, 0, 0>; }\n",
                                           "include \"nest.jts\";\n"};
    constexpr std::string_view kTop[] = {"render_settings { width: 20; }\n",
                                         "include \"settings.jts\";\n", "include \"world.jts\";\n",
                                         "include \"camblock.jts\";\n"};
    constexpr std::string_view kCameras[] = {" perspective_camera { fov: 50; }",
                                             " include \"cam.jts\";"};
    constexpr std::string_view kScene[] = {" sphere { radius: 3; }",
                                           " include \"ball.jts\";",
                                           " include \"lamp.jts\";",
                                           " include \"both.jts\";",
                                           " point_light { position: <1, 1, 1>; }",
                                           " include \"empty.jts\";",
                                           " include \"d/deep.jts\";",
                                           " sphere { radius: r * 2; }",
                                           " include \"d/tex.jts\";",
                                           " sphere { material: tm; }"};
    std::mt19937 random(7);
    auto pick = [&](const auto& choices) { return choices[random() % std::size(choices)]; };
    int read = 0, kept = 0;
    for (int iteration = 0; iteration < 600; ++iteration) {
        std::string text = random() % 2 ? "include \"d/mats.jts\";\n" : "";
        text += pick(kStart);
        for (unsigned block = 1 + random() % 5; block > 0; --block) {
            const unsigned kind = random() % 6;
            if (kind < 4) {
                text += kTop[kind];
                continue;
            }
            text += kind == 4 ? "cameras {" : "scene {";
            for (unsigned n = random() % 5; n > 0; --n)
                text += kind == 4 ? pick(kCameras) : pick(kScene);
            text += " }\n";
        }
        std::vector<Define> defines;
        if (random() % 3 == 0) defines = {{"r", "5"}};
        files.options.defines = defines;
        const ParseResult parsed = parse_scene(text, files.options);
        files.options.defines.clear();
        if (!parsed.ok()) continue;  // a name used before its file is included
        ++read;
        for (int edit = 0; edit < 8; ++edit) {
            Scene scene = parsed.scene;
            auto any = [&](auto& items) -> auto& {
                return items[random() % items.size()];
            };
            if (edit == 1 && !scene.primitives.empty())
                any(scene.primitives).material.finish.edit().reflection = 0.5;
            if (edit == 2 && !scene.primitives.empty()) scene.primitives.pop_back();
            if (edit == 3) scene.primitives.push_back(Primitive{Sphere{}, {}, {}});
            if (edit == 4) scene.primitives.insert(scene.primitives.begin(), Primitive{});
            if (edit == 5) scene.settings.width = 33;
            if (edit == 6 && !scene.cameras.empty()) any(scene.cameras).fov = 12;
            if (edit == 7 && !scene.lights.empty()) scene.lights.erase(scene.lights.begin());
            const std::string out = serialize_scene(scene, {text, parsed, defines});
            if (edit == 0 && defines.empty() && out.find("include") != std::string::npos) ++kept;
            const ParseResult again = parse_scene(out, files.options);
            ASSERT_TRUE(again.ok()) << text << "\nedit " << edit << ":\n" << out;
            ASSERT_TRUE(again.scene == scene) << text << "\nedit " << edit << ":\n" << out;
            ASSERT_EQ(serialize_scene(again.scene, {out, again}), out) << text << "\nedit " << edit;
        }
    }
    EXPECT_GT(read, 300);
    EXPECT_GT(kept, read / 2);
}

}  // namespace
}  // namespace jt
