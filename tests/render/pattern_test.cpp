// The checker pattern, worked out by hand from docs/language.md §13.3.

#include "render/pattern.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>

namespace jt::test {
namespace {

const Colour kRed{1, 0, 0}, kBlue{0, 0, 1};

Material checkered(double size = 1.0) {
    Material m = glowing(kRed);
    m.finish.edit().checker = kBlue;
    m.finish.edit().checker_size = size;
    return m;
}

Colour checker_at(const Material& m, const Vec3& p) {
    return pattern_pigment(m, nullptr, Sphere{}, p);
}

TEST(Checker, ColourAtChosenPoints) {
    const Material m = checkered();
    EXPECT_EQ(checker_at(m, {0.5, 0.5, 0.5}), kRed);    // k = 0
    EXPECT_EQ(checker_at(m, {1.5, 0.5, 0.5}), kBlue);   // k = 1
    EXPECT_EQ(checker_at(m, {1.5, 1.5, 0.5}), kRed);    // k = 2
    EXPECT_EQ(checker_at(m, {-0.5, 0.5, 0.5}), kBlue);  // floor(-0.5) = -1
    EXPECT_EQ(checker_at(m, {-0.5, -0.5, -0.5}), kBlue);
    EXPECT_EQ(checker_at(checkered(2.0), {1.5, 0.5, 0.5}), kRed);
    EXPECT_EQ(checker_at(checkered(2.0), {2.5, 0.5, 0.5}), kBlue);
    Material plain = glowing(kRed);
    EXPECT_EQ(checker_at(plain, {1.5, 0.5, 0.5}), kRed);
}

// A point on a cube face (y = 0) and just below it take the colour of the cube
// above: the 1e-6 keeps a plane on a face one colour, not rounding noise.
TEST(Checker, ACubeFaceShowsOneColour) {
    const Material m = checkered();
    EXPECT_EQ(checker_at(m, {0.5, 0.0, 0.5}), kRed);
    EXPECT_EQ(checker_at(m, {0.5, -1e-9, 0.5}), kRed);
    EXPECT_EQ(checker_at(m, {1.5, -1e-9, 0.5}), kBlue);
    EXPECT_EQ(checker_at(m, {0.5, -1e-3, 0.5}), kBlue);  // well below: the cube under it
}

Scene looking_down_at(const Vec3& point, const Primitive& p) {
    Scene s = scene_with_camera(camera_at(point + Vec3(0, 3, 0), point, {0, 0, -1}));
    s.settings.ambient_light = Colour(1.0);
    s.primitives.push_back(p);
    return s;
}

TEST(Checker, AFloorOnACubeFaceRendersBothColours) {
    const Primitive floor = plane({0, 1, 0}, 0.0, checkered());
    EXPECT_EQ(at(render(looking_down_at({0.5, 0, 0.5}, floor)), 0, 0), (Rgb{255, 0, 0}));
    EXPECT_EQ(at(render(looking_down_at({1.5, 0, 0.5}, floor)), 0, 0), (Rgb{0, 0, 255}));
    EXPECT_EQ(at(render(looking_down_at({1.5, 0, 1.5}, floor)), 0, 0), (Rgb{255, 0, 0}));
}

// The pattern lives in object space: it moves with the primitive.
TEST(Checker, MovesWithItsPrimitive) {
    Primitive floor = plane({0, 1, 0}, 0.0, checkered());
    floor.transforms = {translate({1, 0, 0})};
    EXPECT_EQ(at(render(looking_down_at({0.5, 0, 0.5}, floor)), 0, 0), (Rgb{0, 0, 255}));
    EXPECT_EQ(at(render(looking_down_at({1.5, 0, 0.5}, floor)), 0, 0), (Rgb{255, 0, 0}));
    // A sphere moved to x = 11, hit at world (11, 0, 1): object point (0, 0, 1),
    // k = 1, blue; in world space k would be 12, red.
    Primitive ball = sphere({0, 0, 0}, 1.0, checkered());
    ball.transforms = {translate({11, 0, 0})};
    Scene s = scene_with_camera(camera_at({11, 0, 5}, {11, 0, 0}));
    s.settings.ambient_light = Colour(1.0);
    s.primitives.push_back(ball);
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 255}));
}

}  // namespace
}  // namespace jt::test
