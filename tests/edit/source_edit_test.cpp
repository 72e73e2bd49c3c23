// Save-in-place: edited values are written at their spans; every other byte
// of the file stays as it was.

#include "jtracer/source_edit.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/value_text.hpp"

#include "common/files.hpp"
#include "common/scenes.hpp"

#include <gtest/gtest.h>

namespace jt {
namespace {

// A file with comments, odd spacing, a one-line block and a repeated property.
constexpr const char* kScene = R"(# header comment
render_settings {
    width: 64;   # keep this comment
    height:48;
}
cameras {
    perspective_camera { name: "front"; position: <0, 0, 5>; }  # inline
    perspective_camera {
        active_camera: "side";
        position: <5, 0, 0>;
        look_at: <0,0,0>;
    }
}
scene {
    sphere {
        radius: 1;
        material { pigment: <1, 0, 0>; }
        material {
            diffuse: <0.5, 0.5, 0.5>;  # last material block
        }
        transform { translate: <0, 1, 0>; yrotate: 30; translate: <1, 0, 0>; }
    }
    sphere { center: <2, 0, 0>; }
    point_light {
        position: <0, 5, 5>;
        intensity: <1, 1, 1>;
    }
}
)";

ParseResult parse_ok(std::string_view text) {
    ParseResult r = parse_scene(text);
    EXPECT_TRUE(r.ok()) << "fixture does not parse";
    return r;
}

// Applies the edit, checks it reads back as `edited`, returns the new text.
std::string save(const std::string& text, const Scene& edited) {
    ParseResult base = parse_ok(text);
    SourceEditResult result = apply_scene_edits(text, base.source, base.scene, edited);
    EXPECT_TRUE(result.ok()) << result.error;
    ParseResult again = parse_scene(result.text);
    EXPECT_TRUE(again.ok());
    EXPECT_EQ(again.scene, edited);
    return result.text;
}

std::string replace_once(std::string text, std::string_view from, std::string_view to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

TEST(SourceEdit, NothingChangedGivesTheSameBytes) {
    ParseResult base = parse_ok(kScene);
    SourceEditResult result = apply_scene_edits(kScene, base.source, base.scene, base.scene);
    EXPECT_TRUE(result.ok());
    EXPECT_EQ(result.text, kScene);
    EXPECT_EQ(result.values_changed, 0);
}

TEST(SourceEdit, ReplacesOnlyTheValueInForce) {
    Scene edited = parse_ok(kScene).scene;
    edited.settings.height = 100;
    edited.primitives[0].material.finish.edit().diffuse = Colour(0.25, 0.5, 1.0);
    edited.lights[0].intensity = Colour(0.3, 0.2, 0.1);
    std::string expected = replace_once(kScene, "height:48;", "height:100;");
    expected = replace_once(expected, "diffuse: <0.5, 0.5, 0.5>;", "diffuse: <0.25, 0.5, 1>;");
    expected = replace_once(expected, "intensity: <1, 1, 1>;", "intensity: <0.3, 0.2, 0.1>;");
    EXPECT_EQ(save(kScene, edited), expected);
}

TEST(SourceEdit, InsertsAMissingPropertyOnItsOwnLineWithTheBlocksIndent) {
    Scene edited = parse_ok(kScene).scene;
    edited.settings.samples = 4;
    edited.lights[0].position = Vec3(1, 2, 3);
    std::string expected =
        replace_once(kScene, "    height:48;\n}", "    height:48;\n    samples: 4;\n}");
    expected = replace_once(expected, "position: <0, 5, 5>;", "position: <1, 2, 3>;");
    EXPECT_EQ(save(kScene, edited), expected);
}

// An optional value cleared in a panel (a camera's focus_distance, a
// material's checker) loses its statements; every other byte stays.
TEST(SourceEdit, AnUnsetOptionalValueLosesItsStatements) {
    const std::string text = replace_once(
        replace_once(kScene, "        look_at: <0,0,0>;\n",
                     "        look_at: <0,0,0>;\n        focus_distance: 3;  # near\n"),
        "material { pigment: <1, 0, 0>; }", "material { pigment: <1, 0, 0>; checker: <0, 0, 1>; }");
    Scene edited = parse_ok(text).scene;
    ASSERT_TRUE(edited.cameras[1].focus_distance);
    edited.cameras[1].focus_distance.reset();
    edited.primitives[0].material.finish.edit().checker.reset();
    EXPECT_EQ(save(text, edited), kScene);
}

TEST(SourceEdit, AnEmptiedBackgroundMapLosesItsStatement) {
    const std::string text = replace_once(kScene, "    height:48;\n",
                                          "    height:48;\n    background_map: \"sky.png\";\n");
    Scene edited = parse_ok(text).scene;
    edited.settings.background_map.clear();
    EXPECT_EQ(save(text, edited), kScene);
}

TEST(SourceEdit, InsertsIntoAOneLineBlockInline) {
    Scene edited = parse_ok(kScene).scene;
    edited.cameras[0].fov = 60;
    const std::string expected =
        replace_once(kScene, R"(position: <0, 0, 5>; })", R"(position: <0, 0, 5>; fov: 60; })");
    EXPECT_EQ(save(kScene, edited), expected);
}

// Several properties inserted into one line at once are spaced as one would
// type them, whichever spacing the block has before its brace.
TEST(SourceEdit, SeveralInlineInsertionsAreSpacedOnce) {
    Scene edited = parse_ok(kScene).scene;
    edited.cameras[0].fov = 60;
    edited.cameras[0].aspect = 2;
    std::string expected = replace_once(kScene, R"(position: <0, 0, 5>; })",
                                        R"(position: <0, 0, 5>; aspect: 2; fov: 60; })");
    EXPECT_EQ(save(kScene, edited), expected);

    const std::string tight =
        replace_once(kScene, R"(position: <0, 0, 5>; })", R"(position: <0, 0, 5>;})");
    expected = replace_once(kScene, R"(position: <0, 0, 5>; })",
                            R"(position: <0, 0, 5>; aspect: 2; fov: 60;})");
    EXPECT_EQ(save(tight, edited), expected);
}

TEST(SourceEdit, MaterialPropertyNeverWrittenGoesToTheLastMaterialBlock) {
    Scene edited = parse_ok(kScene).scene;
    edited.primitives[0].material.finish.edit().reflection = 0.5;
    const std::string expected =
        replace_once(kScene, "            diffuse: <0.5, 0.5, 0.5>;  # last material block\n",
                     "            diffuse: <0.5, 0.5, 0.5>;  # last material block\n"
                     "            reflection: 0.5;\n");
    EXPECT_EQ(save(kScene, edited), expected);
}

TEST(SourceEdit, PrimitiveWithoutMaterialGetsAMaterialBlock) {
    Scene edited = parse_ok(kScene).scene;
    edited.primitives[1].material.pigment = Colour(0, 1, 0);
    const std::string expected =
        replace_once(kScene, "sphere { center: <2, 0, 0>; }",
                     "sphere { center: <2, 0, 0>; material { pigment: <0, 1, 0>; } }");
    EXPECT_EQ(save(kScene, edited), expected);
}

TEST(SourceEdit, TransformOperationsAreEditedInOrder) {
    Scene edited = parse_ok(kScene).scene;
    ASSERT_EQ(edited.primitives[0].transforms.size(), 3u);
    edited.primitives[0].transforms[1].degrees = 45;
    edited.primitives[0].transforms[2].vector = Vec3(2, 0, 0);
    const std::string expected = replace_once(kScene, "yrotate: 30; translate: <1, 0, 0>;",
                                              "yrotate: 45; translate: <2, 0, 0>;");
    EXPECT_EQ(save(kScene, edited), expected);
}

TEST(SourceEdit, CameraNameWrittenAsActiveCameraAliasIsEditedThere) {
    Scene edited = parse_ok(kScene).scene;
    ASSERT_EQ(edited.cameras[1].name, "side");
    edited.cameras[1].name = "left";
    EXPECT_EQ(save(kScene, edited),
              replace_once(kScene, R"(active_camera: "side";)", R"(active_camera: "left";)"));
}

TEST(SourceEdit, NewCameraIsAppendedToTheCamerasBlock) {
    Scene edited = parse_ok(kScene).scene;
    Camera camera;
    camera.name = "viewer";
    camera.position = Vec3(1, 2, 3);
    camera.look_at = Vec3(0, 0.5, 0);
    camera.aspect = 1.5;
    camera.fov = 50;
    edited.cameras.push_back(camera);
    const std::string expected = replace_once(kScene, "        look_at: <0,0,0>;\n    }\n}\n",
                                              "        look_at: <0,0,0>;\n    }\n"
                                              "    perspective_camera {\n"
                                              "        name: \"viewer\";\n"
                                              "        position: <1, 2, 3>;\n"
                                              "        look_at: <0, 0.5, 0>;\n"
                                              "        up: <0, 1, 0>;\n"
                                              "        aspect: 1.5;\n"
                                              "        fov: 50;\n"
                                              "    }\n}\n");
    EXPECT_EQ(save(kScene, edited), expected);
}

TEST(SourceEdit, RemovingTheNewCameraAgainGivesBackTheSameBytes) {
    const Scene base = parse_ok(kScene).scene;
    Scene edited = base;
    edited.cameras.push_back(base.cameras[0]);
    edited.cameras.back().name = "copy";
    const std::string with_camera = save(kScene, edited);
    EXPECT_EQ(save(with_camera, base), kScene);
}

TEST(SourceEdit, RemovingAnInlineCameraLeavesTheRestOfItsLine) {
    const std::string text =
        "cameras { perspective_camera { name: \"a\"; } "
        "perspective_camera { name: \"b\"; } }  # two\n";
    Scene edited = parse_ok(text).scene;
    edited.cameras.pop_back();
    EXPECT_EQ(save(text, edited), "cameras { perspective_camera { name: \"a\"; } }  # two\n");
}

TEST(SourceEdit, ShowcaseGetsANewCameraInItsOwnStyle) {
    const std::string text = test::read_file(test::source_path("scenes/showcase.jts"));
    Scene edited = parse_ok(text).scene;
    Camera camera = edited.cameras[0];
    camera.name = "viewer 1";
    camera.position = Vec3(1.5, 2, 8.25);
    edited.cameras.push_back(camera);
    const std::string saved = save(text, edited);
    // Inserted as the last camera of the cameras block, indented like the others.
    const std::size_t at = saved.find("    perspective_camera {\n        name: \"viewer 1\";");
    ASSERT_NE(at, std::string::npos) << saved;
    const std::string inserted =
        "    perspective_camera {\n"
        "        name: \"viewer 1\";\n"
        "        position: <1.5, 2, 8.25>;\n"
        "        look_at: <0, 1, 0>;\n"
        "        up: <0, 1, 0>;\n"
        "        aspect: 1.7777777777777777;\n"
        "        fov: 38;\n"
        "    }\n";
    EXPECT_EQ(saved.substr(at, inserted.size()), inserted);
    EXPECT_EQ(saved.substr(0, at) + saved.substr(at + inserted.size()), text)
        << "every other byte as it was";
    EXPECT_EQ(saved.substr(at + inserted.size(), 2), "}\n") << "inside the cameras block";
}

TEST(SourceEdit, MissingRenderSettingsBlockIsAppended) {
    const std::string text = "cameras { perspective_camera { } }\n";
    Scene edited = parse_ok(text).scene;
    edited.settings.width = 32;
    edited.settings.background = Colour(0.5, 0, 0);
    EXPECT_EQ(save(text, edited), text +
                                      "\nrender_settings {\n    width: 32;\n"
                                      "    background: <0.5, 0, 0>;\n}\n");
}

TEST(SourceEdit, StructuralChangesAreRefusedAndTheTextKept) {
    ParseResult base = parse_ok(kScene);
    Scene edited = base.scene;
    edited.primitives.pop_back();
    SourceEditResult result = apply_scene_edits(kScene, base.source, base.scene, edited);
    EXPECT_FALSE(result.ok());
    EXPECT_NE(result.error.find("primitives"), std::string::npos);
    EXPECT_EQ(result.text, kScene);
}

TEST(SourceEdit, NumbersUseTheShortestTextThatReadsBack) {
    EXPECT_EQ(number_text(2.0), "2");
    EXPECT_EQ(number_text(0.1), "0.1");
    EXPECT_EQ(number_text(-0.0), "0");
    EXPECT_EQ(number_text(1e-5), "1e-05");
    EXPECT_EQ(number_text(0.1 + 0.2), "0.30000000000000004");  // nothing shorter reads back
    EXPECT_EQ(vector_text(Vec3(1, -0.5, 0.25)), "<1, -0.5, 0.25>");
}

TEST(SourceEdit, OneComponentEditKeepsTheOtherComponentsText) {
    const std::string text =
        "cameras { perspective_camera { position: <-5.0, 8.0, 6.0>; } }\n"
        "scene { sphere { transform { translate: < 1.50 ,2.0, # up\n 3e0 >; } } }\n";
    Scene edited = parse_ok(text).scene;
    edited.cameras[0].position.x = 5;
    edited.primitives[0].transforms[0].vector.z = 0.25;
    EXPECT_EQ(save(text, edited),
              "cameras { perspective_camera { position: <5, 8.0, 6.0>; } }\n"
              "scene { sphere { transform { translate: < 1.50 ,2.0, # up\n 0.25 >; } } }\n");
    // A clipped colour component is written as the value it reads as.
    const std::string colour = "scene { point_light { intensity: <2.0, 0.50, 1>; } }";
    Scene dimmer = parse_scene(colour).scene;
    dimmer.lights[0].intensity.z = 0.5;
    ParseResult base = parse_scene(colour);
    EXPECT_EQ(apply_scene_edits(colour, base.source, base.scene, dimmer).text,
              "scene { point_light { intensity: <1, 0.50, 0.5>; } }");
}

TEST(SourceEdit, ShowcaseEditChangesOnlyThatValuesBytes) {
    const std::string text = test::read_file(test::source_path("scenes/showcase.jts"));
    ParseResult base = parse_ok(text);
    ASSERT_FALSE(base.scene.primitives.empty());
    Scene edited = base.scene;
    edited.primitives[0].material.pigment = Colour(0.125, 0.25, 0.5);
    const std::string saved = save(text, edited);
    const BlockSource& material = children_of(base.source, base.source.primitives[0])[0];
    const PropertySource& pigment = properties_of(base.source, material)[0];
    const TextSpan span = pigment.value_span;
    ASSERT_EQ(pigment.name, "pigment");
    EXPECT_EQ(saved.substr(0, span.offset), text.substr(0, span.offset));
    EXPECT_EQ(saved.substr(span.offset, 20), "<0.125, 0.25, 0.5>;\n");
    EXPECT_EQ(saved.substr(span.offset + 18), text.substr(span.offset + span.length));
}

}  // namespace
}  // namespace jt
