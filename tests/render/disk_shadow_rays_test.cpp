// A soft light's shadow rays from one hit share work (docs/language.md §14.1):
// the list of shapes near the cone to the light's disk must hold every shape
// that blocks one of them, and neither that list nor the packets of
// occluded_together may change an answer of occluded().

#include "geometry/intersect.hpp"
#include "jtracer/affine.hpp"
#include "render/light_disk.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <random>
#include <vector>

namespace jt::test {
namespace {

bool blocks(const Geometry& g, std::uint32_t listed, const ShadowRay& r) {
    const std::uint32_t i = listed & ~shape_flag;
    if (!(listed & shape_flag))
        return intersect_sphere(r.origin, r.direction, g.spheres[i].center, g.spheres[i].radius,
                                r.t_min, r.t_max) != no_hit;
    const TransformedShape& s = g.shapes[i];
    const Vec3 o = apply_point(s.to_object, r.origin), d = apply_vector(s.to_object, r.direction);
    CylinderPart part;
    const double t = s.kind == TransformedShape::Kind::sphere
                         ? intersect_sphere(o, d, s.center, s.radius, r.t_min, r.t_max)
                         : intersect_cylinder(o, d, s.radius, s.height, r.t_min, r.t_max, part);
    return t != no_hit;
}

struct Counts {
    int blocked = 0, open = 0;
};

// Hits on the crowd's spheres (and random points), each lit by a soft light
// of 16 points; the rays leave the point lifted along its normal, as
// disk_visibility's do.
void check_disk_rays(int count, unsigned seed, bool expect_list, Counts& counts) {
    std::mt19937 rng(seed);
    Scene scene = random_crowd(rng, count, 6.0, 1.2);
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    std::uniform_real_distribution<double> u(-9.0, 9.0), unit(-1.0, 1.0);
    for (const Vec3 light : {Vec3{0, 20, 0}, Vec3{0.3, 0.2, -0.1}, Vec3{-7, 3, 8}}) {
        for (int i = 0; i < 400; ++i) {
            Vec3 point{u(rng), u(rng), u(rng)};
            Vec3 normal = glm::normalize(Vec3{unit(rng), unit(rng), unit(rng)});
            if (i % 2 == 1 && !g.spheres.empty()) {
                const WorldSphere& s = g.spheres[rng() % g.spheres.size()];
                point = s.center + s.radius * normal;
            }
            const double lift = 1e-9 * 20.0;
            const Vec3 origin = point + lift * normal;
            const double radius = 0.05 + 1.5 * (unit(rng) + 1.0);
            const Vec3 to_light = light - point;
            if (!(glm::length(to_light) > radius)) continue;
            const LightDisk disk = light_disk(light, radius, glm::normalize(to_light));

            DiskCandidates near;
            ASSERT_EQ(shapes_toward_disk(g, point, lift, light, radius, near), expect_list);
            std::vector<ShadowRay> rays;
            for (int m = 0; m < 16; ++m) {
                const Vec3 q = disk_point(disk, m, 16, 0.7 * i);
                const Vec3 path = q - origin;
                const double length = glm::length(path);
                rays.push_back({origin, path / length, 0.0, length});
            }
            bool together[shadow_packet];
            OccluderHint hint;
            occluded_together(g, rays, together, &hint);
            for (std::size_t m = 0; m < rays.size(); ++m) {
                const ShadowRay& r = rays[m];
                const bool alone = occluded(g, r.origin, r.direction, r.t_min, r.t_max);
                ASSERT_EQ(together[m], alone) << "hit " << i << " ray " << m;
                (alone ? counts.blocked : counts.open)++;
                if (!expect_list) continue;
                const ListedShapes listed = near.listed();
                ASSERT_EQ(
                    occluded_among(g, listed, r.origin, r.direction, r.t_min, r.t_max, nullptr, {}),
                    alone)
                    << "hit " << i << " ray " << m;
                for (std::uint32_t c = 0; c < g.spheres.size() + g.shapes.size(); ++c) {
                    const std::uint32_t shape =
                        c < g.spheres.size()
                            ? c
                            : static_cast<std::uint32_t>(c - g.spheres.size()) | shape_flag;
                    if (blocks(g, shape, r)) {
                        ASSERT_NE(std::ranges::find(listed.shapes, shape), listed.shapes.end())
                            << "hit " << i << " ray " << m << ": blocker " << c << " not listed";
                    }
                }
            }
        }
    }
}

TEST(DiskShadowRays, ListHoldsEveryBlockerWithoutBvh) {
    Counts c;
    check_disk_rays(7, 21, true, c);
    EXPECT_GT(c.blocked, 1000);
    EXPECT_GT(c.open, 1000);
}

TEST(DiskShadowRays, ListHoldsEveryBlockerWithBvh) {
    Counts c;
    check_disk_rays(60, 22, true, c);
    EXPECT_GT(c.blocked, 1000);
    EXPECT_GT(c.open, 1000);
}

TEST(DiskShadowRays, PacketsAnswerAsSingleRays) {
    // Too many shapes for a list: the rays go through the BVH as packets.
    Counts c;
    check_disk_rays(300, 23, false, c);
    EXPECT_GT(c.blocked, 1000);
    EXPECT_GT(c.open, 1000);
}

}  // namespace
}  // namespace jt::test
