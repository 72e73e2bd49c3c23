// Pixels whose values are worked out by hand from docs/language.md §5-§8, one rule at
// a time. Most use a 1x1 image: its one ray runs exactly from the camera
// position through look_at, so each scene is aimed where the rule shows.

#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace jt::test {
namespace {

const Vec3 z_axis{0, 0, 1};

TEST(Analytic, MissShowsTheBackground) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}), 7, 5);
    s.settings.background = {0.2, 0.4, 0.6};
    Image8 image = render(s);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) EXPECT_EQ(at(image, x, y), (Rgb{51, 102, 153}));
}

TEST(Analytic, QuantisationRoundsHalvesUpAndClamps) {
    EXPECT_EQ(quantize_channel(0.5), 128);   // 127.5 rounds up
    EXPECT_EQ(quantize_channel(0.75), 191);  // 191.25
    EXPECT_EQ(quantize_channel(0.375), 96);  // 95.625
    EXPECT_EQ(quantize_channel(1.5), 255);
    EXPECT_EQ(quantize_channel(-0.25), 0);
    EXPECT_EQ(quantize_channel(std::nan("")), 0);
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    s.settings.background = {0.5, 0.375, 1.0};
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{128, 96, 255}));
}

// Sphere straight ahead, light above and behind the camera: the hit point is
// P = (0, 0, -4), N = (0, 0, 1), V = (0, 0, 1).
TEST(Analytic, LitSphereCentrePixel) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -5}));
    s.settings.ambient_light = {0.2, 0.2, 0.2};
    Material m;
    m.pigment = {0.8, 0.4, 0.2};
    m.finish.edit().ambient = {0.5, 0.5, 0.5};
    m.finish.edit().diffuse = {0.5, 0.5, 0.5};
    m.finish.edit().specular = {0.3, 0.2, 0.1};
    m.finish.edit().diffuse_k = 2.0;
    m.finish.edit().specular_k = 3.0;
    s.primitives.push_back(sphere({0, 0, -5}, 1.0, m));
    s.lights.push_back({{0, 4, 0}, {0.6, 0.6, 0.6}});
    // L = normalize((0, 4, 4)) so N.L = 1/sqrt(2); R = 2 (N.L) N - L = (0, -1, 1)/sqrt(2),
    // R.V = 1/sqrt(2).
    const double n_dot_l = 1.0 / std::sqrt(2.0);
    const double r_dot_v = 1.0 / std::sqrt(2.0);
    Colour c = 0.2 * 0.5 * m.pigment + 0.6 * 0.5 * m.pigment * std::pow(n_dot_l, 1.0 / 2.0) +
               0.6 * m.finish->specular * std::pow(r_dot_v, 3.0);
    EXPECT_EQ(at(render(s), 0, 0), expected(c));
    // By hand, red: 0.2*0.5*0.8 + 0.6*0.5*0.8*2^-0.25 + 0.6*0.3*2^-1.5
    //             = 0.08 + 0.20182 + 0.06364 = 0.34546, * 255 = 88.09 -> 88.
    EXPECT_EQ(expected(c), (Rgb{88, 47, 23}));
}

TEST(Analytic, LightBehindTheSurfaceAddsNothing) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -5}));
    s.primitives.push_back(sphere({0, 0, -5}, 1.0, matte({1, 1, 1})));
    s.lights.push_back({{0, 0, -20}, {1, 1, 1}});
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));
}

// Looking straight down at the floor y = -1; a light overhead, and a ball
// between them casts a hard shadow on the point seen.
TEST(Analytic, ShadowedPlanePointGetsOnlyAmbient) {
    Scene s = scene_with_camera(camera_at({0, 1, 0}, {0, -1, 0}, {0, 0, -1}));
    s.settings.ambient_light = {0.5, 0.5, 0.5};
    Material floor = matte({0.8, 0.6, 0.4});
    floor.finish.edit().ambient = {0.5, 0.5, 0.5};
    s.primitives.push_back(plane({0, 1, 0}, -1.0, floor));
    s.lights.push_back({{0, 5, 0}, {0.5, 0.5, 0.5}});
    // Lit: ambient 0.5*0.5*pigment + 0.5*1*pigment*1.
    EXPECT_EQ(at(render(s), 0, 0), expected(0.25 * floor.pigment + 0.5 * floor.pigment));
    s.primitives.push_back(sphere({0, 3, 0}, 0.5));  // behind the camera, above the floor
    EXPECT_EQ(at(render(s), 0, 0), expected(0.25 * floor.pigment));
    // A second light off to the side still reaches it: N.L = 1/sqrt(2).
    s.lights.push_back({{4, 3, 0}, {0.4, 0.4, 0.4}});
    EXPECT_EQ(at(render(s), 0, 0),
              expected(0.25 * floor.pigment + 0.4 * floor.pigment / std::sqrt(2.0)));
}

TEST(Analytic, ALightBeyondTheOccluderIsNotShadowedByWhatLiesPastIt) {
    Scene s = scene_with_camera(camera_at({0, 1, 0}, {0, -1, 0}, {0, 0, -1}));
    Material floor = matte({1, 1, 1});
    s.primitives.push_back(plane({0, 1, 0}, -1.0, floor));
    s.lights.push_back({{0, 2, 0}, {0.5, 0.5, 0.5}});
    s.primitives.push_back(sphere({0, 5, 0}, 0.5));  // above the light: no shadow
    EXPECT_EQ(at(render(s), 0, 0), expected(Colour(0.5)));
}

// A mirror wall ahead, a glowing ball behind the camera: the wall shows
// reflection * the ball's colour, once recurse_depth allows one bounce.
TEST(Analytic, ReflectionOfAKnownColour) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    s.settings.ambient_light = {1, 1, 1};
    Material mirror;
    mirror.finish.edit().reflection = 0.5;
    s.primitives.push_back(plane(z_axis, -5.0, mirror));
    const Colour ball{0.2, 0.6, 1.0};
    s.primitives.push_back(sphere({0, 0, 5}, 1.0, glowing(ball)));
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));  // recurse_depth 0: no reflections
    s.settings.recurse_depth = 1;
    EXPECT_EQ(at(render(s), 0, 0), expected(0.5 * ball));
    // A reflected ray that misses returns the background.
    s.primitives.pop_back();
    s.settings.background = {0.4, 0.8, 0.2};
    // The mirror itself is black: only the reflected background shows.
    EXPECT_EQ(at(render(s), 0, 0), expected(0.5 * s.settings.background));
}

// Two facing mirrors: each bounce adds reflection^k of the ball's glow, and
// recurse_depth counts the bounces.
TEST(Analytic, RecurseDepthLimitsBounces) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    s.settings.ambient_light = {1, 1, 1};
    Material mirror;
    mirror.pigment = {0.1, 0.1, 0.1};
    mirror.finish.edit().ambient = {1, 1, 1};
    mirror.finish.edit().reflection = 0.5;
    s.primitives.push_back(plane(z_axis, -5.0, mirror));
    s.primitives.push_back(plane(z_axis, 5.0, mirror));
    for (int depth = 0; depth <= 3; ++depth) {
        s.settings.recurse_depth = depth;
        double c = 0.0, weight = 1.0;
        for (int k = 0; k <= depth; ++k, weight *= 0.5) c += weight * 0.1;
        EXPECT_EQ(at(render(s), 0, 0), expected(Colour(c))) << "depth " << depth;
    }
}

// Transforms apply in the order written. A sphere of radius 0.25 at the
// origin, translated by 1 along x then scaled by 2, sits at x = 2 (radius
// 0.5); scaled first then translated, it would sit at x = 1.
TEST(Analytic, TransformsApplyInWrittenOrder) {
    Primitive p = sphere({0, 0, 0}, 0.25, glowing({1, 1, 1}));
    p.transforms = {translate({1, 0, 0}), scale({2, 2, 2})};
    auto hit_at = [&](const Vec3& where) {
        Scene s = scene_with_camera(camera_at(where + Vec3(0, 0, 10), where));
        s.settings.ambient_light = {1, 1, 1};
        s.primitives.push_back(p);
        return at(render(s), 0, 0) == Rgb{255, 255, 255};
    };
    EXPECT_TRUE(hit_at({2, 0, 0}));
    EXPECT_FALSE(hit_at({1, 0, 0}));
    // Just inside and just outside the scaled radius 0.5.
    EXPECT_TRUE(hit_at({2.49, 0, 0}));
    EXPECT_FALSE(hit_at({2.51, 0, 0}));
    p.transforms = {scale({2, 2, 2}), translate({1, 0, 0})};
    EXPECT_TRUE(hit_at({1, 0, 0}));
    EXPECT_FALSE(hit_at({2, 0, 0}));
}

// A positive rotation turns +x toward +y (z), +y toward +z (x), +z toward +x (y).
TEST(Analytic, RotationsFollowTheRightHandRule) {
    struct Case {
        TransformKind axis;
        Vec3 start, end, axis_direction;
    };
    const Case cases[] = {
        {TransformKind::zrotate, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}},
        {TransformKind::xrotate, {0, 2, 0}, {0, 0, 2}, {1, 0, 0}},
        {TransformKind::yrotate, {0, 0, 2}, {2, 0, 0}, {0, 1, 0}},
        {TransformKind::zrotate, {0, 2, 0}, {-2, 0, 0}, {0, 0, 1}},
    };
    for (const Case& c : cases) {
        Primitive p = sphere(c.start, 0.5, glowing({1, 1, 1}));
        p.transforms = {rotate(c.axis, 90.0)};
        // Look at each candidate along the rotation axis: the ray passes no other.
        auto hit_at = [&](const Vec3& where) {
            Vec3 up = c.axis == TransformKind::yrotate ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
            Scene s = scene_with_camera(camera_at(where + 10.0 * c.axis_direction, where, up));
            s.settings.ambient_light = {1, 1, 1};
            s.primitives.push_back(p);
            return at(render(s), 0, 0) == Rgb{255, 255, 255};
        };
        EXPECT_TRUE(hit_at(c.end)) << "rotation " << int(c.axis);
        EXPECT_FALSE(hit_at(-c.end)) << "rotation " << int(c.axis);
        EXPECT_FALSE(hit_at(c.start)) << "rotation " << int(c.axis);
    }
}

// Normals go through the inverse transpose. On the ellipsoid x^2/4 + y^2 +
// z^2 = 1 (a unit sphere scaled by <2, 1, 1>), at P = (sqrt 2, 0, sqrt 0.5)
// the normal is (x/4, y, z) normalised = (1, 0, 2)/sqrt 5. A light far along
// +x gives N.L = 1/sqrt 5; a normal carried by the matrix itself would give
// 2/sqrt 6 instead.
TEST(Analytic, NormalsUseTheInverseTranspose) {
    const Vec3 p{std::sqrt(2.0), 0, std::sqrt(0.5)};
    const Vec3 n = glm::normalize(Vec3(1, 0, 2));
    Scene s = scene_with_camera(camera_at(p + 5.0 * n, p));
    Primitive e = sphere({0, 0, 0}, 1.0, matte({1, 1, 1}));
    e.transforms = {scale({2, 1, 1})};
    s.primitives.push_back(e);
    s.lights.push_back({p + Vec3(1e6, 0, 0), {1, 1, 1}});
    EXPECT_EQ(at(render(s), 0, 0), expected(Colour(1.0 / std::sqrt(5.0))));
}

// The cylinder's top cap, bottom cap and side, each lit head-on (N.L = 1) by a
// light of a different colour, so each face shows which normal it got.
TEST(Analytic, CylinderSideAndCaps) {
    auto seen = [](const Vec3& from, const Vec3& to) {
        Scene s = scene_with_camera(camera_at(from, to, {0.1, 0.2, 1.0}));
        s.primitives.push_back(cylinder(1.0, 2.0, matte({1, 1, 1})));
        s.lights.push_back({{0, 10, 0}, {0.8, 0, 0}});   // above the top cap
        s.lights.push_back({{0, -10, 0}, {0, 0.8, 0}});  // below the bottom cap
        s.lights.push_back({{0, 1, 10}, {0, 0, 0.8}});   // in front of the side
        return at(render(s), 0, 0);
    };
    EXPECT_EQ(seen({0, 5, 0}, {0, 0, 0}), (Rgb{204, 0, 0}));   // top cap, y = 2
    EXPECT_EQ(seen({0, -5, 0}, {0, 0, 0}), (Rgb{0, 204, 0}));  // bottom cap, y = 0
    // Side at (0, 1, 1): the side light is at N.L = 1 (its position is straight
    // out along +z); the cap lights are at right angles.
    EXPECT_EQ(seen({0, 1, 5}, {0, 1, 0}), (Rgb{0, 0, 204}));
    // Past the top and bottom the cylinder ends: the ray misses.
    EXPECT_EQ(seen({0, 2.01, 5}, {0, 2.01, 0}), (Rgb{0, 0, 0}));
    EXPECT_EQ(seen({0, -0.01, 5}, {0, -0.01, 0}), (Rgb{0, 0, 0}));
}

// Surfaces are two-sided: seen from inside a sphere or from under a floor,
// the normal faces the viewer and the light at the camera lights it fully.
TEST(Analytic, TwoSidedNormals) {
    Scene inside = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    inside.primitives.push_back(sphere({0, 0, 0}, 3.0, matte({1, 1, 1})));
    inside.lights.push_back({{0, 0, 0}, {0.5, 0.5, 0.5}});
    EXPECT_EQ(at(render(inside), 0, 0), expected(Colour(0.5)));

    Scene below = scene_with_camera(camera_at({0, -3, 0}, {0, 0, 0}, {0, 0, -1}));
    below.primitives.push_back(plane({0, 1, 0}, 0.0, matte({1, 1, 1})));
    below.lights.push_back({{0, -1, 0}, {0.5, 0.5, 0.5}});
    EXPECT_EQ(at(render(below), 0, 0), expected(Colour(0.5)));
}

// docs/language.md §7.3: pixel (i, j) from the bottom left looks along
// f + sx r + sy u with sx = (2 (i + 0.5) / w - 1) t aspect, sy = (2 (j + 0.5) / h - 1) t.
// With fov 90 (t = 1), aspect 2 and a 4x2 image, pixel (3, 1), top right, looks
// along (1.5, 0.5, -1). A small ball on that line shows in that pixel alone.
TEST(Analytic, CameraMapsPixelCentres) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0, 2.0), 4, 2);
    s.settings.ambient_light = {1, 1, 1};
    s.primitives.push_back(sphere(10.0 * Vec3(1.5, 0.5, -1), 0.2, glowing({1, 1, 1})));
    Image8 image = render(s);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(at(image, x, y), (x == 3 && y == 1 ? Rgb{255, 255, 255} : Rgb{0, 0, 0}))
                << x << "," << y;
}

TEST(Analytic, ZeroScaleLeavesThePrimitiveOut) {
    Scene s = scene_with_camera(camera_at({0, 0, 5}, {0, 0, 0}), 9, 9);
    s.settings.background = {0.1, 0.2, 0.3};
    s.settings.ambient_light = {1, 1, 1};
    for (Primitive p :
         {sphere({0, 0, 0}, 1.0, glowing({1, 0, 0})), cylinder(0.5, 1.0, glowing({1, 0, 0})),
          plane({0, 0, 1}, 0.0, glowing({1, 0, 0}))}) {
        p.transforms = {scale({2.0, 0.0, 1.0})};
        Scene t = s;
        t.primitives.push_back(p);
        Image8 image = render(t);
        for (int y = 0; y < 9; ++y)
            for (int x = 0; x < 9; ++x) ASSERT_EQ(at(image, x, y), expected(s.settings.background));
    }
}

TEST(Analytic, NonFiniteValuesNeverReachAPixel) {
    Scene s = scene_with_camera(camera_at({0, 0, 5}, {0, 0, 0}), 9, 9);
    s.settings.ambient_light = {1, 1, 1};
    Primitive p = sphere({0, 0, 0}, 1.0, glowing({1, 0, 0}));
    p.transforms = {scale({1e300, 1e300, 1e300}), scale({1e300, 1, 1})};
    s.primitives.push_back(p);
    s.primitives.push_back(sphere({std::nan(""), 0, 0}, 1.0, glowing({0, 1, 0})));
    Image8 image = render(s);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) EXPECT_EQ(at(image, x, y), (Rgb{0, 0, 0}));
    // A camera whose look_at equals its position (the validator refuses it)
    // renders the background rather than NaN.
    Scene bad = scene_with_camera(camera_at({1, 1, 1}, {1, 1, 1}), 3, 3);
    bad.settings.background = {0.5, 0.5, 0.5};
    EXPECT_EQ(at(render(bad), 1, 1), (Rgb{128, 128, 128}));
}

}  // namespace
}  // namespace jt::test
