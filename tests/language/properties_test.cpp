// docs/language.md §4: every property's default, kind and range.

#include "test_util.hpp"

namespace jt {
namespace {

using test::brief;
using test::parse_clean;

TEST(Defaults, EmptyBlocksGiveTheTableDefaults) {
    ParseResult r = parse_clean(
        "render_settings { }\n"
        "cameras { perspective_camera { } }\n"
        "scene { sphere { material { } transform { } } plane { } cylinder { } point_light { } "
        "}");
    const Scene& s = r.scene;
    EXPECT_EQ(s.settings.width, 0);
    EXPECT_EQ(s.settings.height, 0);
    EXPECT_EQ(s.settings.recurse_depth, 0);
    EXPECT_EQ(s.settings.filename, "jtracer.bmp");
    EXPECT_EQ(s.settings.active_camera, "");
    EXPECT_EQ(s.settings.background, Colour(0));
    EXPECT_EQ(s.settings.ambient_light, Colour(0));
    EXPECT_EQ(s.settings.samples, 1);
    const Camera& c = s.cameras.at(0);
    EXPECT_EQ(c.name, "");
    EXPECT_EQ(c.position, Vec3(0, 0, 0));
    EXPECT_EQ(c.look_at, Vec3(0, 0, -1));
    EXPECT_EQ(c.up, Vec3(0, 1, 0));
    EXPECT_EQ(c.aspect, 1.0);
    EXPECT_EQ(c.fov, 45.0);
    ASSERT_EQ(s.primitives.size(), 3u);
    EXPECT_EQ(shape_as<Sphere>(s.primitives[0].shape), (Sphere{{0, 0, 0}, 1.0}));
    EXPECT_EQ(shape_as<Plane>(s.primitives[1].shape), (Plane{{0, 1, 0}, 0.0}));
    EXPECT_EQ(shape_as<Cylinder>(s.primitives[2].shape), (Cylinder{0.5, 1.0}));
    const Material& m = s.primitives[0].material;
    EXPECT_EQ(m.pigment, Colour(0));
    EXPECT_EQ(m.finish->ambient, Colour(0));
    EXPECT_EQ(m.finish->diffuse, Colour(0));
    EXPECT_EQ(m.finish->specular, Colour(0));
    EXPECT_EQ(m.finish->diffuse_k, 1.0);
    EXPECT_EQ(m.finish->specular_k, 64.0);
    EXPECT_EQ(m.finish->reflection, 0.0);
    EXPECT_TRUE(s.primitives[0].transforms.empty());
    EXPECT_EQ(s.lights.at(0).position, Vec3(0));
    EXPECT_EQ(s.lights.at(0).intensity, Colour(0));
}

TEST(Ints, AreTruncatedTowardZero) {
    ParseResult r = parse_clean(
        "render_settings { width: 640.9; height: 480.5; recurse_depth: 2.99; samples: 4.7; }");
    EXPECT_EQ(r.scene.settings.width, 640);
    EXPECT_EQ(r.scene.settings.height, 480);
    EXPECT_EQ(r.scene.settings.recurse_depth, 2);
    EXPECT_EQ(r.scene.settings.samples, 4);
    EXPECT_EQ(parse_clean("render_settings { recurse_depth: -0.5; }").scene.settings.recurse_depth,
              0);
}

TEST(Ints, WidthAndHeightRanges) {
    EXPECT_EQ(parse_clean("render_settings { width: 0; }").scene.settings.width, 0);
    EXPECT_EQ(parse_clean("render_settings { width: 65535; }").scene.settings.width, 65535);
    EXPECT_EQ(brief("render_settings { width: 65536; }"),
              "1:26: error: 'width' must be a whole number from 0 to 65535, got 65536");
    EXPECT_EQ(brief("render_settings { height: -2; }"),
              "1:27: error: 'height' must be a whole number from 0 to 65535, got -2");
    EXPECT_EQ(brief("render_settings { width: 1e300; }"),
              "1:26: error: 'width' must be a whole number from 0 to 65535, got 1e300");
}

TEST(Ints, RecurseDepthAbove256IsClampedWithAWarning) {
    ParseResult r = parse_scene("render_settings { recurse_depth: 1000; }");
    EXPECT_EQ(brief(r.diagnostics),
              "1:34: warning: 'recurse_depth' 1000 is more than 256: clamped to 256");
    EXPECT_EQ(r.scene.settings.recurse_depth, 256);
    EXPECT_EQ(brief("render_settings { recurse_depth: -1; }"),
              "1:34: error: 'recurse_depth' must be 0 or more, got -1");
}

TEST(Ints, SamplesExtensionRange) {
    EXPECT_EQ(parse_clean("render_settings { samples: 1024; }").scene.settings.samples, 1024);
    EXPECT_EQ(brief("render_settings { samples: 0; }"),
              "1:28: error: 'samples' must be a whole number from 1 to 1024, got 0");
    EXPECT_EQ(brief("render_settings { samples: 1025; }"),
              "1:28: error: 'samples' must be a whole number from 1 to 1024, got 1025");
}

TEST(Colours, AreClippedToZeroOneWithAWarning) {
    ParseResult r = parse_scene("scene { point_light { intensity: <1.5, -0.2, 0.5>; } }");
    EXPECT_EQ(brief(r.diagnostics),
              "1:34: warning: 'intensity' <1.5, -0.2, 0.5> is outside the colour range [0, 1]: "
              "clipped to <1, 0, 0.5>");
    EXPECT_EQ(r.scene.lights.at(0).intensity, Colour(1, 0, 0.5));
    // In range: no warning, and every colour property clips.
    parse_clean("render_settings { background: <0, 1, 0.5>; }");
    for (std::string name : {"pigment", "ambient", "diffuse", "specular"}) {
        ParseResult m = parse_scene("scene { sphere { material { " + name + ": <2, 0, 0>; } } }");
        EXPECT_EQ(m.diagnostics.size(), 1u) << name;
        EXPECT_EQ(m.scene.primitives.at(0).material.pigment.x +
                      m.scene.primitives[0].material.finish->ambient.x +
                      m.scene.primitives[0].material.finish->diffuse.x +
                      m.scene.primitives[0].material.finish->specular.x,
                  1.0)
            << name;
    }
    EXPECT_EQ(
        parse_scene("render_settings { ambient_light: <0, 0, 7>; }").scene.settings.ambient_light,
        Colour(0, 0, 1));
}

TEST(Vectors, AreNotClipped) {
    ParseResult r = parse_clean("scene { sphere { center: <-5, 10, 1e3>; } }");
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives.at(0).shape).center, Vec3(-5, 10, 1000));
}

TEST(Camera, AspectMustBePositive) {
    EXPECT_EQ(brief("cameras { perspective_camera { aspect: 0; } }"),
              "1:40: error: 'aspect' must be greater than 0 and at most 1e+09, got 0");
}

TEST(Camera, FovMustBeStrictlyBetween0And180) {
    EXPECT_EQ(parse_clean("cameras { perspective_camera { fov: 179.9; } }").scene.cameras[0].fov,
              179.9);
    EXPECT_EQ(brief("cameras { perspective_camera { fov: 180; } }"),
              "1:37: error: 'fov' must be between 0 and 180 degrees (exclusive), got 180");
    EXPECT_EQ(brief("cameras { perspective_camera { fov: 0; } }"),
              "1:37: error: 'fov' must be between 0 and 180 degrees (exclusive), got 0");
}

TEST(Camera, UnknownPropertyIsAnError) {
    EXPECT_EQ(brief("cameras { perspective_camera { lookat: <0, 0, 0>; } }"),
              "1:32: error: unknown property 'lookat' in 'perspective_camera'; did you mean "
              "'look_at'? (allowed: name, position, look_at, up, aspect, fov, aperture, "
              "focus_distance)");
}

TEST(Shapes, RadiusAndHeightMustBePositive) {
    EXPECT_EQ(brief("scene { sphere { radius: 0; } }"),
              "1:26: error: 'radius' must be greater than 0 and at most 1e+09, got 0");
    EXPECT_EQ(brief("scene { cylinder { radius: -1; height: 0; } }"),
              "1:28: error: 'radius' must be greater than 0 and at most 1e+09, got -1\n"
              "1:40: error: 'height' must be greater than 0 and at most 1e+09, got 0");
}

TEST(Shapes, RejectedValuesLeaveTheDefault) {
    ParseResult r = parse_scene("scene { cylinder { radius: -1; height: 2; } }");
    EXPECT_EQ(shape_as<Cylinder>(r.scene.primitives.at(0).shape), (Cylinder{0.5, 2.0}));
}

TEST(Shapes, PlaneNormalMustBeNonZeroAndIsKeptAsWritten) {
    ParseResult r = parse_clean("scene { plane { normal: <0, 0, 2>; distance: -2; } }");
    EXPECT_EQ(shape_as<Plane>(r.scene.primitives.at(0).shape).normal, Vec3(0, 0, 2));
    EXPECT_EQ(brief("scene { plane { normal: <0, 0, 0>; } }"),
              "1:25: error: 'normal' must not be the zero vector, got <0, 0, 0>");
}

TEST(Shapes, PropertiesOfOtherShapesAreUnknown) {
    EXPECT_EQ(brief("scene { plane { radius: 1; } }"),
              "1:17: error: unknown property 'radius' in 'plane' (allowed: normal, distance, "
              "material, transform)");
}

TEST(Materials, ExponentsMustBePositive) {
    EXPECT_EQ(brief("scene { sphere { material { diffuse_k: 0; specular_k: -3; } } }"),
              "1:40: error: 'diffuse_k' must be greater than 0 and at most 1e+09, got 0\n"
              "1:55: error: 'specular_k' must be greater than 0 and at most 1e+09, got -3");
}

TEST(Materials, ReflectionOutsideZeroOneIsClampedWithAWarning) {
    ParseResult r = parse_scene("scene { sphere { material { reflection: 1.5; } } }");
    EXPECT_EQ(brief(r.diagnostics),
              "1:41: warning: 'reflection' 1.5 is outside 0..1: clamped to 1");
    EXPECT_EQ(r.scene.primitives.at(0).material.finish->reflection, 1.0);
    ParseResult low = parse_scene("scene { sphere { material { reflection: -0.5; } } }");
    EXPECT_EQ(low.scene.primitives.at(0).material.finish->reflection, 0.0);
    EXPECT_EQ(low.diagnostics.size(), 1u);
}

TEST(Materials, RepeatedPropertyInOneMaterialWarns) {
    EXPECT_EQ(brief("scene { sphere { material { reflection: 0.1; reflection: 0.2; } } }"),
              "1:46: warning: 'reflection' is set again in this 'material'; the later value "
              "wins (first set at line 1)");
}

TEST(Transforms, RotationsTakeDegreesAndVectorsTakeVectors) {
    EXPECT_EQ(brief("scene { sphere { transform { xrotate: <1, 0, 0>; } } }"),
              "1:39: error: 'xrotate' takes a number like 1.5, got the vector <1, 0, 0>");
    EXPECT_EQ(brief("scene { sphere { transform { scale: 2; } } }"),
              "1:37: error: 'scale' takes a vector like <0, 1, 0>, got the number 2");
    EXPECT_EQ(brief("scene { sphere { transform { rotate: 2; } } }"),
              "1:30: error: unknown property 'rotate' in 'transform'; did you mean 'xrotate'? "
              "(allowed: translate, scale, xrotate, yrotate, zrotate)");
}

TEST(Settings, FilenameMustNotBeEmpty) {
    ParseResult r = parse_scene("render_settings { filename: \"\"; }");
    EXPECT_EQ(brief(r.diagnostics), "1:29: error: 'filename' must not be empty");
    EXPECT_EQ(r.scene.settings.filename, "jtracer.bmp");
}

}  // namespace
}  // namespace jt
