// Soft shadows (docs/language.md §14.0, §14.1): the pixel hash, radius 0 as
// the point light to the byte, the penumbra where cones and similar triangles
// put it, light through glass, and the same bytes however the image is cut.

#include "jtracer/parser.hpp"
#include "jtracer/render_tile.hpp"
#include "render/camera_rays.hpp"
#include "render/light_disk.hpp"
#include "render/pixel_hash.hpp"
#include "render/prepared_frame.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace jt::test {
namespace {

// Worked out apart from the code, in Python's unbounded integers reduced mod
// 2^32 after every product: h = ((i*73856093) % 2^32) ^ ((j*19349663) % 2^32)
// ^ ((s*83492791) % 2^32); h ^= h >> 16; h = (h * 0x45d9f3b) % 2^32; h ^= h >> 16.
TEST(PixelHash, MatchesValuesComputedApart) {
    EXPECT_EQ(pixel_hash(0, 0, 0), 0u);
    EXPECT_EQ(pixel_hash(1, 0, 0), 610084548u);
    EXPECT_EQ(pixel_hash(0, 1, 0), 1706363101u);
    EXPECT_EQ(pixel_hash(0, 0, 1), 3959992562u);
    EXPECT_EQ(pixel_hash(639, 479, 15), 1803326592u);
    EXPECT_EQ(pixel_hash(12345, 54321, 2048), 3068396235u);
    EXPECT_EQ(pixel_hash(65534, 65534, 1023), 4060025325u);
    // 2 pi h / 2^32, as Python's floats (IEEE doubles) give it.
    EXPECT_EQ(pixel_angle(1, 0, 0), 0.8925037151507332);
    EXPECT_EQ(pixel_angle(639, 479, 15), 2.638119074260033);
    EXPECT_EQ(pixel_angle(65534, 65534, 1023), 5.9394844502250255);
}

TEST(LightDisk, PointsLieOnTheDiskFacingThePoint) {
    const Vec3 centre{1, 2, 3};
    for (const Vec3& l : {Vec3(0, 1, 0), Vec3(0, -1, 0), glm::normalize(Vec3(1, 2, -3))}) {
        const LightDisk disk = light_disk(centre, 0.5, l);
        EXPECT_NEAR(glm::length(disk.e1), 1.0, 1e-15);
        EXPECT_NEAR(glm::dot(disk.e1, l), 0.0, 1e-15);
        EXPECT_NEAR(glm::dot(disk.e2, l), 0.0, 1e-15);
        EXPECT_NEAR(glm::dot(disk.e1, disk.e2), 0.0, 1e-15);
        for (int m = 0; m < 16; ++m) {
            const Vec3 q = disk_point(disk, m, 16, 1.0);
            EXPECT_NEAR(glm::dot(q - centre, l), 0.0, 1e-15);
            EXPECT_LE(glm::length(q - centre), 0.5 * std::sqrt(15.5 / 16) + 1e-15);
        }
    }
}

Scene parse(const std::string& text) {
    ParseResult parsed = parse_scene(text);
    EXPECT_TRUE(parsed.ok()) << (parsed.diagnostics.empty() ? "" : parsed.diagnostics[0].message);
    return parsed.scene;
}

Image8 render_with(const Scene& scene, int samples, int threads = 0,
                   std::optional<PixelRect> region = std::nullopt) {
    RenderOptions o = render_options_for(scene);
    o.samples = samples;
    o.threads = threads;
    o.previews = false;
    o.region = region;
    return render_image(prepare_scene(scene).value(), o);
}

// Spheres, a mirror, glass and a plane, under two lights: every kind of
// shadow ray (opaque, through glass, from a reflected and a refracted hit).
const char* const kShadowScene = R"(
render_settings { width: 48; height: 36; recurse_depth: 4; ambient_light: <0.2, 0.2, 0.2>; }
cameras { perspective_camera { position: <0, 2.5, 6>; look_at: <0, 0.4, 0>; aspect: 1.3333; } }
scene {
    plane { normal: <0, 1, 0>; distance: -1;
            material { pigment: <0.9, 0.9, 0.8>; diffuse: <1, 1, 1>; checker: <0.3, 0.3, 0.35>; } }
    sphere { center: <-1.2, 0, 0>; radius: 1;
             material { pigment: <1, 0.3, 0.2>; diffuse: <0.8, 0.8, 0.8>; specular: <0.5, 0.5, 0.5>;
                        specular_k: 20; reflection: 0.3; } }
    sphere { center: <1.1, -0.2, 0.5>; radius: 0.8;
             material { pigment: <0.05, 0.05, 0.05>; transmission: 0.8; ior: 1.5; } }
    point_light { position: <-3, 6, 4>; intensity: <0.7, 0.7, 0.7>; LIGHT_A }
    point_light { position: <4, 3, -2>; intensity: <0.4, 0.35, 0.3>; LIGHT_B }
}
)";

std::string shadow_scene(const std::string& a, const std::string& b) {
    std::string text = kShadowScene;
    text.replace(text.find("LIGHT_A"), 7, a);
    text.replace(text.find("LIGHT_B"), 7, b);
    return text;
}

TEST(SoftShadow, RadiusZeroIsThePointLightWhateverItsSamples) {
    const Scene point = parse(shadow_scene("", ""));
    for (int samples : {1, 4}) {
        const Image8 reference = render_with(point, samples);
        for (const char* light : {"radius: 0;", "radius: 0; shadow_samples: 1;",
                                  "radius: 0; shadow_samples: 1024;", "shadow_samples: 7;"}) {
            SCOPED_TRACE(light);
            EXPECT_EQ(render_with(parse(shadow_scene(light, light)), samples), reference);
        }
    }
}

TEST(SoftShadow, SameBytesWithALensForEveryThreadCountRegionAndTile) {
    // With a lens too: its rays carry the pixel's angle as the lights' do.
    std::string text =
        shadow_scene("radius: 0.8; shadow_samples: 24;", "radius: 0.3; shadow_samples: 5;");
    text.replace(text.find("aspect: 1.3333;"), 15, "aspect: 1.3333; aperture: 0.15;");
    const Scene scene = parse(text);
    for (int samples : {1, 3}) {
        SCOPED_TRACE(samples);
        const Image8 whole = render_with(scene, samples, 1);
        EXPECT_NE(whole, render_with(parse(shadow_scene("", "")), samples, 1));
        EXPECT_EQ(render_with(scene, samples, 3), whole);
        const PixelRect window{13, 7, 40, 29};
        const Image8 part = render_with(scene, samples, 2, window);
        for (int y = window.y0; y < window.y1; ++y)
            for (int x = window.x0; x < window.x1; ++x) ASSERT_EQ(at(part, x, y), at(whole, x, y));
        RenderOptions o = render_options_for(scene);
        o.samples = samples;
        const auto frame = prepare_frame(prepare_scene(scene).value(), o);
        const PixelRect tile{5, 20, 31, 36};
        const RenderedTile rendered = render_tile(*frame, tile);
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
                ASSERT_EQ(at(rendered.pixels, x - tile.x0, y - tile.y0), at(whole, x, y));
    }
}

// A sphere of radius R at height h over the plane y = 0, under a light of
// radius r at height H straight above it. From a point P = (0, 0, z) the
// sphere fills the cone of half-angle asin(R / |S - P|) about P -> S, and the
// light's disk (facing P) the cone of half-angle atan(r / |L - P|) about
// P -> L. P is fully lit where the cones are apart, in the umbra where the
// light's cone lies inside the sphere's, and in the penumbra between.
struct Penumbra {
    double H = 10, h = 1, R = 0.5, r = 2;
    // > 0 lit, < 0 not; `inner` picks the umbra's edge.
    double margin(double z, bool inner) const {
        const double to_sphere = std::asin(R / std::hypot(z, h));
        const double to_light = std::atan(r / std::hypot(z, H));
        const double apart = std::abs(std::atan2(z, h) - std::atan2(z, H));
        return inner ? apart - (to_sphere - to_light) : apart - (to_sphere + to_light);
    }
    double edge(bool inner) const {
        double lo = 0.0, hi = 5.0;
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            (margin(mid, inner) < 0.0 ? lo : hi) = mid;
        }
        return lo;
    }
};

TEST(SoftShadow, PenumbraLiesWhereSimilarTrianglesPutIt) {
    const Penumbra g;
    // Similar triangles through the sphere's rim from the light's rim: the
    // penumbra runs from (R H - r h) / (H - h) to (R H + r h) / (H - h).
    const double inner_st = (g.R * g.H - g.r * g.h) / (g.H - g.h);
    const double outer_st = (g.R * g.H + g.r * g.h) / (g.H - g.h);
    const double inner = g.edge(true), outer = g.edge(false);

    // One column of pixels looking down on the +z side of the shadow; the
    // sphere's own image falls on the -z side.
    const int size = 81, column = 40;
    const std::string base = R"(
render_settings { width: 81; height: 81; ambient_light: <0.2, 0.2, 0.2>; }
cameras { perspective_camera { position: <0, 20, 20>; look_at: <0, 0, 0.6>; fov: 5; } }
scene {
    plane { normal: <0, 1, 0>; distance: 0; material { pigment: <1, 1, 1>; diffuse: <1, 1, 1>; } }
)";
    const std::string occluder = "sphere { center: <0, 1, 0>; radius: 0.5; }\n";
    const std::string light =
        "point_light { position: <0, 10, 0>; intensity: <0.8, 0.8, 0.8>; radius: 2; "
        "shadow_samples: 1024; }\n";
    const PixelRect strip{column, 0, column + 1, size};
    const Image8 soft = render_with(parse(base + occluder + light + "}"), 1, 0, strip);
    const Image8 lit = render_with(parse(base + light + "}"), 1, 0, strip);
    const Image8 dark = render_with(parse(base + occluder + "}"), 1, 0, strip);

    const Scene scene = parse(base + "}");
    const CameraFrame camera = camera_frame(scene.cameras[0], size, size);
    auto ground = [&](int y) {  // where the pixel's ray meets the plane
        const Vec3 d = camera_direction(camera, column + 0.5, y + 0.5);
        return camera.position + (-camera.position.y / d.y) * d;
    };
    std::vector<std::pair<double, int>> levels;  // (z, red) across the penumbra and out
    int penumbra_pixels = 0;
    for (int y = 0; y + 1 < size; ++y) {
        const Vec3 p = ground(y);
        const Vec3 d = glm::normalize(p - camera.position);
        // Skip what the sphere hides and the shadow's far side.
        const Vec3 to_centre = Vec3(0, 1, 0) - camera.position;
        const double along = glm::dot(to_centre, d);
        if (glm::dot(to_centre, to_centre) - along * along < 0.25 || p.z < 0.0) continue;
        const double pixel = glm::length(ground(y + 1) - p);
        ASSERT_LT(pixel, 0.1);
        // Cones and similar triangles agree within a pixel here.
        EXPECT_LT(std::abs(inner - inner_st), pixel);
        EXPECT_LT(std::abs(outer - outer_st), pixel);
        const Rgb s = at(soft, column, y), l = at(lit, column, y), k = at(dark, column, y);
        const bool near_edge =
            std::abs(p.z - inner) < pixel + 0.01 || std::abs(p.z - outer) < pixel + 0.01;
        SCOPED_TRACE(testing::Message() << "z " << p.z << " pixel " << pixel);
        if (p.z > outer && !near_edge) {
            EXPECT_EQ(s, l);
        }
        if (p.z < inner && !near_edge) {
            EXPECT_EQ(s, k);
        }
        if (p.z > inner && p.z < outer && !near_edge) {
            EXPECT_GT(s.r, k.r);
            EXPECT_LT(s.r, l.r);
            ++penumbra_pixels;
        }
        // Past the penumbra the level falls slowly with dot(N, L).
        if (p.z < outer) levels.emplace_back(p.z, s.r);
    }
    // From the umbra outward through the penumbra, the light only grows.
    std::sort(levels.begin(), levels.end());
    for (std::size_t i = 1; i < levels.size(); ++i)
        EXPECT_GE(levels[i].second, levels[i - 1].second) << "at z " << levels[i].first;
    EXPECT_GE(penumbra_pixels, 3);
}

TEST(SoftShadow, InsideTheLightsSphereItIsAPointLight) {
    // The light's sphere reaches the plane: under it, P is inside.
    const std::string text = R"(
render_settings { width: 20; height: 20; ambient_light: <0.1, 0.1, 0.1>; }
cameras { perspective_camera { position: <0, 6, 2>; look_at: <0, 0, 0>; fov: 30; } }
scene {
    plane { normal: <0, 1, 0>; distance: 0; material { pigment: <1, 1, 1>; diffuse: <1, 1, 1>; } }
    sphere { center: <0.3, 0.2, 0.3>; radius: 0.1; }
    point_light { position: <0, 0.5, 0>; intensity: <0.6, 0.6, 0.6>; LIGHT }
}
)";
    auto with = [&](const std::string& light) {
        std::string t = text;
        t.replace(t.find("LIGHT"), 5, light);
        return render_with(parse(t), 1);
    };
    const Image8 soft = with("radius: 1;"), point = with("");
    std::string plain = text;
    const Scene scene = parse(plain.replace(plain.find("LIGHT"), 5, ""));
    const CameraFrame camera = camera_frame(scene.cameras[0], 20, 20);
    int inside = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            const Vec3 d = camera_direction(camera, x + 0.5, y + 0.5);
            const Vec3 p = camera.position + (-camera.position.y / d.y) * d;
            if (glm::length(Vec3(0, 0.5, 0) - p) < 0.99 &&
                glm::length(p - Vec3(0.3, 0.2, 0.3)) > 0.3) {
                EXPECT_EQ(at(soft, x, y), at(point, x, y)) << x << ", " << y;
                ++inside;
            }
        }
    EXPECT_GT(inside, 40);
    EXPECT_NE(soft, point);  // outside the sphere the light is soft
}

TEST(SoftShadow, GlassLetsItsTransmissionThroughOnEveryPath) {
    // Straight under a glass ball much larger than the light, every path to
    // the light crosses the ball twice: t^2, as a point light gives.
    const std::string text = R"(
render_settings { width: 1; height: 1; ambient_light: <0.1, 0.1, 0.1>; }
cameras { perspective_camera { position: <6, 1, 0>; look_at: <0, 0, 0>; } }
scene {
    plane { normal: <0, 1, 0>; distance: 0; material { pigment: <1, 1, 1>; diffuse: <1, 1, 1>; } }
    sphere { center: <0, 2, 0>; radius: 1.5;
             material { pigment: <0, 0, 0>; transmission: 0.5; ior: 1.3; } }
    point_light { position: <0, 6, 0>; intensity: <1, 1, 1>; LIGHT }
}
)";
    auto with = [&](const std::string& light) {
        std::string t = text;
        t.replace(t.find("LIGHT"), 5, light);
        return at(render_with(parse(t), 1), 0, 0);
    };
    // No ambient term (the material's ambient is 0); 0.5^2 * dot(N, L) with
    // N = L = <0, 1, 0>: 0.25 -> 63.75 -> 64. Unshadowed it would be 255.
    EXPECT_EQ(with(""), (Rgb{64, 64, 64}));
    EXPECT_EQ(with("radius: 0.5; shadow_samples: 64;"), (Rgb{64, 64, 64}));
}

}  // namespace
}  // namespace jt::test
