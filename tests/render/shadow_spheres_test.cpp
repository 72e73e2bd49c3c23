// Hard shadow rays walk a BVH of padded float spheres (render/shadow_spheres.hpp)
// that only culls for the exact test: on rays that graze the spheres, start or
// end inside them or within the pad of them, occluded() must give the exact
// answer, and float spheres without the pad must lose some of those hits.

#include "render/shadow_spheres.hpp"
#include "geometry/intersect.hpp"
#include "jtracer/affine.hpp"
#include "render/direction_table.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace jt::test {
namespace {

// Heavily overlapping plain spheres of many sizes (the shadow BVH is built
// only for such), every fifth primitive a
// transformed cylinder (the shadow BVH's user geometry).
Scene sphere_crowd(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-4.0, 4.0), r(0.05, 2.5), angle(0.0, 360.0);
    Scene scene;
    for (int i = 0; i < 300; ++i) {
        Primitive p = i % 5 == 4 ? cylinder(0.3 * r(rng), 2.0 * r(rng))
                                 : sphere({u(rng), u(rng), u(rng)}, r(rng));
        if (i % 5 == 4)
            p.transforms = {rotate(TransformKind::xrotate, angle(rng)),
                            rotate(TransformKind::yrotate, angle(rng)),
                            translate({u(rng), u(rng), u(rng)})};
        scene.primitives.push_back(p);
    }
    return scene;
}

// The exact answer: every sphere and shape tested in double precision.
bool exactly_occluded(const Geometry& g, const ShadowRay& r) {
    for (const WorldSphere& s : g.spheres)
        if (intersect_sphere(r.origin, r.direction, s.center, s.radius, r.t_min, r.t_max) != no_hit)
            return true;
    for (const TransformedShape& s : g.shapes) {
        const Vec3 o = apply_point(s.to_object, r.origin),
                   d = apply_vector(s.to_object, r.direction);
        CylinderPart part;
        if (intersect_cylinder(o, d, s.radius, s.height, r.t_min, r.t_max, part) != no_hit)
            return true;
    }
    return false;
}

// Rays whose line passes the chosen sphere's centre within a hair of its
// radius (inside or out, by 2^-40 to 2^-6 of it), starting before, inside or
// past the sphere and ending anywhere along it; rays leaving from a hair
// inside or outside a sphere's surface; and rays that leave a point of a
// sphere's surface, lifted as trace's shadow rays are, for a random light.
std::vector<ShadowRay> grazing_rays(const Geometry& g, std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), hair(-40.0, -6.0), along(-1.5, 3.0);
    std::vector<ShadowRay> rays;
    for (int i = 0; i < count; ++i) {
        const WorldSphere& s = g.spheres[rng() % g.spheres.size()];
        Vec3 d = glm::normalize(Vec3{unit(rng), unit(rng), unit(rng)});
        if (i % 4 == 3) {
            const Vec3 light = 8.0 * Vec3{unit(rng), unit(rng), unit(rng)};
            const Vec3 point = s.center + s.radius * d;
            const Vec3 lifted = point + 1e-9 * 8.0 * d;
            const double distance = glm::length(light - lifted);
            rays.push_back({lifted, (light - lifted) / distance, 0.0, distance});
            continue;
        }
        if (i % 4 == 2) {
            // Just inside or outside the surface, leaving it: a crossing (or
            // none) a hair from the origin.
            const Vec3 n = glm::normalize(Vec3{unit(rng), unit(rng), unit(rng)});
            if (glm::dot(d, n) < 0.0) d = -d;
            const double offset = (rng() % 2 ? 1.0 : -1.0) * std::exp2(hair(rng));
            rays.push_back({s.center + s.radius * (1.0 + offset) * n, d, 0.0,
                            std::max(0.0, along(rng) + 1.5) * s.radius});
            continue;
        }
        Vec3 w = glm::normalize(glm::cross(d, Vec3{unit(rng), unit(rng), unit(rng)}));
        const double offset = (rng() % 2 ? 1.0 : -1.0) * std::exp2(hair(rng));
        const Vec3 closest = s.center + s.radius * (1.0 + offset) * w;
        const Vec3 origin = closest - along(rng) * s.radius * d;
        const double t_max = std::max(0.0, along(rng) + 1.5) * s.radius;
        rays.push_back({origin, d, 0.0, t_max});
    }
    return rays;
}

struct Tally {
    int blocked = 0, open = 0, wrong = 0;
};

Tally compare(const Geometry& g, const std::vector<ShadowRay>& rays) {
    Tally tally;
    for (const ShadowRay& r : rays) {
        const bool exact = exactly_occluded(g, r);
        (exact ? tally.blocked : tally.open) += 1;
        if (occluded(g, r.origin, r.direction, r.t_min, r.t_max) != exact) ++tally.wrong;
    }
    return tally;
}

TEST(ShadowSpheres, PaddedFloatSpheresKeepEveryExactHit) {
    for (unsigned seed : {1u, 2u, 3u}) {
        std::mt19937 rng(seed);
        auto prepared = prepare_scene(sphere_crowd(rng)).value();
        const Geometry& g = *prepared->geometry;
        ASSERT_NE(g.shadow.bvh, nullptr);
        const Tally tally = compare(g, grazing_rays(g, rng, 40000));
        EXPECT_EQ(tally.wrong, 0) << "seed " << seed;
        // Both answers common, so that the comparison means something.
        EXPECT_GT(tally.blocked, 5000) << "seed " << seed;
        EXPECT_GT(tally.open, 2000) << "seed " << seed;
    }
}

// In a crowded scene a shadow ray walks its light's cell list up to far more
// shapes than elsewhere before the shadow BVH takes over: both must give the
// exact answer, for rays from lifted points of the spheres' surfaces and
// from anywhere around them.
TEST(ShadowSpheres, CrowdedCellsGiveTheExactAnswer) {
    std::mt19937 rng(4);
    auto prepared = prepare_scene(sphere_crowd(rng)).value();
    const Geometry& g = *prepared->geometry;
    ASSERT_TRUE(g.crowded);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int long_cells = 0;
    for (const Vec3 light : {Vec3{0, 20, 0}, Vec3{15, -3, -10}, Vec3{-9, 4, 12}}) {
        const DirectionTable table =
            build_direction_table(g, light, table_resolution(g.spheres.size() + g.shapes.size()));
        Tally tally;
        for (int i = 0; i < 4000; ++i) {
            const WorldSphere& s = g.spheres[rng() % g.spheres.size()];
            const Vec3 n = glm::normalize(Vec3{unit(rng), unit(rng), unit(rng)});
            const Vec3 origin = i % 2 ? s.center + s.radius * n + 1e-9 * 8.0 * n
                                      : 9.0 * Vec3{unit(rng), unit(rng), unit(rng)};
            const double distance = glm::length(light - origin);
            const ShadowRay r{origin, (light - origin) / distance, 0.0, distance};
            auto cell = shapes_toward(table, -r.direction);
            ASSERT_TRUE(cell);
            if (cell->size() > 16) ++long_cells;
            const bool exact = exactly_occluded(g, r);
            (exact ? tally.blocked : tally.open) += 1;
            OccluderHint hint;
            if (occluded(g, r.origin, r.direction, r.t_min, r.t_max, &hint, &table) != exact)
                ++tally.wrong;
        }
        EXPECT_EQ(tally.wrong, 0);
        EXPECT_GT(tally.blocked, 500);
        EXPECT_GT(tally.open, 100);
    }
    EXPECT_GT(long_cells, 1000);
}

// The same rays against float spheres of the exact radius: Embree's float
// test misses some of the grazing hits, which is what the pad is for.
TEST(ShadowSpheres, UnpaddedFloatSpheresLoseHits) {
    std::mt19937 rng(1);
    auto prepared = prepare_scene(sphere_crowd(rng)).value();
    auto& g = const_cast<Geometry&>(*prepared->geometry);
    double magnitude = 0.0;
    for (const WorldSphere& s : g.spheres)
        magnitude = std::max({magnitude, std::abs(s.center.x) + s.radius,
                              std::abs(s.center.y) + s.radius, std::abs(s.center.z) + s.radius});
    rtcReleaseScene(g.shadow.bvh);
    g.shadow = {};
    build_shadow_spheres(g, magnitude, RTC_BUILD_QUALITY_MEDIUM, 0.0);
    const Tally tally = compare(g, grazing_rays(g, rng, 40000));
    EXPECT_GT(tally.wrong, 0);
}

}  // namespace
}  // namespace jt::test
