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
    double t = s.kind == ShapeKind::sphere
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
        DirectionTable table = build_direction_table(g, light, table_resolution(count, false));
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
                ASSERT_NE(std::ranges::find(candidates->shapes, candidate),
                          candidates->shapes.end())
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

// Whether the ray hits anything, after checking that the table's answer is
// the BVH's to the bit.
bool same_first_hit(const Geometry& g, const DirectionTable& table, const Vec3& eye, const Vec3& d,
                    int ray, std::uint32_t* source = nullptr) {
    Hit expected, actual;
    const bool hit = closest_hit(g, eye, d, 0.0, expected);
    EXPECT_EQ(closest_hit(g, eye, d, 0.0, actual, &table), hit) << "ray " << ray;
    if (!hit) return false;
    EXPECT_EQ(actual.t, expected.t) << "ray " << ray;
    EXPECT_EQ(actual.source, expected.source) << "ray " << ray;
    EXPECT_EQ(actual.normal, expected.normal) << "ray " << ray;
    if (source) *source = expected.source;
    return true;
}

// Around a camera: the first hit through the table is the BVH's, to the bit,
// for rays all over the sphere of directions and rays grazing silhouettes.
void check_camera_table(int count, unsigned seed) {
    auto prepared = prepare_scene(crowd(count, seed)).value();
    const Geometry& g = *prepared->geometry;
    std::mt19937 rng(seed + 2);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (Vec3 eye : {Vec3{0, 2, 15}, Vec3{0.5, -0.3, 0.2}}) {
        DirectionTable table = build_direction_table(g, eye, table_resolution(count, true));
        ASSERT_GT(table.resolution, 0);
        int hits = 0;
        for (int i = 0; i < 20000; ++i) {
            Vec3 d = glm::normalize(Vec3{unit(rng), unit(rng), unit(rng)});
            if (i % 2 == 1 && !g.spheres.empty()) {
                const WorldSphere& s = g.spheres[rng() % g.spheres.size()];
                Vec3 axis = glm::normalize(s.center - eye);
                Vec3 side = glm::normalize(glm::cross(axis, d));
                d = glm::normalize(s.center + s.radius * (1.0 + 1e-12 * unit(rng)) * side - eye);
            }
            hits += same_first_hit(g, table, eye, d, i);
            ASSERT_FALSE(::testing::Test::HasFailure());
        }
        EXPECT_GT(hits, 2000);
    }
}

TEST(DirectionTable, FirstHitsAroundACameraWithBvh) {
    check_camera_table(300, 21);
}

TEST(DirectionTable, FirstHitsAroundACameraWithoutBvh) {
    check_camera_table(7, 22);
}

TEST(DirectionTable, LongCoveredListsGiveTheBvhsFirstHits) {
    // Hundreds of big spheres overlapping along the view, as in the nested
    // shells benchmark: the central cells list more than max_covered_position,
    // each is covered, and a walk of them (handing over to the BVH when it
    // runs long) finds the BVH's hit to the bit. Tiny far spheres beside them
    // cover no cell.
    Scene scene;
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 400; ++i)
        scene.primitives.push_back(sphere({0.5 * unit(rng), 0.5 * unit(rng), -5.0 - 0.05 * i},
                                          1.0 + 0.5 * (unit(rng) + 1)));
    for (int i = 0; i < 100; ++i)
        scene.primitives.push_back(sphere({30.0 + 0.3 * (i % 10), 0.3 * (i / 10), -40.0}, 0.01));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    ASSERT_TRUE(g.bvh);
    const Vec3 eye{0, 0, 10};
    DirectionTable table = build_direction_table(g, eye, table_resolution(500, true));
    ASSERT_GT(table.resolution, 0);
    auto ahead = shapes_toward(table, {0, 0, -1});
    ASSERT_TRUE(ahead);
    EXPECT_GT(ahead->size(), max_covered_position);
    EXPECT_TRUE(ahead->covered);
    auto tiny = shapes_toward(table, Vec3{31.0, 1.0, -40.0} - eye);
    ASSERT_TRUE(tiny);
    EXPECT_GE(tiny->size(), 1u);
    EXPECT_FALSE(tiny->covered);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 target = i % 4 == 3
                                ? Vec3{30.0 + 1.5 * (unit(rng) + 1), 1.5 * (unit(rng) + 1), -40}
                                : Vec3{1.5 * unit(rng), 1.5 * unit(rng), -5.0};
        const Vec3 d = glm::normalize(target - eye);
        hits += same_first_hit(g, table, eye, d, i);
        ASSERT_FALSE(::testing::Test::HasFailure());
    }
    EXPECT_GT(hits, 10000);
}

TEST(DirectionTable, AWalkThatRunsLongHandsOverToTheBvh) {
    // A big sphere covers the cell, nearest of all, but the cell's rays meet
    // it farther than the 300 tiny spheres listed after it: the walk stops
    // after max_covered_position of them, and the BVH finds the rest.
    Scene scene;
    scene.primitives.push_back(sphere({0, 0, -100}, 90.0));
    const Vec3 eye{0, 0, 10};
    const Vec3 along = glm::normalize(Vec3{0, 0.3, -1});
    std::mt19937 rng(32);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 300; ++i)
        scene.primitives.push_back(
            sphere(eye + (20.2 + 0.002 * i) * along + 0.05 * Vec3{unit(rng), unit(rng), 0}, 0.02));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    ASSERT_TRUE(g.bvh);
    DirectionTable table = build_direction_table(g, eye, table_resolution(301, true));
    ASSERT_GT(table.resolution, 0);
    auto listed = shapes_toward(table, along);
    ASSERT_TRUE(listed);
    EXPECT_GT(listed->size(), max_covered_position);
    EXPECT_TRUE(listed->covered);
    int tiny = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 d = glm::normalize(along + 0.004 * Vec3{unit(rng), unit(rng), unit(rng)});
        std::uint32_t source = 0;
        ASSERT_TRUE(same_first_hit(g, table, eye, d, i, &source));
        ASSERT_FALSE(::testing::Test::HasFailure());
        tiny += source != 0;
    }
    EXPECT_GT(tiny, 0);
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
        build_direction_table(*prepared->geometry, {0, 10, 4}, table_resolution(64, false));
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
                EXPECT_LE(table.nearest[k - 1], table.nearest[k]);
            }
            const WorldSphere& s = g.spheres[table.shapes[k]];
            EXPECT_LT(table.nearest[k], glm::length(s.center - Vec3{0, 10, 4}) - s.radius);
            EXPECT_GT(table.nearest[k], glm::length(s.center - Vec3{0, 10, 4}) - s.radius - 1e-3);
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
    DirectionTable table = build_direction_table(g, {0, 0, 0}, table_resolution(1500, false));
    EXPECT_EQ(table.resolution, 0);
    EXPECT_TRUE(table.shapes.empty());
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
