// pick_primitive gives the render's own first hit: a render in which each
// primitive shows a colour of its own (ambient only, no lights) names the
// primitive every pixel's ray meets first, and the pick must name the same.

#include "jtracer/pick.hpp"

#include "common/scenes.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>

namespace jt {
namespace {

// Primitive i shows the colour with the 24-bit value i + 1; the background 0.
Colour id_colour(int primitive) {
    const int id = primitive + 1;
    return Colour((id >> 16) & 255, (id >> 8) & 255, id & 255) / 255.0;
}

int id_at(const Image8& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return ((p[0] << 16) | (p[1] << 8) | p[2]) - 1;
}

// The same geometry, each primitive in its id colour, one sample a pixel.
Scene id_scene(Scene scene) {
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        Material m;
        m.pigment = id_colour(static_cast<int>(i));
        m.finish.edit().ambient = Colour(1.0);
        scene.primitives[i].material = m;
    }
    scene.lights.clear();
    scene.settings.ambient_light = Colour(1.0);
    scene.settings.background = Colour(0.0);
    scene.settings.samples = 1;
    return scene;
}

// Every pixel's pick against the id render; returns how many pixels hit something.
int expect_picks_match_the_render(const Scene& scene) {
    const auto prepared = prepare_scene(scene).value();
    const RenderOptions options = render_options_for(scene);
    const auto frame = prepare_frame(prepared, options);
    const Scene ids = id_scene(scene);
    RenderOptions id_options = render_options_for(ids);
    id_options.previews = false;
    const Image8 rendered = render_image(prepare_scene(ids).value(), id_options);
    int hits = 0, mismatches = 0;
    for (int y = 0; y < rendered.height; ++y)
        for (int x = 0; x < rendered.width; ++x) {
            const std::optional<PickedPrimitive> pick = pick_primitive(*frame, x, y);
            const int picked = pick ? pick->primitive : -1;
            if (picked != id_at(rendered, x, y) && ++mismatches <= 5)
                ADD_FAILURE() << "pixel " << x << "," << y << ": picked " << picked
                              << ", the render shows " << id_at(rendered, x, y);
            if (!pick) continue;
            ++hits;
            EXPECT_GT(pick->distance, 0.0);
        }
    EXPECT_EQ(mismatches, 0);
    return hits;
}

TEST(Pick, EveryPixelOfTheShowcaseNamesThePrimitiveTheRenderShows) {
    const Scene scene = test::showcase_at(192, 108);
    const int hits = expect_picks_match_the_render(scene);
    EXPECT_GT(hits, 192 * 108 / 4) << "the grid crosses the showcase's objects";
}

Scene many_spheres(int count) {
    Scene scene = test::scene_with_camera(
        test::camera_at({0, 0, 30}, {0, 0, 0}, {0, 1, 0}, 50.0, 160.0 / 120.0), 160, 120);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> along(-10.0, 10.0), size(0.02, 0.12);
    for (int i = 0; i < count; ++i)
        scene.primitives.push_back(
            test::sphere({along(random), along(random), along(random)}, size(random)));
    return scene;
}

TEST(Pick, EveryPixelOfAHundredThousandSpheresNamesThePrimitiveTheRenderShows) {
    const Scene scene = many_spheres(100000);
    const int hits = expect_picks_match_the_render(scene);
    EXPECT_GT(hits, 160 * 120 / 4);
}

TEST(Pick, TheDistanceReachesThePickedSurfaceAndProjectsBackToThePixel) {
    const Scene scene = many_spheres(2000);
    const auto frame = prepare_frame(prepare_scene(scene).value(), render_options_for(scene));
    const Camera& camera = scene.cameras[0];
    int checked = 0;
    for (int y = 0; y < 120; y += 2)
        for (int x = 0; x < 160; x += 2) {
            const std::optional<PickedPrimitive> pick = pick_primitive(*frame, x, y);
            if (!pick) continue;
            ++checked;
            const Sphere& s = shape_as<Sphere>(scene.primitives[pick->primitive].shape);
            // The ray as docs/language.md §7 makes it, rebuilt here: to the pixel's centre.
            const Vec3 forward = glm::normalize(camera.look_at - camera.position);
            const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
            const Vec3 up = glm::cross(right, forward);
            const double t = std::tan(camera.fov * 0.5 * std::numbers::pi / 180.0);
            const double sx = (2.0 * (x + 0.5) / 160 - 1.0) * t * camera.aspect;
            const double sy = (2.0 * (y + 0.5) / 120 - 1.0) * t;
            const Vec3 d = glm::normalize(forward + sx * right + sy * up);
            const Vec3 point = camera.position + pick->distance * d;
            EXPECT_NEAR(glm::length(point - s.center), s.radius, 1e-9) << x << "," << y;
            const std::optional<ImagePoint> back = project_to_image(*frame, point);
            ASSERT_TRUE(back);
            EXPECT_NEAR(back->x, x + 0.5, 1e-6);
            EXPECT_NEAR(back->y, y + 0.5, 1e-6);
        }
    EXPECT_GT(checked, 100);
}

TEST(Pick, OutsideTheFrameAndBehindTheCameraThereIsNothing) {
    const Scene scene = many_spheres(10);
    const auto frame = prepare_frame(prepare_scene(scene).value(), render_options_for(scene));
    for (auto [x, y] : {std::pair{-1, 0}, {0, -1}, {160, 0}, {0, 120}})
        EXPECT_FALSE(pick_primitive(*frame, x, y)) << x << "," << y;
    EXPECT_FALSE(project_to_image(*frame, {0, 0, 31}));
    EXPECT_FALSE(project_to_image(*frame, {0, 0, 30}));
    const std::optional<ImagePoint> centre = project_to_image(*frame, {0, 0, 0});
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->x, 80.0, 1e-9);
    EXPECT_NEAR(centre->y, 60.0, 1e-9);
}

}  // namespace
}  // namespace jt
