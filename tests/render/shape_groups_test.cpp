// The groups of a small scene (render/shape_groups.hpp) answer a ray without a
// list exactly as the BVH does, to the bit: rays leaving spheres and a plane
// as mirror rays do, rays grazing each sphere's outline and each group's rim
// (where a lane's sphere touches its group's) at a few 1e-12 of a radius in
// and out, rays from inside spheres and from far away, at several scales.

#include "render/shape_groups.hpp"

#include "geometry/intersect.hpp"
#include "render/listed_shapes.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "render/sphere_batch.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace jt::test {
namespace {

// Spheres on a loose grid, some touching and overlapping, a few scaled and
// rotated cylinders among them and a plane under them, all times `s`.
Scene small_scene(double s, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene scene;
    scene.primitives.push_back(plane({0, 1, 0}, 0.0));
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            const double r = s * (0.2 + 0.6 * unit(rng));
            scene.primitives.push_back(
                sphere({s * (2.0 * i - 4.0 + 0.4 * unit(rng)), r + s * unit(rng),
                        s * (2.0 * j - 4.0 + 0.4 * unit(rng))},
                       r));
        }
    for (int i = 0; i < 6; ++i) {
        Primitive c = cylinder(s * (0.1 + 0.3 * unit(rng)), s * (0.5 + 2.0 * unit(rng)));
        c.transforms = {rotate(TransformKind::zrotate, 60.0 * unit(rng)),
                        rotate(TransformKind::yrotate, 90.0 * unit(rng)),
                        translate({s * (2.0 * i - 5.0), 0.0, s * (-6.0 + unit(rng))})};
        scene.primitives.push_back(c);
    }
    return scene;
}

Vec3 any_direction(std::mt19937& rng) {
    std::normal_distribution<double> n;
    Vec3 d;
    do d = {n(rng), n(rng), n(rng)};
    while (!(glm::dot(d, d) > 1e-6));
    return glm::normalize(d);
}

std::uint64_t bits(double x) {
    return std::bit_cast<std::uint64_t>(x);
}

// The same query against the geometry with its groups and the one without
// (which walks the BVH): the same hit, t, shape and normal to the bit.
void same_hit(const Geometry& grouped, const Geometry& plain, const Vec3& origin,
              const Vec3& direction, int& hits) {
    Hit a, b;
    const bool found = closest_hit(grouped, origin, direction, 0.0, a);
    ASSERT_EQ(found, closest_hit(plain, origin, direction, 0.0, b));
    if (!found) return;
    ++hits;
    ASSERT_EQ(bits(a.t), bits(b.t));
    ASSERT_EQ(a.source, b.source);
    ASSERT_EQ(bits(a.normal.x), bits(b.normal.x));
    ASSERT_EQ(bits(a.normal.y), bits(b.normal.y));
    ASSERT_EQ(bits(a.normal.z), bits(b.normal.z));
}

// A sphere of the groups' lanes: lane k of `lanes`.
WorldSphere lane(const SphereLanes& lanes, std::size_t k) {
    return {Vec3(lanes.x[k], lanes.y[k], lanes.z[k]), lanes.r[k], 0};
}

// From `origin`, a ray past `s`'s outline by `miss` radii (negative: into it).
Vec3 grazing(const WorldSphere& s, const Vec3& origin, double miss, std::mt19937& rng) {
    const Vec3 to = s.center - origin;
    return glm::normalize(to + (s.radius * (1.0 + miss)) * across(to, rng));
}

constexpr double misses[] = {-1e-6, -1e-12, 0.0, 1e-12, 1e-6};

TEST(ShapeGroups, RaysWithoutAListMeetWhatTheBvhMeets) {
    for (const double s : {1e-3, 1.0, 1e4}) {
        std::mt19937 rng(57);
        const Scene scene = small_scene(s, rng);
        auto grouped_scene = prepare_scene(scene).value();
        auto plain_scene = prepare_scene(scene).value();
        ASSERT_NE(grouped_scene->geometry.get(), plain_scene->geometry.get());
        const Geometry& grouped = *grouped_scene->geometry;
        ASSERT_TRUE(grouped.bvh);
        ASSERT_FALSE(grouped.groups.empty());
        // The same geometry, its rays left to the BVH.
        Geometry& plain = const_cast<Geometry&>(*plain_scene->geometry);
        plain.groups = ShapeGroups{};

        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int rays = 0, hits = 0;
        auto trace = [&](const Vec3& origin, const Vec3& direction) {
            ++rays;
            same_hit(grouped, plain, origin, direction, hits);
        };
        for (const WorldSphere& from : grouped.spheres) {
            for (int k = 0; k < 40; ++k) {
                // A mirror ray leaving the sphere, lifted off it.
                const Vec3 n = any_direction(rng);
                const Vec3 point = from.center + from.radius * n;
                const Vec3 lifted = point + 1e-9 * s * 10.0 * n;
                Vec3 d = any_direction(rng);
                if (glm::dot(d, n) < 0.0) d = -d;
                trace(lifted, d);
                // From the same point, grazing another sphere's outline.
                const WorldSphere& to = grouped.spheres[rng() % grouped.spheres.size()];
                if (&to != &from)
                    for (const double miss : misses) trace(lifted, grazing(to, lifted, miss, rng));
                ASSERT_FALSE(::testing::Test::HasFailure());
            }
            // From inside the sphere.
            trace(from.center, any_direction(rng));
        }
        // Rays leaving the plane upward, as its mirror rays do.
        for (int k = 0; k < 2000; ++k) {
            const Vec3 origin{s * (12.0 * unit(rng) - 6.0), s * 1e-8, s * (12.0 * unit(rng) - 6.0)};
            Vec3 d = any_direction(rng);
            d.y = std::abs(d.y);
            trace(origin, d);
            ASSERT_FALSE(::testing::Test::HasFailure());
        }
        // Each group's rim: where its farthest lane touches it, rays tangent
        // to both, just in and just out, from points around the scene.
        const ShapeGroups& groups = grouped.groups;
        for (std::size_t g = 0; g < groups.count(); ++g) {
            const WorldSphere rim = lane(groups.bounds[g / sphere_batch], g % sphere_batch);
            for (std::size_t k = 0; k < sphere_batch; ++k) {
                if (!(groups.used[g] >> k & 1u)) continue;
                const WorldSphere member = lane(groups.members[g], k);
                Vec3 out = member.center - rim.center;
                out = glm::dot(out, out) > 0.0 ? glm::normalize(out) : Vec3(0, 1, 0);
                const Vec3 touch = member.center + member.radius * out;
                for (int m = 0; m < 20; ++m) {
                    const Vec3 along = across(out, rng);
                    for (const double miss : misses) {
                        const Vec3 through = touch + (miss * member.radius) * out;
                        const Vec3 origin = through - s * (1.0 + 8.0 * unit(rng)) * along;
                        trace(origin, along);
                    }
                    ASSERT_FALSE(::testing::Test::HasFailure());
                }
            }
        }
        // From far away, beyond what the groups take: the BVH answers both.
        for (int k = 0; k < 200; ++k) {
            const Vec3 origin = 100.0 * s * any_direction(rng);
            trace(origin, grazing(grouped.spheres[k % grouped.spheres.size()], origin,
                                  misses[k % std::size(misses)], rng));
        }
        EXPECT_GT(rays, 6000);
        EXPECT_GT(hits, rays / 4) << "scale " << s;
    }
}

TEST(ShapeGroups, LanesReadWholeGiveTheGatheredLanesAnswers) {
    // lanes_missed_early (SSE2, and AVX where the processor has it) against
    // spheres_missed_early of the same spheres, which the scalar test checks.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int decided = 0;
    for (int round = 0; round < 20000; ++round) {
        SphereLanes lanes;
        WorldSphere spheres[sphere_batch];
        const WorldSphere* gathered[sphere_batch];
        for (std::size_t k = 0; k < sphere_batch; ++k) {
            spheres[k] = {Vec3(4.0 * unit(rng), 4.0 * unit(rng), 4.0 * unit(rng)), 0.1 + unit(rng),
                          0};
            lanes.x[k] = spheres[k].center.x;
            lanes.y[k] = spheres[k].center.y;
            lanes.z[k] = spheres[k].center.z;
            lanes.r[k] = spheres[k].radius;
            gathered[k] = &spheres[k];
        }
        const Vec3 origin(6.0 * unit(rng) - 1.0, 6.0 * unit(rng) - 1.0, 6.0 * unit(rng) - 1.0);
        const Vec3 direction = round % 2 ? any_direction(rng)
                                         : grazing(spheres[round % sphere_batch], origin,
                                                   misses[round % std::size(misses)], rng);
        const double t_min = round % 3 == 0 ? -1.0 : 0.0;
        const double t_max = 8.0 * unit(rng);
        const BatchRay ray = batch_ray(origin, direction, t_min);
        const unsigned expected = spheres_missed_early<true>(gathered, ray, t_max);
        ASSERT_EQ(lanes_missed_early<true>(lanes, ray, t_max), expected);
        ASSERT_EQ(lanes_missed_early<false>(lanes, ray, t_max),
                  spheres_missed_early<false>(gathered, ray, t_max));
#if defined(JT_SPHERE_BATCH_AVX)
        if (sphere_batch_avx()) {
            ASSERT_EQ(lanes_missed_early_avx<true>(lanes, ray, t_max), expected);
            ASSERT_EQ(lanes_missed_early_avx<false>(lanes, ray, t_max),
                      spheres_missed_early<false>(gathered, ray, t_max));
        }
#endif
        decided += std::popcount(expected);
    }
    EXPECT_GT(decided, 20000);
}

TEST(ShapeGroups, EveryShapeInOneGroupOnce) {
    std::mt19937 rng(3);
    const Scene scene = small_scene(1.0, rng);
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const ShapeGroups& groups = g.groups;
    ASSERT_FALSE(groups.empty());
    std::vector<int> seen(g.spheres.size() + g.shapes.size(), 0);
    for (std::size_t group = 0; group < groups.count(); ++group)
        for (std::size_t k = 0; k < sphere_batch; ++k) {
            if (!(groups.used[group] >> k & 1u)) continue;
            const std::uint32_t listed = groups.listed[group * sphere_batch + k];
            const bool is_sphere = !(listed & shape_flag);
            EXPECT_EQ(is_sphere, (groups.spheres[group] >> k & 1u) != 0);
            ++seen[is_sphere ? listed : g.spheres.size() + (listed & ~shape_flag)];
        }
    for (const int n : seen) EXPECT_EQ(n, 1);
}

TEST(ShapeGroups, NoneForMoreShapesThanTheLimit) {
    Scene scene;
    for (std::size_t i = 0; i <= max_grouped_shapes; ++i)
        scene.primitives.push_back(sphere({3.0 * static_cast<double>(i), 0, 0}, 1.0));
    auto prepared = prepare_scene(scene).value();
    EXPECT_TRUE(prepared->geometry->groups.empty());
    scene.primitives.pop_back();
    auto fewer = prepare_scene(scene).value();
    EXPECT_FALSE(fewer->geometry->groups.empty());
}

}  // namespace
}  // namespace jt::test
