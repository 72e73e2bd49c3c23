// No shadow acne or speckles at any scale: the same scene scaled by 1e-3 and
// by 1e3 renders the same image as at scale 1, and a lit floor is one flat
// colour wherever no shadow can fall.

#include "scene_builder.hpp"

#include "jtracer/image_diff.hpp"

#include <gtest/gtest.h>

namespace jt::test {
namespace {

// A floor, a wall, a sphere and a cylinder lying on its side; lights at
// grazing and steep angles, mirrors, all in world units times `k`.
Scene scaled_scene(double k) {
    Scene s = scene_with_camera(
        camera_at(k * Vec3(0, 3, 9), k * Vec3(0, 0.8, 0), {0, 1, 0}, 45.0, 160.0 / 90.0), 160, 90);
    s.settings.recurse_depth = 3;
    s.settings.background = {0.2, 0.3, 0.5};
    s.settings.ambient_light = {0.2, 0.2, 0.2};
    Material floor = matte({0.8, 0.8, 0.8});
    floor.finish.edit().ambient = {1, 1, 1};
    floor.finish.edit().reflection = 0.3;
    s.primitives.push_back(plane({0, 1, 0}, 0.0, floor));
    s.primitives.push_back(plane({0, 0, 1}, -6.0 * k, matte({0.9, 0.7, 0.5})));
    Material ball = matte({0.9, 0.2, 0.2});
    ball.finish.edit().specular = {1, 1, 1};
    ball.finish.edit().reflection = 0.5;
    s.primitives.push_back(sphere(k * Vec3(-1.2, 1, 0), k, ball));
    Primitive tube = cylinder(0.5, 2.0, matte({0.2, 0.3, 0.9}));
    tube.transforms = {rotate(TransformKind::zrotate, 90.0), translate({2.5, 0.5, 0.5}),
                       scale(Vec3(k))};
    s.primitives.push_back(tube);
    s.lights.push_back({k * Vec3(4, 6, 4), {0.6, 0.6, 0.6}});
    s.lights.push_back({k * Vec3(-8, 0.3, 3), {0.3, 0.3, 0.2}});  // grazes the floor
    return s;
}

TEST(Scale, SameImageFromMillimetresToKilometres) {
    Image8 unit = render(scaled_scene(1.0));
    for (double k : {1e-3, 1e3}) {
        ImageDiff d = diff_images(unit, render(scaled_scene(k)), 1);
        // Rounding may move a silhouette edge pixel; acne would flip hundreds.
        EXPECT_LE(d.pixels_over, 3u) << "scale " << k;
    }
}

// Looking straight down at a floor lit from straight above, with nothing to
// cast a shadow: every pixel must be the same lit colour. Self-shadowing from
// a badly offset shadow ray shows up as dark speckles.
TEST(Scale, LitFloorHasNoAcne) {
    for (double k : {1e-3, 1.0, 1e3, 1e6}) {
        Scene s = scene_with_camera(
            camera_at(k * Vec3(0.3, 5, 0.2), k * Vec3(0.3, 0, 0.2), {0, 0, -1}, 60.0), 64, 64);
        s.primitives.push_back(plane({0, 1, 0}, 0.0, matte({1, 1, 1})));
        s.lights.push_back({k * Vec3(0, 1e3, 0), {0.5, 0.5, 0.5}});
        Image8 image = render(s);
        int dark = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                if (at(image, x, y).r < 120) ++dark;
        EXPECT_EQ(dark, 0) << "scale " << k;
    }
}

}  // namespace
}  // namespace jt::test
