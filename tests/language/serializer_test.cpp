// serialize_scene: canonical text that reads back to exactly the same scene.

#include "jtracer/serializer.hpp"

#include "test_util.hpp"

#include <cmath>
#include <limits>

namespace jt {
namespace {

Scene awkward_scene() {
    Scene s;
    s.settings.width = 641;
    s.settings.height = 479;
    s.settings.recurse_depth = 7;
    s.settings.filename = "out dir/image.bmp";
    s.settings.active_camera = "Second";
    s.settings.background = {0.1, 1.0 / 3.0, 2.0 / 3.0};
    s.settings.ambient_light = {std::nextafter(0.5, 1.0), 0, 1};
    s.settings.samples = 16;
    s.cameras.push_back(Camera{"First",
                               {0.1, 0.2, 0.3},
                               {1e-300, -0.0, 987654321.00000012},
                               {0, 0, 1},
                               1.3333333333333333,
                               33.3,
                               0.0,
                               std::nullopt});
    s.cameras.push_back(test::named_camera("Second"));
    s.primitives.push_back(
        Primitive{Sphere{{std::numeric_limits<double>::min(), 1e-17, -7.125}, 0.30000000000000004},
                  Material{{1, 0, 0},
                           Finish{{0.2, 0.2, 0.2},
                                  {0.9, 0.8, 0.7},
                                  {1, 1, 1},
                                  2.5,
                                  128,
                                  0.75,
                                  0.5,
                                  1.5,
                                  Colour{0, 1, 0},
                                  0.25,
                                  "maps/a.png",
                                  2.0}},
                  {{TransformKind::translate, {1, 2, 3}, 0},
                   {TransformKind::xrotate, {0, 0, 0}, -90},
                   {TransformKind::scale, {2, 0.5, 1}, 0},
                   {TransformKind::yrotate, {0, 0, 0}, 1e-9},
                   {TransformKind::zrotate, {0, 0, 0}, 45}}});
    s.primitives.push_back(Primitive{Plane{{0, 0, -3}, -2.5}, Material{}, {}});
    s.primitives.push_back(Primitive{Cylinder{0.75, 5}, test::reflective(1), {}});
    s.lights.push_back(PointLight{{1.5, 2, 4}, {0, 0.8, 0}});
    return s;
}

TEST(Serializer, AwkwardValuesReadBackExactly) {
    Scene s = awkward_scene();
    std::string text = serialize_scene(s);
    ParseResult r = parse_scene(text);
    EXPECT_EQ(test::brief(r.diagnostics), "") << text;
    EXPECT_TRUE(r.scene == s) << text;
}

TEST(Serializer, WritesShortNumbersAndAFixedLayout) {
    Scene s;
    s.settings.width = 2;
    s.cameras.push_back(test::named_camera("c"));
    s.primitives.push_back(Primitive{Sphere{{0.1, 0, -2}, 1.5}, Material{}, {}});
    EXPECT_EQ(serialize_scene(s),
              "# Written by JTracer.\n"
              "\n"
              "render_settings {\n"
              "    width: 2;\n"
              "    height: 0;\n"
              "    recurse_depth: 0;\n"
              "    filename: \"jtracer.bmp\";\n"
              "    background: <0, 0, 0>;\n"
              "    ambient_light: <0, 0, 0>;\n"
              "}\n"
              "\n"
              "cameras {\n"
              "    perspective_camera {\n"
              "        name: \"c\";\n"
              "        position: <0, 0, 0>;\n"
              "        look_at: <0, 0, -1>;\n"
              "        up: <0, 1, 0>;\n"
              "        aspect: 1;\n"
              "        fov: 45;\n"
              "    }\n"
              "}\n"
              "\n"
              "scene {\n"
              "    sphere {\n"
              "        center: <0.1, 0, -2>;\n"
              "        radius: 1.5;\n"
              "        material {\n"
              "            pigment: <0, 0, 0>;\n"
              "            ambient: <0, 0, 0>;\n"
              "            diffuse: <0, 0, 0>;\n"
              "            specular: <0, 0, 0>;\n"
              "            diffuse_k: 1;\n"
              "            specular_k: 64;\n"
              "            reflection: 0;\n"
              "        }\n"
              "    }\n"
              "}\n");
}

TEST(Serializer, UnwritableStringCharactersBecomeUnderscores) {
    Scene s;
    s.settings.filename = "a\"b\nc";
    ParseResult r = parse_scene(serialize_scene(s));
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.scene.settings.filename, "a_b_c");
}

TEST(Serializer, EmptySceneReadsBackEqual) {
    ParseResult r = parse_scene(serialize_scene(Scene{}));
    EXPECT_EQ(test::brief(r.diagnostics), "");
    EXPECT_TRUE(r.scene == Scene{});
}

// A `mesh { }` without its `file` parses (the validator reports it); writing
// its empty default as `file: "";` made text that does not parse. Kept as
// tests/hardening/regressions/parser/mesh-without-file.jts.
TEST(Serializer, AMeshWithoutItsFileReadsBackEqual) {
    ParseResult first = parse_scene("scene { mesh { } }");
    ASSERT_TRUE(first.ok()) << test::brief(first.diagnostics);
    const std::string text = serialize_scene(first.scene);
    EXPECT_EQ(text.find("file:"), std::string::npos) << text;
    ParseResult again = parse_scene(text);
    EXPECT_TRUE(again.ok()) << test::brief(again.diagnostics) << "\n" << text;
    EXPECT_TRUE(again.scene == first.scene) << text;
}

}  // namespace
}  // namespace jt
