// docs/language.md §3 and §11: structure, recovery and the diagnostics it gives.

#include "test_util.hpp"

namespace jt {
namespace {

using test::brief;
using test::parse_clean;

TEST(Structure, MissingSemicolonPointsJustPastTheValue) {
    EXPECT_EQ(brief("scene {\n  sphere {\n    radius: 2\n  }\n}"),
              "3:14: error: expected ';' after the value of 'radius'");
    EXPECT_EQ(brief("scene { sphere { center: <1, 2, 3> radius: 2; } }"),
              "1:35: error: expected ';' after the value of 'center'");
}

TEST(Structure, MissingSemicolonStillReadsTheNextProperty) {
    ParseResult r = parse_scene("scene { sphere { center: <1, 2, 3>\n radius: 2; } }");
    ASSERT_EQ(r.scene.primitives.size(), 1u);
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives[0].shape), (Sphere{{1, 2, 3}, 2}));
}

TEST(Structure, MissingColon) {
    EXPECT_EQ(brief("scene { sphere { radius 2; } }"),
              "1:25: error: expected ':' after 'radius', got the number 2");
}

TEST(Structure, MissingValue) {
    EXPECT_EQ(brief("scene { sphere { radius: ; } }"),
              "1:26: error: expected a value after 'radius:', got ';'");
}

TEST(Structure, MissingOpeningBrace) {
    EXPECT_EQ(brief("scene { sphere radius: 2; }"),
              "1:16: error: expected '{' after 'sphere', got the word 'radius'");
}

TEST(Structure, UnknownTopLevelBlockListsWhatIsAllowedAndSuggests) {
    EXPECT_EQ(brief("render_setings { width: 2; }"),
              "1:1: error: unknown block 'render_setings' at the top level; did you mean "
              "'render_settings'? (allowed: render_settings, cameras, scene, include, define, "
              "material)");
    EXPECT_EQ(brief("lights { }"),
              "1:1: error: unknown block 'lights' at the top level (allowed: render_settings, "
              "cameras, scene, include, define, material)");
}

// The statements of language 1.3 stand where blocks do: a misspelt one is
// suggested like a block, and the rest of the text is read on.
TEST(Structure, AMisspeltStatementIsSuggested) {
    EXPECT_EQ(brief("defne r = 1;\nDefine s = 2;\nincud \"a.jts\";\nmaterail m { }\n"
                    "cameras { includ \"c.jts\"; }\nscene { inclde \"b.jts\"; sphere { } }"),
              "1:1: error: unknown block 'defne' at the top level; did you mean 'define'? "
              "(allowed: render_settings, cameras, scene, include, define, material)\n"
              "2:1: error: unknown block 'Define' at the top level; did you mean 'define'? "
              "(allowed: render_settings, cameras, scene, include, define, material)\n"
              "3:1: error: unknown block 'incud' at the top level; did you mean 'include'? "
              "(allowed: render_settings, cameras, scene, include, define, material)\n"
              "4:1: error: unknown block 'materail' at the top level; did you mean 'material'? "
              "(allowed: render_settings, cameras, scene, include, define, material)\n"
              "5:11: error: unknown block 'includ' in 'cameras'; did you mean 'include'? "
              "(allowed: perspective_camera, include)\n"
              "6:9: error: unknown block 'inclde' in 'scene'; did you mean 'include'? "
              "(allowed: sphere, plane, cylinder, triangle, mesh, point_light, include)");
}

// '2pi', '0x10' or '1_000': a name against the value is one mistake in its
// statement, not the start of the next one, whose errors would echo it.
TEST(Structure, ANameAgainstAValueIsOneError) {
    EXPECT_EQ(brief("define r = 2pi;\nscene { sphere { radius: 0x10; center: <r, 0, 0>; } }"),
              "1:13: error: expected ';' after the value of 'define r' (a name cannot follow a "
              "value directly: '2pi' is written '2 * pi')\n"
              "2:27: error: expected ';' after the value of 'radius' (a name cannot follow a "
              "value directly: '2pi' is written '2 * pi')");
    // A name after a space is the next line's, whose ';' is missing.
    ParseResult r = parse_scene("define r = 2\nscene { sphere { radius: r } }");
    EXPECT_EQ(brief(r.diagnostics),
              "1:13: error: expected ';' after the value of 'define r'\n"
              "2:27: error: expected ';' after the value of 'radius'");
    ASSERT_EQ(r.scene.primitives.size(), 1u);
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives[0].shape).radius, 2.0);
}

// POV-Ray users write '2 pi' for 2 * pi (it is an error there too): a name
// after a space on the value's line, not starting a property ('name:'), a
// block ('name {') or a statement, continues the value. One error, with the
// hint, not a second about 'pi' as a property or a block.
TEST(Structure, ANameAfterAValueOnItsLineIsOneError) {
    const std::string side_by_side =
        " (two values side by side are not multiplied: write '*' between them)";
    EXPECT_EQ(brief("define r = 2 pi;\nscene { sphere { radius: 2 r; center: <r, 0, 0>; } }"),
              "1:13: error: expected ';' after the value of 'define r'" + side_by_side +
                  "\n2:27: error: expected ';' after the value of 'radius'" + side_by_side);
    EXPECT_EQ(brief("define r = 2 sin(30);"),
              "1:13: error: expected ';' after the value of 'define r'" + side_by_side);
    // In a vector, where a ',' is due.
    EXPECT_EQ(brief("scene { sphere { center: <2pi, 2 pi, 0>; } }"),
              "1:28: error: a vector takes three numbers separated by commas, like <0, 1, 0>; "
              "expected ',' but got the word 'pi' (a name after a value does not multiply it: "
              "'2pi' and '2 pi' are written '2 * pi')");
    // A property, a block or a statement on the same line is the next one.
    ParseResult r = parse_scene(
        "define r = 2 define s = 3;\n"
        "scene { sphere { radius: r center: <s, 0, 0>; } sphere { radius: 1 material { } } }");
    EXPECT_EQ(brief(r.diagnostics),
              "1:13: error: expected ';' after the value of 'define r'\n"
              "2:27: error: expected ';' after the value of 'radius'\n"
              "2:67: error: expected ';' after the value of 'radius'");
    ASSERT_EQ(r.scene.primitives.size(), 2u);
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives[0].shape).center, Vec3(3, 0, 0));
}

// A POV-Ray user's words, too far from ours for a typo, are named with ours.
TEST(Structure, APovRayWordIsAnsweredWithOurs) {
    const std::string top =
        " (allowed: render_settings, cameras, scene, include, define, material)";
    EXPECT_EQ(brief("declare R = 1;"),
              "1:1: error: unknown block 'declare' at the top level; POV-Ray's 'declare' is "
              "'define' here" +
                  top);
    EXPECT_EQ(brief("local R = 1;"),
              "1:1: error: unknown block 'local' at the top level; POV-Ray's 'local' is 'define' "
              "here" +
                  top);
    EXPECT_EQ(brief("scene { light_source { } }"),
              "1:9: error: unknown block 'light_source' in 'scene'; POV-Ray's 'light_source' is "
              "'point_light' here (allowed: sphere, plane, cylinder, triangle, mesh, point_light, "
              "include)");
    EXPECT_EQ(brief("scene { sphere { finish { } } }"),
              "1:18: error: unknown block 'finish' in 'sphere'; POV-Ray's 'finish' is 'material' "
              "here (allowed: material, transform)");
    // Where ours does not stand either, the message says where it does.
    EXPECT_EQ(brief("light_source { }"),
              "1:1: error: unknown block 'light_source' at the top level; POV-Ray's "
              "'light_source' is 'point_light' here, which stands in 'scene { ... }'");
    EXPECT_EQ(brief("camera { }"),
              "1:1: error: unknown block 'camera' at the top level; POV-Ray's 'camera' is "
              "'perspective_camera' here, which stands in 'cameras { ... }'");
    EXPECT_EQ(brief("scene { pigment { } }"),
              "1:9: error: unknown block 'pigment' in 'scene'; POV-Ray's 'pigment' is "
              "'material' here, which stands in a primitive (sphere, plane, cylinder, triangle "
              "or mesh), or named at the top level as 'material NAME { ... }'");
    // Properties too, where ours stands in the same block.
    EXPECT_EQ(brief("cameras { perspective_camera { location: <0, 0, 5>; angle: 60; } }"),
              "1:32: error: unknown property 'location' in 'perspective_camera'; POV-Ray's "
              "'location' is 'position' here (allowed: name, position, look_at, up, aspect, fov, "
              "aperture, focus_distance)\n"
              "1:53: error: unknown property 'angle' in 'perspective_camera'; POV-Ray's 'angle' "
              "is 'fov' here (allowed: name, position, look_at, up, aspect, fov, aperture, "
              "focus_distance)");
    // A property is not a block: 'pigment:' belongs in a material.
    EXPECT_EQ(brief("scene { sphere { pigment: <1, 0, 0>; } }"),
              "1:18: error: unknown property 'pigment' in 'sphere' (allowed: center, radius, "
              "material, transform)");
    EXPECT_EQ(brief("scene { sphere { declare: 1; } }"),
              "1:18: error: unknown property 'declare' in 'sphere' (allowed: center, radius, "
              "material, transform)");
}

TEST(Structure, UnknownPropertySuggestsTheNearestName) {
    EXPECT_EQ(brief("scene { sphere { radus: 2; } }"),
              "1:18: error: unknown property 'radus' in 'sphere'; did you mean 'radius'? "
              "(allowed: center, radius, material, transform)");
    EXPECT_EQ(brief("render_settings { widht: 2; }"),
              "1:19: error: unknown property 'widht' in 'render_settings'; did you mean "
              "'width'? (allowed: width, height, recurse_depth, filename, active_camera, "
              "background, ambient_light, samples, background_map)");
    EXPECT_EQ(brief("scene { point_light { colour: <1, 1, 1>; } }"),
              "1:23: error: unknown property 'colour' in 'point_light' (allowed: position, "
              "intensity, radius, shadow_samples)");
}

TEST(Structure, UnknownBlockInsideABlockIsSkippedWhole) {
    ParseResult r = parse_scene("scene { sphere { matrial { pigment: <1, 0, 0>; } radius: 3; } }");
    EXPECT_EQ(brief(r.diagnostics),
              "1:18: error: unknown block 'matrial' in 'sphere'; did you mean 'material'? "
              "(allowed: material, transform)");
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives.at(0).shape).radius, 3.0);
}

TEST(Structure, WrongKindNamesTheExpectedKind) {
    EXPECT_EQ(brief("scene { sphere { center: 2; } }"),
              "1:26: error: 'center' takes a vector like <0, 1, 0>, got the number 2");
    EXPECT_EQ(brief("scene { sphere { radius: <1, 2, 3>; } }"),
              "1:26: error: 'radius' takes a number like 1.5, got the vector <1, 2, 3>");
    EXPECT_EQ(brief("render_settings { width: \"wide\"; }"),
              "1:26: error: 'width' takes a whole number like 640, got the string \"wide\"");
    EXPECT_EQ(brief("render_settings { filename: out; }"),
              "1:29: error: unknown name 'out' (names must be defined before they are used)");
    EXPECT_EQ(brief("render_settings { background: 1; }"),
              "1:31: error: 'background' takes a colour like <1, 0.5, 0>, got the number 1");
}

TEST(Structure, VectorsTakeExactlyThreeNumbers) {
    EXPECT_EQ(brief("scene { sphere { center: <1, 2>; } }"),
              "1:31: error: a vector takes three numbers separated by commas, like <0, 1, 0>; "
              "expected ',' but got '>'");
    EXPECT_EQ(brief("scene { sphere { center: <1, 2, 3, 4>; } }"),
              "1:34: error: a vector takes exactly three numbers, like <0, 1, 0>; expected '>' "
              "but got ','");
    EXPECT_EQ(brief("scene { sphere { center: <1 2 3>; } }"),
              "1:29: error: a vector takes three numbers separated by commas, like <0, 1, 0>; "
              "expected ',' but got the number 2");
}

TEST(Structure, UnclosedBlockPointsAtItsOpeningLine) {
    // The manual's own scene example.
    EXPECT_EQ(brief("scene {\n    sphere {\n        center: <1.0, 0.0, 0.0>;\n    }\n"
                    "    point_light {\n        position: <5.0, 5.0, 3.0>;\n"
                    "        intensity: <0.8, 0.8, 0.0>;\n}\n"),
              "1:1: error: this 'scene' block is never closed: expected '}' before the end of "
              "the file");
}

TEST(Structure, ErrorsAreAllReportedWithRecovery) {
    EXPECT_EQ(brief("scene {\n"
                    "  sphere { radius: -1; center: 3; }\n"
                    "  plane { normal: <0, 0, 0>; }\n"
                    "  cube { }\n"
                    "}\n"),
              "2:20: error: 'radius' must be greater than 0 and at most 1e+09, got -1\n"
              "2:32: error: 'center' takes a vector like <0, 1, 0>, got the number 3\n"
              "3:19: error: 'normal' must not be the zero vector, got <0, 0, 0>\n"
              "4:3: error: unknown block 'cube' in 'scene' (allowed: sphere, plane, cylinder, "
              "triangle, mesh, point_light, include)");
}

TEST(Structure, ErrorsAreCappedAtTwentyWithAFinalNote) {
    std::string text;
    for (int i = 0; i < 50; ++i) text += "junk;\n";
    ParseResult r = parse_scene(text);
    ASSERT_EQ(r.diagnostics.size(), 21u);
    EXPECT_EQ(r.diagnostics[19].pos, (SourcePos{20, 1}));
    EXPECT_EQ(r.diagnostics[20].message, "too many errors (20); stopping here");
    EXPECT_EQ(r.diagnostics[20].pos, (SourcePos{21, 1}));
}

TEST(Structure, PropertiesWhereOnlyBlocksGo) {
    EXPECT_EQ(brief("scene { radius: 1; }"),
              "1:9: error: 'scene' holds only blocks (sphere, plane, cylinder, triangle, mesh and "
              "point_light), not properties like 'radius'");
    EXPECT_EQ(brief("cameras { fov: 1; }"),
              "1:11: error: 'cameras' holds only blocks (perspective_camera), not properties "
              "like 'fov'");
}

TEST(Structure, StrayClosingBraceAtTopLevel) {
    EXPECT_EQ(brief("scene { }\n}"),
              "2:1: error: expected a block (render_settings, cameras or scene), got '}' (this "
              "'}' closes no block: is there one '}' too many?)");
}

// C's and POV-Ray's habit of a ';' after a block's '}' says so, and 'scene'
// is said to hold blocks, not properties.
TEST(Structure, ASemicolonAfterABlockSaysItIsNotNeeded) {
    EXPECT_EQ(brief("scene { sphere { radius: 1; };\n}"),
              "1:30: error: expected a block or '}' in 'scene', got ';' (a block ends at its "
              "'}', with no ';' after it)");
    EXPECT_EQ(brief("scene { sphere { material { } ; } }"),
              "1:31: error: expected a property name or '}' in 'sphere', got ';' (a block ends "
              "at its '}', with no ';' after it)");
    EXPECT_EQ(brief("scene { }\n  ;"),
              "2:3: error: expected a block (render_settings, cameras or scene), got ';' (a "
              "block ends at its '}', with no ';' after it)");
    EXPECT_EQ(brief("scene { , }"), "1:9: error: expected a block or '}' in 'scene', got ','");
}

// A block of the language written where it cannot stand is no unknown
// block: the message says where it goes (docs/language.md §3.3).
TEST(Structure, AKnownBlockInTheWrongPlaceSaysWhereItGoes) {
    ParseResult r = parse_scene(
        "sphere { radius: 1; }\n"
        "point_light { intensity: <1, 1, 1>; }\n"
        "perspective_camera { fov: 30; }\n"
        "scene { perspective_camera { } material { } render_settings { }\n"
        "  sphere { point_light { } radius: 2; } }\n"
        "cameras { sphere { } }\n"
        "transform { }\n");
    EXPECT_EQ(brief(r.diagnostics),
              "1:1: error: 'sphere' cannot stand at the top level: it stands in 'scene { ... }'\n"
              "2:1: error: 'point_light' cannot stand at the top level: it stands in "
              "'scene { ... }'\n"
              "3:1: error: 'perspective_camera' cannot stand at the top level: it stands in "
              "'cameras { ... }'\n"
              "4:9: error: 'perspective_camera' cannot stand in 'scene': it stands in "
              "'cameras { ... }'\n"
              "4:32: error: 'material' cannot stand in 'scene': it stands in a primitive "
              "(sphere, plane, cylinder, triangle or mesh), or named at the top level as "
              "'material NAME { ... }'\n"
              "4:45: error: 'render_settings' cannot stand in 'scene': it stands at the top "
              "level\n"
              "5:12: error: 'point_light' cannot stand in 'sphere': it stands in "
              "'scene { ... }' (is the '}' of the 'sphere' at 5:3 missing?)\n"
              "6:11: error: 'sphere' cannot stand in 'cameras': it stands in 'scene { ... }'\n"
              "7:1: error: 'transform' cannot stand at the top level: it stands in a primitive "
              "(sphere, plane, cylinder, triangle or mesh)");
    // Each is skipped whole: the sphere after it is read.
    ASSERT_EQ(r.scene.primitives.size(), 1u);
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives[0].shape).radius, 2.0);
    // Inside a block of properties too.
    EXPECT_EQ(brief("render_settings { perspective_camera { } }"),
              "1:19: error: 'perspective_camera' cannot stand in 'render_settings': it stands in "
              "'cameras { ... }'");
}

// POV-Ray's and C's habits of '(' after a value: 'pi()', a name called, a
// product without '*'.
TEST(Structure, AParenthesisAfterAValueSaysWhatTakesOne) {
    const std::string hint =
        " ('(' after a value neither calls it nor multiplies: only the functions take '(', pi, "
        "clock and defined names are values, and a product is written with '*')";
    EXPECT_EQ(brief("define r = 2;\n"
                    "scene { sphere { radius: pi(); } sphere { radius: r(2); } }\n"
                    "define s = 2(3);"),
              "2:28: error: expected ';' after the value of 'radius'" + hint + "\n" +
                  "2:52: error: expected ';' after the value of 'radius'" + hint + "\n" +
                  "3:13: error: expected ';' after the value of 'define s'" + hint);
}

// A block that stands beside the one it is in, or further out, most often
// follows a '}' left out: the message asks about that block's '}'.
TEST(Structure, ABlockInsideItsNeighbourAsksForTheMissingBrace) {
    EXPECT_EQ(brief("scene {\n"
                    "  sphere { radius: 1;\n"
                    "  sphere { radius: 2; }\n"
                    "}\n"),
              "3:3: error: 'sphere' cannot stand in 'sphere': it stands in 'scene { ... }' (is "
              "the '}' of the 'sphere' at 2:3 missing?)\n"
              "1:1: error: this 'scene' block is never closed: expected '}' before the end of "
              "the file");
    EXPECT_EQ(brief("scene { sphere { material { pigment: <1, 0, 0>;\n"
                    "  transform { scale: 2; } } }"),
              "2:3: error: 'transform' cannot stand in 'material': it stands in a primitive "
              "(sphere, plane, cylinder, triangle or mesh) (is the '}' of the 'material' at 1:18 "
              "missing?)\n"
              "1:1: error: this 'scene' block is never closed: expected '}' before the end of "
              "the file");
    EXPECT_EQ(brief("scene { point_light { sphere { } } }"),
              "1:23: error: 'sphere' cannot stand in 'point_light': it stands in 'scene { ... }' "
              "(is the '}' of the 'point_light' at 1:9 missing?)");
}

TEST(Structure, SeveralRenderSettingsLastWinsWholeWithAWarning) {
    ParseResult r = parse_scene(
        "render_settings { width: 10; height: 20; recurse_depth: 3; }\n"
        "render_settings { width: 30; }\n");
    EXPECT_EQ(brief(r.diagnostics),
              "2:1: warning: another 'render_settings' block: only the last one is used, so the "
              "one at line 1 is ignored");
    EXPECT_EQ(r.scene.settings.width, 30);
    EXPECT_EQ(r.scene.settings.height, 0);  // the default, not the earlier block's 20
    EXPECT_EQ(r.scene.settings.recurse_depth, 0);
    ASSERT_TRUE(r.source.render_settings);
    EXPECT_EQ(r.source.render_settings->keyword_span.pos.line, 2);
}

TEST(Structure, SeveralSceneBlocksLastWinsWithAWarning) {
    ParseResult r = parse_scene("scene { sphere { } point_light { } }\nscene { plane { } }\n");
    EXPECT_EQ(brief(r.diagnostics),
              "2:1: warning: another 'scene' block: only the last one is used, so the one at "
              "line 1 is ignored");
    ASSERT_EQ(r.scene.primitives.size(), 1u);
    EXPECT_TRUE(shape_is<Plane>(r.scene.primitives[0].shape));
    EXPECT_TRUE(r.scene.lights.empty());
    EXPECT_EQ(r.source.primitives.size(), 1u);
    EXPECT_TRUE(r.source.lights.empty());
}

TEST(Structure, CamerasAccumulateAcrossBlocksInFileOrder) {
    ParseResult r = parse_clean(
        "cameras { perspective_camera { name: \"a\"; } perspective_camera { name: \"b\"; } }\n"
        "cameras { perspective_camera { name: \"c\"; } }\n");
    ASSERT_EQ(r.scene.cameras.size(), 3u);
    EXPECT_EQ(r.scene.cameras[0].name, "a");
    EXPECT_EQ(r.scene.cameras[1].name, "b");
    EXPECT_EQ(r.scene.cameras[2].name, "c");
    EXPECT_EQ(r.source.cameras.size(), 3u);
}

TEST(Structure, RepeatedPropertyLaterWinsWithAWarning) {
    ParseResult r = parse_scene("scene { sphere {\n radius: 2;\n radius: 3;\n } }");
    EXPECT_EQ(brief(r.diagnostics),
              "3:2: warning: 'radius' is set again in this 'sphere'; the later value wins (first "
              "set at line 2)");
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives.at(0).shape).radius, 3.0);
}

TEST(Structure, TransformPropertiesAllApplyInOrderWithoutWarning) {
    ParseResult r = parse_clean(
        "scene { cylinder { transform { translate: <1, 0, 0>; zrotate: 45; translate: <1, 0, "
        "0>; scale: <2, 1, 1>; } } }");
    const auto& ops = r.scene.primitives.at(0).transforms;
    ASSERT_EQ(ops.size(), 4u);
    EXPECT_EQ(ops[0], (TransformOp{TransformKind::translate, {1, 0, 0}, 0}));
    EXPECT_EQ(ops[1], (TransformOp{TransformKind::zrotate, {0, 0, 0}, 45}));
    EXPECT_EQ(ops[2], (TransformOp{TransformKind::translate, {1, 0, 0}, 0}));
    EXPECT_EQ(ops[3], (TransformOp{TransformKind::scale, {2, 1, 1}, 0}));
}

TEST(Structure, SeveralTransformBlocksApplyInOrder) {
    ParseResult r = parse_clean(
        "scene { sphere { transform { xrotate: 10; } radius: 2; transform { yrotate: 20; } "
        "} }");
    const auto& ops = r.scene.primitives.at(0).transforms;
    ASSERT_EQ(ops.size(), 2u);
    EXPECT_EQ(ops[0].kind, TransformKind::xrotate);
    EXPECT_EQ(ops[0].degrees, 10.0);
    EXPECT_EQ(ops[1].kind, TransformKind::yrotate);
    EXPECT_EQ(ops[1].degrees, 20.0);
    EXPECT_EQ(children_of(r.source, r.source.primitives.at(0)).size(), 2u);
}

TEST(Structure, SeveralMaterialBlocksEachSetOnlyWhatTheyName) {
    ParseResult r = parse_clean(
        "scene { sphere {\n"
        "  material { pigment: <1, 0, 0>; reflection: 0.5; }\n"
        "  material { pigment: <0, 1, 0>; specular_k: 8; }\n"
        "} }");
    const Material& m = r.scene.primitives.at(0).material;
    EXPECT_EQ(m.pigment, Colour(0, 1, 0));
    EXPECT_EQ(m.finish->reflection, 0.5);
    EXPECT_EQ(m.finish->specular_k, 8.0);
    EXPECT_EQ(m.finish->diffuse_k, 1.0);
}

// POV-Ray's bare translate: the error says where it stands here.
TEST(Structure, ATransformPropertyOutsideATransformSaysWhereItGoes) {
    EXPECT_EQ(brief("scene { sphere { translate: <1, 0, 0>; } }"),
              "1:18: error: unknown property 'translate' in 'sphere' (allowed: center, radius, "
              "material, transform); write it in a transform block: transform { translate: "
              "...; }");
}

// One fact, one message: as a block or as 'material: NAME;'.
TEST(Structure, LightsTakeNoMaterialOrTransform) {
    EXPECT_EQ(brief("scene { point_light { material { pigment: <1, 1, 1>; } } }"),
              "1:23: error: a point_light takes no 'material': only sphere, plane, "
              "cylinder, triangle and mesh do");
    EXPECT_EQ(brief("scene { point_light {\n transform { translate: <1, 1, 1>; }\n} }"),
              "2:2: error: a point_light takes no 'transform': only sphere, plane, "
              "cylinder, triangle and mesh do");
    EXPECT_EQ(brief("material m { pigment: <1, 0, 0>; }\n"
                    "scene { point_light { material: m; } }"),
              "2:23: error: a point_light takes no 'material': only sphere, plane, "
              "cylinder, triangle and mesh do");
}

TEST(Structure, ActiveCameraInsideACameraIsReadAsNameWithAWarning) {
    ParseResult r = parse_scene(
        "cameras {\n  perspective_camera {\n    active_camera: \"Far Angle Camera\";\n  }\n}");
    EXPECT_EQ(brief(r.diagnostics),
              "3:5: warning: 'active_camera' inside a camera is read as 'name'; write name: "
              "\"Far Angle Camera\"; instead");
    EXPECT_EQ(r.scene.cameras.at(0).name, "Far Angle Camera");
    ASSERT_FALSE(properties_of(r.source, r.source.cameras.at(0)).empty());
    EXPECT_EQ(properties_of(r.source, r.source.cameras.at(0))[0].name, "name");
}

TEST(Structure, NoSceneBlockParsesClean) {
    ParseResult r = parse_clean("cameras { perspective_camera { } }");
    EXPECT_FALSE(r.source.scene);
}

}  // namespace
}  // namespace jt

namespace jt {
namespace {

TEST(Structure, BlocksInsideBlocksThatHoldOnlyProperties) {
    EXPECT_EQ(test::brief("render_settings { foo { } width: 2; }"),
              "1:19: error: unexpected block 'foo' in 'render_settings', which holds only "
              "properties");
    EXPECT_EQ(test::brief("scene { sphere { material { x { } } } }"),
              "1:29: error: unexpected block 'x' in 'material', which holds only properties");
    EXPECT_EQ(test::brief("cameras { perspective_camera { bar { } } }"),
              "1:32: error: unexpected block 'bar' in 'perspective_camera', which holds only "
              "properties");
    EXPECT_EQ(test::brief("scene { sphere { transform { y { } } } }"),
              "1:30: error: unexpected block 'y' in 'transform', which holds only properties");
    EXPECT_EQ(test::brief("scene { point_light { glow { } } }"),
              "1:23: error: unexpected block 'glow' in 'point_light', which holds only "
              "properties");
}

}  // namespace
}  // namespace jt
