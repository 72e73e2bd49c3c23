// Light tables only narrow the search: every shape that blocks a shadow ray
// must be among its cell's candidates, and occlusion answers must not change.

#include "render/direction_table.hpp"
#include "geometry/intersect.hpp"
#include "jtracer/affine.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <random>

namespace jt::test {
namespace {

// A crowd of spheres, ellipsoids and cylinders around the origin.
Scene crowd(int count, unsigned seed) {
    std::mt19937 rng(seed);
    return random_crowd(rng, count, 6.0, 1.2);
}

bool blocks(const Geometry& g, std::uint32_t candidate, const Vec3& o, const Vec3& d,
            double t_max) {
    const std::uint32_t i = candidate & ~shape_flag;
    if (!(candidate & shape_flag))
        return intersect_sphere(o, d, g.spheres[i].center, g.spheres[i].radius, 0.0, t_max) !=
               no_hit;
    const TransformedShape& s = g.shapes[i];
    Vec3 oo = apply_point(s.to_object, o), dd = apply_vector(s.to_object, d);
    CylinderPart part;
    double t = s.kind == TransformedShape::Kind::sphere
                   ? intersect_sphere(oo, dd, s.center, s.radius, 0.0, t_max)
                   : intersect_cylinder(oo, dd, s.radius, s.height, 0.0, t_max, part);
    return t != no_hit;
}

// Shadow rays from points on shapes' surfaces and from random points, including
// rays aimed at silhouettes (where rounding decides), toward lights inside and
// outside the crowd.
void check_buffers(int count, unsigned seed) {
    Scene scene = crowd(count, seed);
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<double> u(-9.0, 9.0), unit(-1.0, 1.0);
    int blocked = 0, open = 0;
    for (Vec3 light : {Vec3{0, 20, 0}, Vec3{0.3, 0.2, -0.1}, Vec3{-7, 3, 8}, Vec3{5, -1, 2}}) {
        DirectionTable table = build_direction_table(g, light, table_resolution(count));
        ASSERT_GT(table.resolution, 0);
        for (int i = 0; i < 6000; ++i) {
            Vec3 origin{u(rng), u(rng), u(rng)};
            if (i % 2 == 1 && !g.spheres.empty()) {
                // Just outside a sphere's silhouette as seen from the light.
                const WorldSphere& s = g.spheres[rng() % g.spheres.size()];
                Vec3 axis = glm::normalize(s.center - light);
                Vec3 side = glm::normalize(glm::cross(axis, Vec3{unit(rng), unit(rng), unit(rng)}));
                double grazing = s.radius * (1.0 + 1e-12 * unit(rng));
                origin = s.center + grazing * side + (1.0 + 2.0 * (unit(rng) + 1.0)) * axis;
            }
            Vec3 to_light = light - origin;
            double distance = glm::length(to_light);
            Vec3 d = to_light / distance;
            auto candidates = shapes_toward(table, -d);
            ASSERT_TRUE(candidates);
            for (std::uint32_t c = 0; c < g.spheres.size() + g.shapes.size(); ++c) {
                std::uint32_t candidate =
                    c < g.spheres.size()
                        ? c
                        : static_cast<std::uint32_t>(c - g.spheres.size()) | shape_flag;
                if (!blocks(g, candidate, origin, d, distance)) continue;
                ASSERT_NE(std::ranges::find(candidates->entries, candidate, &Listed::shape),
                          candidates->entries.end())
                    << "ray " << i << " blocked by " << c << " missing from its cell";
            }
            OccluderHint hint;
            bool with = occluded(g, origin, d, 0.0, distance, &hint, &table);
            ASSERT_EQ(with, occluded(g, origin, d, 0.0, distance)) << "ray " << i;
            (with ? blocked : open)++;
        }
    }
    EXPECT_GT(blocked, 1000);
    EXPECT_GT(open, 1000);
}

TEST(DirectionTable, HoldsEveryBlockerWithBvh) {
    check_buffers(300, 11);
}

TEST(DirectionTable, HoldsEveryBlockerWithoutBvh) {
    check_buffers(7, 12);
}

TEST(DirectionTable, CellsAreFewAndSmallForSparseShapes) {
    // 64 small spheres on a floor seen from a light above: most cells list none
    // or one, which is what makes the table worth its building.
    Scene scene;
    for (int x = 0; x < 8; ++x)
        for (int z = 0; z < 8; ++z)
            scene.primitives.push_back(sphere({2.0 * x - 7, 0.6, 2.0 * z - 7}, 0.6));
    auto prepared = prepare_scene(scene).value();
    DirectionTable table =
        build_direction_table(*prepared->geometry, {0, 10, 4}, table_resolution(64));
    ASSERT_GT(table.resolution, 0);
    const std::size_t cells = table.cell_start.size() - 1;
    std::size_t most = 0, empty = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        const std::size_t listed = table.cell_start[c + 1] - table.cell_start[c];
        most = std::max(most, listed);
        empty += listed == 0;
    }
    EXPECT_LE(most, 4u);
    // Each list nearest first, and `nearest` a true lower bound.
    const Geometry& g = *prepared->geometry;
    for (std::size_t c = 0; c < cells; ++c)
        for (std::uint32_t k = table.cell_start[c]; k < table.cell_start[c + 1]; ++k) {
            if (k > table.cell_start[c]) {
                EXPECT_LE(table.listed[k - 1].nearest, table.listed[k].nearest);
            }
            const WorldSphere& s = g.spheres[table.listed[k].shape];
            EXPECT_LT(table.listed[k].nearest, glm::length(s.center - Vec3{0, 10, 4}) - s.radius);
            EXPECT_GT(table.listed[k].nearest,
                      glm::length(s.center - Vec3{0, 10, 4}) - s.radius - 1e-3);
        }
    EXPECT_GT(empty, cells * 3 / 4);
    // Up, away from the floor: nothing to test.
    auto up = shapes_toward(table, {0.1, 1.0, 0.2});
    ASSERT_TRUE(up);
    EXPECT_EQ(up->size(), 0u);
    // Toward one sphere's centre: that sphere, and at most a neighbour.
    auto toward = shapes_toward(table, Vec3{1, 0.6, 1} - Vec3{0, 10, 4});
    ASSERT_TRUE(toward);
    EXPECT_GE(toward->size(), 1u);
    EXPECT_LE(toward->size(), 2u);
    // A zero direction cannot pick a cell.
    EXPECT_FALSE(shapes_toward(table, {0, 0, 0}));
}

TEST(DirectionTable, NoneWhenShapesSurroundThePoint) {
    // Shells around the light: each is listed in every cell, so the table
    // would hold millions of listings. None is built; the BVH answers.
    Scene scene;
    for (int i = 0; i < 1500; ++i) scene.primitives.push_back(sphere({0, 0, 0}, 1.0 + 0.01 * i));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    DirectionTable table = build_direction_table(g, {0, 0, 0}, table_resolution(1500));
    EXPECT_EQ(table.resolution, 0);
    EXPECT_TRUE(table.listed.empty());
    EXPECT_FALSE(shapes_toward(table, {1, 0, 0}));
    EXPECT_TRUE(occluded(g, {0, 0, 20}, {0, 0, -1}, 0.0, 20.0, nullptr, &table));
}

TEST(DirectionTable, NoneWhenTheTablesWouldCostMoreThanTheySave) {
    auto prepared = prepare_scene(crowd(300, 13)).value();
    std::vector<PointLight> lights(300, PointLight{{0, 20, 0}, Colour(1.0)});
    EXPECT_TRUE(build_light_tables(*prepared->geometry, lights).empty());
    lights.resize(4);
    EXPECT_EQ(build_light_tables(*prepared->geometry, lights).size(), 4u);
}

}  // namespace
}  // namespace jt::test
