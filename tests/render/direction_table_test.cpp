// Light tables only narrow the search: every shape that blocks a shadow ray
// must be among its cell's candidates, and occlusion answers must not change.

#include "render/direction_table.hpp"
#include "geometry/intersect.hpp"
#include "jtracer/affine.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>
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
    // Inside the crowd every face has cells over all of it; from outside,
    // only windows of one to three faces (the last two lights: far off, the
    // crowd seen across a cube edge and a cube corner).
    for (Vec3 light : {Vec3{0, 20, 0}, Vec3{0.3, 0.2, -0.1}, Vec3{-7, 3, 8}, Vec3{5, -1, 2},
                       Vec3{60, 60.5, 0.2}, Vec3{-45, 45.3, -44.8}}) {
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
    std::size_t most = 0, at_most_one = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        const std::size_t listed = table.cell_start[c + 1] - table.cell_start[c];
        most = std::max(most, listed);
        at_most_one += listed <= 1;
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
            EXPECT_LE(table.nearest[k], padded_bound(s.center, s.radius, Vec3{0, 10, 4}).nearest);
        }
    EXPECT_GT(at_most_one, cells * 3 / 4);
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

TEST(DirectionTable, CellsSpanOnlyTheDirectionsOfShapes) {
    // 200 small spheres in a box 2 across, 40 from the light: over a whole
    // face they would crowd into a few cells of 29 an edge (lists of
    // dozens, left to the BVH). The cells span only the face's part where
    // the spheres lie, so they are much finer and their lists short.
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Scene scene;
    for (int i = 0; i < 200; ++i)
        scene.primitives.push_back(sphere({u(rng), 40.0 + u(rng), u(rng)}, 0.05));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const Vec3 light{0, 0, 0};
    DirectionTable table = build_direction_table(g, light, table_resolution(200));
    ASSERT_EQ(table.resolution, 29);
    std::size_t most = 0;
    for (std::size_t c = 0; c + 1 < table.cell_start.size(); ++c)
        most = std::max<std::size_t>(most, table.cell_start[c + 1] - table.cell_start[c]);
    EXPECT_LE(most, 16u);
    // Face 2 (+y) holds them all, within a window of about a twentieth of it.
    for (int face = 0; face < 6; ++face) {
        const FaceWindow& w = table.windows[static_cast<std::size_t>(face)];
        if (face == 2) {
            EXPECT_LT(w.u1 - w.u0, 0.1);
            EXPECT_LT(w.v1 - w.v0, 0.1);
        } else {
            EXPECT_GT(w.u0, w.u1) << "face " << face << " covers nothing";
        }
    }
    // Beside the window, and toward another face: nothing listed.
    auto beside = shapes_toward(table, {0.2, 1.0, 0.0});
    ASSERT_TRUE(beside);
    EXPECT_EQ(beside->size(), 0u);
    auto away = shapes_toward(table, {0.0, -1.0, 0.1});
    ASSERT_TRUE(away);
    EXPECT_EQ(away->size(), 0u);
    // Every sphere a ray toward it meets is listed, and the answers agree
    // with the BVH's.
    std::uniform_int_distribution<std::size_t> pick(0, g.spheres.size() - 1);
    int blocked = 0;
    for (int i = 0; i < 4000; ++i) {
        const WorldSphere& s = g.spheres[pick(rng)];
        // Beyond the sphere, aimed at the light near its silhouette.
        const Vec3 aim =
            s.center + s.radius * (1.0 + 0.01 * u(rng)) * glm::normalize(Vec3{u(rng), 0.0, u(rng)});
        const Vec3 origin = light + (aim - light) * (1.5 + u(rng) * 0.4);
        const double distance = glm::length(light - origin);
        const Vec3 d = (light - origin) / distance;
        auto candidates = shapes_toward(table, -d);
        ASSERT_TRUE(candidates);
        for (std::uint32_t c = 0; c < g.spheres.size(); ++c)
            if (blocks(g, c, origin, d, distance)) {
                ASSERT_NE(std::ranges::find(candidates->shapes, c), candidates->shapes.end())
                    << "ray " << i << " blocked by " << c << " missing from its cell";
            }
        const bool with = occluded(g, origin, d, 0.0, distance, nullptr, &table);
        ASSERT_EQ(with, occluded(g, origin, d, 0.0, distance)) << "ray " << i;
        blocked += with;
    }
    EXPECT_GT(blocked, 500);
    EXPECT_LT(blocked, 3500);
}

bool same_table(const DirectionTable& a, const DirectionTable& b) {
    for (std::size_t face = 0; face < 6; ++face) {
        const FaceWindow &x = a.windows[face], &y = b.windows[face];
        if (x.u0 != y.u0 || x.u1 != y.u1 || x.v0 != y.v0 || x.v1 != y.v1 ||
            x.u_scale != y.u_scale || x.v_scale != y.v_scale)
            return false;
    }
    return a.resolution == b.resolution && a.cell_start == b.cell_start && a.shapes == b.shapes &&
           a.nearest == b.nearest;
}

TEST(DirectionTable, TheSameWhateverTheThreads) {
    // Cones, windows and cells are worked out in parallel, and the tables
    // beside the BVH: each list must still come out as on one thread, nearest
    // first with ties in index order, for the light outside the crowd, inside
    // it (every face whole) and seen across a cube corner.
    Scene scene = crowd(3000, 21);
    for (const Vec3& light : {Vec3{0, 20, 0}, Vec3{0.3, 0.2, -0.1}, Vec3{-45, 45.3, -44.8}})
        scene.lights.push_back(PointLight{light, Colour(1.0)});
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    ASSERT_EQ(prepared->light_tables->size(), scene.lights.size());
    tbb::task_arena one_thread(1);
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
        const Vec3 light = scene.lights[k].position;
        DirectionTable alone;
        one_thread.execute(
            [&] { alone = build_direction_table(g, light, table_resolution(3000)); });
        ASSERT_GT(alone.resolution, 0);
        EXPECT_TRUE(same_table(alone, build_direction_table(g, light, table_resolution(3000))))
            << "light " << k;
        EXPECT_TRUE(same_table(alone, (*prepared->light_tables)[k])) << "light " << k;
    }
}

TEST(DirectionTable, ALongListIsWalkedOnlyUpToTheRaysOrigin) {
    // A row of spheres away from the light shares its cells, a list longer
    // than a walk takes (max_light_walk). A shadow ray from between two of
    // them meets only those nearer the light: from near the light the walk
    // is short, from far along the row the BVH answers. Either way the answer
    // is the one without the table, blocked from behind the first sphere on.
    constexpr int row = static_cast<int>(max_light_walk) + 40;
    Scene scene;
    for (int i = 0; i < row; ++i)
        scene.primitives.push_back(sphere({0.01 * (i % 3), 0, -2.0 * i}, 0.5));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const Vec3 light{0, 0, 10};
    DirectionTable table = build_direction_table(g, light, table_resolution(row));
    ASSERT_GT(table.resolution, 0);
    const auto listed = shapes_toward(table, {0, 0, -1});
    ASSERT_TRUE(listed);
    ASSERT_GT(listed->size(), max_light_walk + 20) << "one cell lists the whole row";
    for (int gap = 0; gap < row - 1; ++gap) {
        for (double side : {0.0, 0.3, 0.49, 0.51}) {
            const Vec3 origin{side, 0.2, -2.0 * gap - 1.0};
            const Vec3 to_light = light - origin;
            const double distance = glm::length(to_light);
            const Vec3 d = to_light / distance;
            const bool with = occluded(g, origin, d, 0.0, distance, nullptr, &table);
            EXPECT_EQ(with, occluded(g, origin, d, 0.0, distance)) << gap << ", " << side;
            if (side < 0.45) {
                EXPECT_TRUE(with) << gap << ", " << side;
            }
        }
    }
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
