// Depth of field (docs/language.md §14.2): one sample is the pinhole image to
// the byte, the plane in focus is as sharp as the pinhole's, what lies off it
// blurs, and focus_distance defaults to the distance to look_at.

#include "jtracer/parser.hpp"
#include "render/camera_rays.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace jt::test {
namespace {

Scene parse(const std::string& text) {
    ParseResult parsed = parse_scene(text);
    EXPECT_TRUE(parsed.ok()) << (parsed.diagnostics.empty() ? "" : parsed.diagnostics[0].message);
    return parsed.scene;
}

Image8 render_with(const Scene& scene, int samples, int threads = 0) {
    RenderOptions o = render_options_for(scene);
    o.samples = samples;
    o.threads = threads;
    o.previews = false;
    return render_image(prepare_scene(scene).value(), o);
}

// A checkered wall at distance 8 straight ahead (self-lit: its pixels are its
// pattern's colours exactly), a red ball at distance 3 in the upper left.
std::string wall_scene(const std::string& lens) {
    return R"(
render_settings { width: 40; height: 30; ambient_light: <1, 1, 1>; }
cameras { perspective_camera { position: <0, 0, 0>; look_at: <0, 0, -8>; aspect: 1.3333; fov: 50;
                               )" +
           lens + R"( } }
scene {
    plane { normal: <0, 0, 1>; distance: -8;
            material { pigment: <0.9, 0.8, 0.2>; checker: <0.1, 0.2, 0.6>; checker_size: 0.37;
                       ambient: <1, 1, 1>; diffuse: <0, 0, 0>; } }
    sphere { center: <-1.2, 0.8, -3>; radius: 0.5;
             material { pigment: <1, 0, 0>; ambient: <1, 1, 1>; diffuse: <0, 0, 0>; } }
}
)";
}

TEST(Lens, OneSampleIsThePinholeImageToTheByte) {
    const Image8 pinhole = render_with(parse(wall_scene("")), 1);
    EXPECT_EQ(render_with(parse(wall_scene("aperture: 0.4;")), 1), pinhole);
    EXPECT_EQ(render_with(parse(wall_scene("aperture: 0.4; focus_distance: 3;")), 1), pinhole);
}

TEST(Lens, ApertureZeroIsThePinholeForEverySampleCount) {
    for (int samples : {2, 9}) {
        EXPECT_EQ(render_with(parse(wall_scene("aperture: 0; focus_distance: 3;")), samples),
                  render_with(parse(wall_scene("")), samples));
    }
}

TEST(Lens, ThePlaneInFocusIsSharpAndTheRestBlurs) {
    const int samples = 16;
    const Image8 pinhole = render_with(parse(wall_scene("")), samples);
    // Focused on the wall (look_at lies on it): every lens ray of a sample
    // meets the wall where the pinhole ray of that sample does.
    const Image8 lens = render_with(parse(wall_scene("aperture: 0.3;")), samples);
    int wall_pixels = 0, ball_differs = 0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) {
            // The ball's image and its blurred rim: left of x = 19, above y = 16.
            if (x < 19 && y > 15) {
                ball_differs += at(lens, x, y) != at(pinhole, x, y);
                continue;
            }
            EXPECT_EQ(at(lens, x, y), at(pinhole, x, y)) << x << ", " << y;
            ++wall_pixels;
        }
    EXPECT_GT(wall_pixels, 800);
    EXPECT_GT(ball_differs, 10);  // the ball, far off the plane in focus, blurs
    // Focused on the ball instead, the wall blurs.
    const Image8 near =
        render_with(parse(wall_scene("aperture: 0.3; focus_distance: 3;")), samples);
    int wall_differs = 0;
    for (int y = 0; y < 15; ++y)
        for (int x = 20; x < 40; ++x) wall_differs += at(near, x, y) != at(pinhole, x, y);
    EXPECT_GT(wall_differs, 100);
}

TEST(Lens, FocusDistanceDefaultsToTheDistanceToLookAt) {
    EXPECT_EQ(render_with(parse(wall_scene("aperture: 0.3;")), 8),
              render_with(parse(wall_scene("aperture: 0.3; focus_distance: 8;")), 8));
    EXPECT_NE(render_with(parse(wall_scene("aperture: 0.3;")), 8),
              render_with(parse(wall_scene("aperture: 0.3; focus_distance: 7.5;")), 8));
}

TEST(Lens, SameBytesForEveryThreadCount) {
    const Scene scene = parse(wall_scene("aperture: 0.3; focus_distance: 3;"));
    const Image8 one = render_with(scene, 5, 1);
    EXPECT_EQ(render_with(scene, 5, 2), one);
    EXPECT_EQ(render_with(scene, 5, 3), one);
}

TEST(Lens, RaysLeaveTheLensAndMeetThePlaneInFocus) {
    Camera c = camera_at({1, 2, 3}, {2, 1, -4}, {0, 1, 0}, 40.0, 1.5);
    c.aperture = 0.25;
    c.focus_distance = 6.0;
    const CameraFrame frame = camera_frame(c, 30, 20);
    const int n = 9;
    EXPECT_FALSE(lens_ray(frame, camera_direction(frame, 3.5, 4.5), n, 3, 4, 0));
    for (std::uint32_t k = 1; k < n; ++k) {
        const Vec3 d = camera_direction(frame, 3.2, 4.7);
        const std::optional<LensRay> ray = lens_ray(frame, d, n, 3, 4, k);
        ASSERT_TRUE(ray);
        const Vec3 off = ray->origin - frame.position;
        EXPECT_NEAR(glm::dot(off, frame.forward), 0.0, 1e-15);  // on the lens
        EXPECT_NEAR(glm::length(off), 0.25 * std::sqrt(static_cast<double>(k) / n), 1e-15);
        EXPECT_NEAR(glm::length(ray->direction), 1.0, 1e-15);
        // Where the pinhole ray crosses the plane in focus, so does this one.
        const Vec3 focus = frame.position + d * (6.0 / glm::dot(d, frame.forward));
        const double t = glm::dot(focus - ray->origin, ray->direction);
        EXPECT_LT(glm::length(ray->origin + t * ray->direction - focus), 1e-13);
    }
    c.aperture = 0.0;
    EXPECT_FALSE(lens_ray(camera_frame(c, 30, 20), camera_direction(frame, 3.5, 4.5), n, 3, 4, 5));
}

}  // namespace
}  // namespace jt::test
