// The parser on valid input: structure, spans, defaults.

#include "jtracer/parser.hpp"

#include "test_util.hpp"

#include <gtest/gtest.h>

namespace jt {
namespace {

TEST(ParseBasics, EmptyTextIsAnEmptySceneWithNoDiagnostics) {
    ParseResult r = parse_scene("");
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_EQ(r.scene, Scene{});
}

TEST(ParseBasics, ReadsEveryBlockKind) {
    ParseResult r = parse_scene(R"(
render_settings { width: 64; height: 32; recurse_depth: 2; filename: "a.bmp";
                  active_camera: "b"; background: <0.1, 0.2, 0.3>;
                  ambient_light: <0.5, 0.5, 0.5>; samples: 4; }
cameras {
    perspective_camera { name: "a"; position: <1, 2, 3>; look_at: <0, 0, 0>;
                         up: <0, 0, 1>; aspect: 2; fov: 60; }
    perspective_camera { name: "b"; }
}
scene {
    sphere { center: <1, 0, 0>; radius: 2; }
    plane { normal: <0, 0, 1>; distance: -2; }
    cylinder { radius: 0.75; height: 5; }
    point_light { position: <1.5, 2, 4>; intensity: <0, 0.8, 0>; }
}
)");
    ASSERT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].message;
    const Scene& s = r.scene;
    EXPECT_EQ(s.settings.width, 64);
    EXPECT_EQ(s.settings.height, 32);
    EXPECT_EQ(s.settings.recurse_depth, 2);
    EXPECT_EQ(s.settings.filename, "a.bmp");
    EXPECT_EQ(s.settings.active_camera, "b");
    EXPECT_EQ(s.settings.background, Colour(0.1, 0.2, 0.3));
    EXPECT_EQ(s.settings.ambient_light, Colour(0.5));
    EXPECT_EQ(s.settings.samples, 4);
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_EQ(s.cameras[0].name, "a");
    EXPECT_EQ(s.cameras[0].position, Vec3(1, 2, 3));
    EXPECT_EQ(s.cameras[0].look_at, Vec3(0, 0, 0));
    EXPECT_EQ(s.cameras[0].up, Vec3(0, 0, 1));
    EXPECT_EQ(s.cameras[0].aspect, 2.0);
    EXPECT_EQ(s.cameras[0].fov, 60.0);
    EXPECT_EQ(s.cameras[1], (test::named_camera("b")));
    ASSERT_EQ(s.primitives.size(), 3u);
    EXPECT_EQ(shape_as<Sphere>(s.primitives[0].shape), (Sphere{{1, 0, 0}, 2}));
    EXPECT_EQ(shape_as<Plane>(s.primitives[1].shape), (Plane{{0, 0, 1}, -2}));
    EXPECT_EQ(shape_as<Cylinder>(s.primitives[2].shape), (Cylinder{0.75, 5}));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].position, Vec3(1.5, 2, 4));
    EXPECT_EQ(s.lights[0].intensity, Colour(0, 0.8, 0));
}

TEST(ParseBasics, SourceSpansPointAtNamesAndValues) {
    std::string text =
        "scene {\n  sphere {\n    radius: 2.5;\n    material { pigment: <1, 0, 0>; }\n  }\n}\n";
    ParseResult r = parse_scene(text);
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(r.source.scene.has_value());
    ASSERT_EQ(r.source.primitives.size(), 1u);
    const BlockSource& sphere = r.source.primitives[0];
    EXPECT_EQ(sphere.keyword, "sphere");
    EXPECT_EQ(sphere.keyword_span.pos, (SourcePos{2, 3}));
    EXPECT_EQ(text[sphere.open_brace], '{');
    EXPECT_EQ(text[sphere.close_brace], '}');
    ASSERT_EQ(properties_of(r.source, sphere).size(), 1u);
    const PropertySource& radius = properties_of(r.source, sphere)[0];
    EXPECT_EQ(radius.name, "radius");
    EXPECT_EQ(radius.name_span.pos, (SourcePos{3, 5}));
    EXPECT_EQ(text.substr(radius.value_span.offset, radius.value_span.length), "2.5");
    EXPECT_EQ(radius.value_span.pos, (SourcePos{3, 13}));
    ASSERT_EQ(children_of(r.source, sphere).size(), 1u);
    const BlockSource& material = children_of(r.source, sphere)[0];
    EXPECT_EQ(material.keyword, "material");
    ASSERT_EQ(properties_of(r.source, material).size(), 1u);
    const PropertySource& pigment = properties_of(r.source, material)[0];
    EXPECT_EQ(text.substr(pigment.value_span.offset, pigment.value_span.length), "<1, 0, 0>");
}

// Names and keywords in the source map refer to static storage, never to the
// text, which the caller may drop (the CLI does, before rendering).
TEST(ParseBasics, SourceRecordsOutliveTheText) {
    ParseResult r;
    {
        std::string text =
            "cameras { perspective_camera { active_camera: \"A\"; } }\n"
            "scene { cylinder { height: 2; transform { scale: <1, 2, 1>; } } }\n";
        r = parse_scene(text);
    }
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.source.primitives.size(), 1u);
    const BlockSource& cylinder = r.source.primitives[0];
    EXPECT_EQ(cylinder.keyword, "cylinder");
    EXPECT_EQ(properties_of(r.source, cylinder)[0].name, "height");
    const BlockSource& transform = children_of(r.source, cylinder)[0];
    EXPECT_EQ(transform.keyword, "transform");
    EXPECT_EQ(properties_of(r.source, transform)[0].name, "scale");
    EXPECT_EQ(r.source.cameras.at(0).keyword, "perspective_camera");
    EXPECT_EQ(properties_of(r.source, r.source.cameras.at(0))[0].name, "name");
}

}  // namespace
}  // namespace jt
