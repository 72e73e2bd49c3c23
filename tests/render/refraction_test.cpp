// Refraction and attenuated shadows, worked out by hand from docs/language.md §13.2.

#include "render/refraction.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace jt::test {
namespace {

Material clear_glass(double transmission, double ior) {
    Material m;  // black pigment: only the transmitted ray shows
    m.finish.edit().transmission = transmission;
    m.finish.edit().ior = ior;
    return m;
}

void expect_near(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-12) << "x";
    EXPECT_NEAR(a.y, b.y, 1e-12) << "y";
    EXPECT_NEAR(a.z, b.z, 1e-12) << "z";
}

// Snell: 45 degrees into glass of index sqrt(2) leaves at 30 degrees, and back.
TEST(Refraction, DirectionAtAKnownAngle) {
    const double s = std::sqrt(0.5);
    const Vec3 n{0, 1, 0};  // facing the ray, which comes down from above
    const Vec3 in = transmitted_direction({s, -s, 0}, n, true, std::sqrt(2.0));
    expect_near(in, {0.5, -std::sqrt(3.0) / 2, 0});
    const Vec3 out = transmitted_direction(in, n, false, std::sqrt(2.0));
    expect_near(out, {s, -s, 0});
}

TEST(Refraction, NormalIncidenceGoesStraight) {
    expect_near(transmitted_direction({0, 0, -1}, {0, 0, 1}, true, 1.5), {0, 0, -1});
    expect_near(transmitted_direction({0, 0, -1}, {0, 0, 1}, false, 1.5), {0, 0, -1});
}

// Inside glass of index 1.5 the critical angle is asin(1/1.5) = 41.81 degrees:
// 40 degrees refracts out, 45 degrees is reflected as by a mirror.
TEST(Refraction, TotalInternalReflectionPastTheCriticalAngle) {
    const Vec3 n{0, 1, 0};
    const double below = 40.0 * M_PI / 180.0, past = 45.0 * M_PI / 180.0;
    const Vec3 refracted =
        transmitted_direction({std::sin(below), -std::cos(below), 0}, n, false, 1.5);
    EXPECT_NEAR(refracted.x, 1.5 * std::sin(below), 1e-12);  // Snell: sin t = 1.5 sin i
    EXPECT_LT(refracted.y, 0.0);                             // it crossed the surface
    const Vec3 d{std::sin(past), -std::cos(past), 0};
    expect_near(transmitted_direction(d, n, false, 1.5), {d.x, -d.y, 0});
}

// The centre ray through a glass sphere reaches a target the size of a pin
// behind it: any bend would miss it and show the background.
TEST(Refraction, RayThroughAGlassSpheresCentreGoesStraight) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -5}));
    s.settings.recurse_depth = 2;  // in and out
    s.settings.ambient_light = Colour(1.0);
    s.settings.background = {1, 0, 0};
    s.primitives.push_back(sphere({0, 0, -5}, 1.0, clear_glass(1.0, 1.5)));
    s.primitives.push_back(sphere({0, 0, -20}, 0.01, glowing({0.2, 0.4, 0.6})));
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{51, 102, 153}));
    // One bounce is not enough to get out of the sphere: its inside is black.
    s.settings.recurse_depth = 1;
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));
}

// An off-centre ray is bent: the pin straight behind the entry point is missed.
TEST(Refraction, AnOffCentreRayIsBent) {
    Scene s = scene_with_camera(camera_at({0.5, 0, 0}, {0.5, 0, -5}));
    s.settings.recurse_depth = 2;
    s.settings.ambient_light = Colour(1.0);
    s.primitives.push_back(sphere({0, 0, -5}, 1.0, clear_glass(1.0, 1.5)));
    s.primitives.push_back(sphere({0.5, 0, -20}, 0.01, glowing({0.2, 0.4, 0.6})));
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));
    // Index 1 bends nothing.
    s.primitives[0].material.finish.edit().ior = 1.0;
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{51, 102, 153}));
}

// A white floor lit from straight above, seen from the side, under a glass
// sphere: the shadow ray crosses the sphere twice, so the light is scaled by t^2.
Scene floor_under_glass(double transmission) {
    Scene s = scene_with_camera(camera_at({5, 1, 0}, {0, 0, 0}));
    s.primitives.push_back(plane({0, 1, 0}, 0.0, matte({0.8, 0.8, 0.8})));
    s.primitives.push_back(sphere({0, 5, 0}, 1.0, clear_glass(transmission, 1.5)));
    s.lights.push_back({{0, 10, 0}, Colour(1.0)});
    return s;
}

TEST(Refraction, ShadowThroughASphereIsScaledByTransmissionSquared) {
    // N = L = +y: the diffuse term is 0.8 * t^2.
    EXPECT_EQ(at(render(floor_under_glass(0.5)), 0, 0), expected(Colour(0.8 * 0.25)));
    EXPECT_EQ(at(render(floor_under_glass(0.9)), 0, 0), expected(Colour(0.8 * 0.81)));
    EXPECT_EQ(at(render(floor_under_glass(1.0)), 0, 0), expected(Colour(0.8)));
    // Transmission 0 is an opaque sphere: the hard shadow of docs/language.md §8.2.
    EXPECT_EQ(at(render(floor_under_glass(0.0)), 0, 0), (Rgb{0, 0, 0}));
}

TEST(Refraction, EverySurfaceCrossedCountsAndAnOpaqueOneBlocks) {
    Scene s = floor_under_glass(0.5);
    s.primitives.push_back(sphere({0, 8, 0}, 0.5, clear_glass(0.8, 1.2)));
    EXPECT_EQ(at(render(s), 0, 0), expected(Colour(0.8 * 0.25 * 0.64)));
    s.primitives.push_back(sphere({0, 3, 0}, 0.5, matte({1, 1, 1})));
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));
}

// The transmitted term comes after the local and reflected ones, each weighted.
TEST(Refraction, TransmittedLightAddsToLocalAndReflectedLight) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -5}));
    s.settings.recurse_depth = 3;
    s.settings.ambient_light = Colour(1.0);
    s.settings.background = {0, 0, 0.4};  // what the reflected ray sees
    Material glass = clear_glass(0.5, 1.5);
    glass.pigment = {0.2, 0, 0};
    glass.finish.edit().ambient = Colour(1.0);
    glass.finish.edit().reflection = 0.25;
    // A thin slab-like plane pair would do too; a plane keeps the path simple:
    // enter the plane z = -5 (facing +z) and see the glowing plane behind it.
    s.primitives.push_back(plane({0, 0, 1}, -5.0, glass));
    s.primitives.push_back(plane({0, 0, 1}, -10.0, glowing({0, 0.6, 0})));
    // 0.2 red locally + 0.25 * background blue + 0.5 * green behind.
    EXPECT_EQ(at(render(s), 0, 0), expected(Colour(0.2, 0.5 * 0.6, 0.25 * 0.4)));
}

}  // namespace
}  // namespace jt::test
