// The view table only narrows the search: through its lists every camera ray
// finds the BVH's first hit to the bit, through pixel centres, anywhere inside
// a pixel and along silhouettes, from cameras outside a crowd, inside it and
// inside a sphere, with shapes behind the camera, at wide and narrow fields.

#include "render/view_table.hpp"
#include "geometry/intersect.hpp"

#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

namespace jt::test {
namespace {

CameraFrame view(const Vec3& eye, const Vec3& look_at, double fov, int width, int height) {
    Camera camera = camera_at(eye, look_at);
    camera.fov = fov;
    camera.aspect = static_cast<double>(width) / height;
    return camera_frame(camera, width, height);
}

// Every block's list, row by row.
std::vector<ListedShapes> block_lists(const ViewTable& table) {
    std::vector<ListedShapes> lists;
    for (int row = 0; row < table.rows; ++row)
        for (int column = 0; column < table.columns; ++column)
            lists.push_back(block_shapes(table, column, row));
    return lists;
}

// Whether the ray through image point (x, y) hits anything, after checking
// that the table's answer is the BVH's to the bit.
bool same_first_hit(const Geometry& g, const ViewTable& table, const CameraFrame& camera, double x,
                    double y, std::uint32_t* source = nullptr) {
    const Vec3 d = camera_direction(camera, x, y);
    Hit expected, actual;
    const bool hit = closest_hit(g, camera.position, d, 0.0, expected);
    const ListedShapes seen = shapes_seen(table, x, y);
    EXPECT_EQ(closest_hit(g, camera.position, d, 0.0, actual, &seen), hit) << x << ", " << y;
    if (!hit) return false;
    EXPECT_EQ(actual.t, expected.t) << x << ", " << y;
    EXPECT_EQ(actual.source, expected.source) << x << ", " << y;
    EXPECT_EQ(actual.normal, expected.normal) << x << ", " << y;
    if (source) *source = expected.source;
    return true;
}

// Where the direction `d` meets the image, in pixels; false off the image.
bool image_point(const CameraFrame& c, const Vec3& d, double& x, double& y) {
    const double z = glm::dot(d, c.forward);
    if (!(z > 0.0)) return false;
    x = (glm::dot(d, c.right) / z / (c.tan_half_fov * c.aspect) + 1.0) * 0.5 * c.width;
    y = (glm::dot(d, c.up) / z / c.tan_half_fov + 1.0) * 0.5 * c.height;
    return x >= 0.0 && x < c.width && y >= 0.0 && y < c.height;
}

// Every pixel centre, random points inside pixels, and points whose rays
// graze the silhouettes of the crowd's spheres. Returns the hits.
int check_view(const Geometry& g, const CameraFrame& camera, unsigned seed) {
    const ViewTable table = build_view_table(g, camera);
    EXPECT_TRUE(table.built);
    if (!table.built) return 0;
    int hits = 0;
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            hits += same_first_hit(g, table, camera, x + 0.5, y + 0.5);
            if (::testing::Test::HasFailure()) return hits;
        }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), along(0.0, 1.0);
    for (int i = 0; i < 5000; ++i) {
        hits +=
            same_first_hit(g, table, camera, along(rng) * camera.width, along(rng) * camera.height);
        if (::testing::Test::HasFailure()) return hits;
    }
    int grazing = 0;
    for (int i = 0; i < 20000 && !g.spheres.empty(); ++i) {
        const WorldSphere& s = g.spheres[rng() % g.spheres.size()];
        const Vec3 axis = glm::normalize(s.center - camera.position);
        const Vec3 side = glm::normalize(glm::cross(axis, Vec3{unit(rng), unit(rng), unit(rng)}));
        const Vec3 d = s.center + s.radius * (1.0 + 1e-12 * unit(rng)) * side - camera.position;
        double x, y;
        if (!image_point(camera, glm::normalize(d), x, y)) continue;
        ++grazing;
        hits += same_first_hit(g, table, camera, x, y);
        if (::testing::Test::HasFailure()) return hits;
    }
    if (!g.spheres.empty()) {
        EXPECT_GT(grazing, 100);
    }
    return hits;
}

std::shared_ptr<const PreparedScene> crowd(int count, unsigned seed) {
    std::mt19937 rng(seed);
    return prepare_scene(random_crowd(rng, count, 6.0, 1.2)).value();
}

TEST(ViewTable, FirstHitsFromOutsideACrowd) {
    auto prepared = crowd(300, 21);
    ASSERT_TRUE(prepared->geometry->bvh);
    EXPECT_GT(check_view(*prepared->geometry, view({0, 2, 15}, {0, 0, 0}, 45, 160, 90), 1), 3000);
}

TEST(ViewTable, FirstHitsFromInsideACrowdWithShapesBehindTheCamera) {
    auto prepared = crowd(300, 22);
    for (const Vec3& look : {Vec3{0, 0, -1}, Vec3{3, 1, 2}})
        EXPECT_GT(check_view(*prepared->geometry, view({0.5, -0.3, 0.2}, look, 90, 97, 61), 2),
                  1000);
}

TEST(ViewTable, FirstHitsWithoutBvh) {
    auto prepared = crowd(7, 23);
    ASSERT_FALSE(prepared->geometry->bvh);
    EXPECT_GT(check_view(*prepared->geometry, view({0, 2, 15}, {0, 0, 0}, 45, 120, 80), 3), 100);
}

TEST(ViewTable, FirstHitsAtWideAndNarrowFields) {
    auto prepared = crowd(300, 24);
    const Geometry& g = *prepared->geometry;
    EXPECT_GT(check_view(g, view({0, 1, 9}, {0, 0, 0}, 170, 90, 90), 4), 1000);
    // Two degrees across, aimed at one sphere: a few spheres fill the image.
    const Vec3 target = g.spheres[5].center;
    EXPECT_GT(check_view(g, view({0, 1, 30}, target, 2, 64, 48), 5), 500);
}

TEST(ViewTable, RaysJustInsideAndOutsideEachOutlineFindTheBvhsFirstHit) {
    // Spheres in front of a wall of big spheres: a ray just outside a front
    // sphere's outline meets the wall. The table must list the front sphere in
    // every block its outline reaches, and must not count a block as covered
    // (leaving the wall out) unless the sphere holds all of it: rays within a
    // millionth of a pixel of each outline's four extremes check both.
    Scene scene;
    std::mt19937 rng(27);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 60; ++i)
        scene.primitives.push_back(
            sphere({4 * unit(rng), 3 * unit(rng), -5 + unit(rng)}, 0.3 + 0.5 * (unit(rng) + 1)));
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 11; ++j)
            scene.primitives.push_back(sphere({-28.0 + 4 * i, -20.0 + 4 * j, -40.0}, 3.0));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const CameraFrame c = view({0, 0, 10}, {0, 0, -1}, 40, 160, 120);
    const ViewTable table = build_view_table(g, c);
    ASSERT_TRUE(table.built);
    int tested = 0, hits = 0;
    for (int i = 0; i < 60; ++i) {
        const WorldSphere& s = g.spheres[i];
        const Vec3 v = s.center - c.position;
        const double x = glm::dot(v, c.right), y = glm::dot(v, c.up), z = glm::dot(v, c.forward);
        // The points where planes through the camera's up (then right) axis
        // touch the sphere: the outline's extremes across (then down) the image.
        for (int axis = 0; axis < 2; ++axis) {
            const double a = axis == 0 ? x : y;
            const double across = std::hypot(a, z);
            const double half = std::asin(s.radius / across);
            for (double side : {-1.0, 1.0}) {
                const double angle = std::atan2(a, z) + side * half;
                // The tangent plane's normal in (a, z), and the touching point.
                const double na = std::cos(angle), nz = -std::sin(angle);
                const double off = a * na + z * nz;
                const Vec3 normal = (axis == 0 ? na * c.right : na * c.up) + nz * c.forward;
                const Vec3 touch = v - off * normal;
                double px, py;
                if (!image_point(c, glm::normalize(touch), px, py)) continue;
                for (double step : {-1e-2, -1e-4, -1e-6, 0.0, 1e-6, 1e-4, 1e-2}) {
                    const double qx = axis == 0 ? px + side * step : px;
                    const double qy = axis == 1 ? py + side * step : py;
                    if (qx < 0 || qy < 0 || qx >= c.width || qy >= c.height) continue;
                    ++tested;
                    hits += same_first_hit(g, table, c, qx, qy);
                    ASSERT_FALSE(::testing::Test::HasFailure());
                }
            }
        }
    }
    EXPECT_GT(tested, 1000);
    EXPECT_EQ(hits, tested) << "inside an outline the sphere, outside it the wall";
    // Every covered block, on a fine grid of points: the wall is left out of
    // its list, so any point the covering sphere missed would show.
    int covered = 0;
    for (int row = 0; row < table.rows; ++row)
        for (int column = 0; column < table.columns; ++column) {
            if (!table.covered[static_cast<std::size_t>(row) * table.columns + column]) continue;
            ++covered;
            for (int j = 0; j <= 8; ++j)
                for (int i = 0; i <= 8; ++i) {
                    const double qx = std::min((column + i / 8.0) * view_block, c.width - 1e-9);
                    const double qy = std::min((row + j / 8.0) * view_block, c.height - 1e-9);
                    same_first_hit(g, table, c, qx, qy);
                    ASSERT_FALSE(::testing::Test::HasFailure());
                }
        }
    EXPECT_GT(covered, 100);
}

// A sphere of `radius` whose outline touches, from the side `toward` points
// to, the plane of camera rays through image points with x = `x` (across) or
// y = `y` (down), at the ray through (x, y), `distance` from the camera.
Primitive touching(const CameraFrame& c, double x, double y, bool across, double toward,
                   double distance, double radius) {
    const Vec3 ray = camera_direction(c, x, y);
    const Vec3 plane_normal = glm::normalize(glm::cross(across ? c.up : c.right, ray));
    // plane_normal points to smaller x across, to larger y down.
    const double side = across ? toward * -1.0 : toward;
    return sphere(c.position + distance * ray + side * radius * plane_normal, radius);
}

TEST(ViewTable, ASphereReachingABlockByAHairIsListedThere) {
    // Spheres placed so that their outline crosses a block's edge by 1e-4
    // pixel: a ray 5e-5 pixel inside the outline, in the block the sphere
    // barely reaches, hits it, so that block must list it.
    const CameraFrame c = view({0, 0, 0}, {0, 0, -1}, 40, 160, 120);
    constexpr double hair = 1e-4;
    std::vector<std::array<double, 2>> probes;
    Scene scene;
    for (int k = 1; k < 40; ++k) {
        const bool across = k % 2 == 0;
        const double edge = view_block * (across ? k : k % 29 + 1);  // inside the image
        const double toward = k % 4 < 2 ? 1.0 : -1.0;  // the side the sphere reaches over to
        const double other = 10.0 + 7.0 * (k % 13);    // the coordinate along the edge
        const double x = across ? edge + toward * hair : other + 0.37;
        const double y = across ? other + 0.37 : edge + toward * hair;
        // toward > 0: the sphere lies before the edge and reaches past it.
        scene.primitives.push_back(touching(c, x, y, across, -toward, 20.0 + k, 0.3));
        probes.push_back(
            {across ? x - toward * 0.5 * hair : x, across ? y : y - toward * 0.5 * hair});
    }
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const ViewTable table = build_view_table(g, c);
    ASSERT_TRUE(table.built);
    for (std::size_t i = 0; i < probes.size(); ++i) {
        std::uint32_t source = ~0u;
        EXPECT_TRUE(same_first_hit(g, table, c, probes[i][0], probes[i][1], &source)) << i;
        EXPECT_EQ(source, i) << "the probe grazes sphere " << i;
    }
}

// A sphere `distance` from the camera whose outline passes the ray through
// image point (x, y) at the angle `gap` (negative: the ray crosses the
// outline by that much), its centre off toward image point (x - dx, y - dy),
// and whose outline spans `angle` about its centre.
Primitive beside_ray(const CameraFrame& c, double x, double y, double dx, double dy, double gap,
                     double angle, double distance) {
    const Vec3 ray = camera_direction(c, x, y);
    const Vec3 away = camera_direction(c, x - dx, y - dy);
    const Vec3 side = glm::normalize(away - glm::dot(away, ray) * ray);
    const double off = angle + gap;
    const Vec3 centre = glm::normalize(std::cos(off) * ray + std::sin(off) * side);
    return sphere(c.position + distance * centre, distance * std::sin(angle));
}

TEST(ViewTable, ASphereIsListedInABlockItsOutlineReachesOnlyAtACorner) {
    // Spheres just off a block's corner, diagonally: the box around each
    // outline reaches over a pixel into the block, but the outline itself
    // either crosses the corner's ray by a hair (the block must list the
    // sphere: a ray just inside the corner hits it) or passes it by 0.3 of a
    // pixel (no ray of the block meets it: the block leaves it out).
    const CameraFrame c = view({0, 0, 0}, {0, 0, -1}, 40, 160, 120);
    const double pixel = 2.0 * c.tan_half_fov / c.height;  // about, in radians
    Scene scene;
    std::vector<std::array<int, 2>> blocks;
    std::vector<std::array<double, 2>> probes;
    for (int k = 0; k < 24; ++k) {
        const int column = 4 + 6 * (k % 6), row = 3 + 6 * (k / 6);
        // The corner the sphere lies off: k % 4 picks which of the four.
        const int cx = k % 2, cy = k / 2 % 2;
        const double x = view_block * (column + cx), y = view_block * (row + cy);
        const double dx = cx ? -1.0 : 1.0, dy = cy ? -1.0 : 1.0;  // away from the block
        const bool reaches = k % 3 != 0;
        scene.primitives.push_back(beside_ray(
            c, x, y, dx, dy, reaches ? -1e-4 * pixel : 0.3 * pixel, 5.0 * pixel, 20.0 + k));
        blocks.push_back({column, row});
        // 1e-5 pixel into the block along both axes from the corner.
        probes.push_back({x - dx * 1e-5, y - dy * 1e-5});
    }
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const ViewTable table = build_view_table(g, c);
    ASSERT_TRUE(table.built);
    for (std::uint32_t k = 0; k < blocks.size(); ++k) {
        const ListedShapes listed = block_shapes(table, blocks[k][0], blocks[k][1]);
        const bool is_listed =
            std::find(listed.shapes.begin(), listed.shapes.end(), k) != listed.shapes.end();
        std::uint32_t source = ~0u;
        const bool hit = same_first_hit(g, table, c, probes[k][0], probes[k][1], &source);
        ASSERT_FALSE(::testing::Test::HasFailure()) << k;
        if (k % 3 != 0) {
            EXPECT_TRUE(is_listed) << "sphere " << k << " crosses the corner's ray";
            EXPECT_TRUE(hit && source == k) << "the probe inside the corner hits sphere " << k;
        } else {
            EXPECT_FALSE(is_listed) << "sphere " << k << " passes the block's corner";
            EXPECT_FALSE(hit) << k;
        }
    }
    EXPECT_GT(check_view(g, c, 8), 1000);
}

TEST(ViewTable, ASphereMissingABlockCornerByAHairDoesNotCoverIt) {
    // Spheres centred on a block's centre, each just too small to hold the
    // block's farthest corner, before a far wall: the corner's ray misses the
    // sphere and meets the wall, so the sphere must not count as covering the
    // block (which would leave the wall out of its list).
    const CameraFrame c = view({0, 0, 0}, {0, 0, -1}, 40, 160, 120);
    Scene scene;
    scene.primitives.push_back(sphere({0, 0, -5000}, 4000.0));  // the wall
    std::vector<std::array<int, 2>> blocks;
    for (int k = 0; k < 12; ++k) {
        const int column = 3 + 3 * k, row = 2 + 2 * k;
        blocks.push_back({column, row});
        const double x0 = view_block * column, y0 = view_block * row;
        const Vec3 axis = camera_direction(c, x0 + 0.5 * view_block, y0 + 0.5 * view_block);
        double widest = 0.0;
        for (double dx : {0.0, 1.0 * view_block})
            for (double dy : {0.0, 1.0 * view_block})
                widest = std::max(widest,
                                  std::acos(glm::dot(axis, camera_direction(c, x0 + dx, y0 + dy))));
        const double distance = 30.0;
        scene.primitives.push_back(
            sphere(c.position + distance * axis, distance * std::sin(widest * (1.0 - 1e-4))));
    }
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const ViewTable table = build_view_table(g, c);
    ASSERT_TRUE(table.built);
    int wall = 0;
    for (const auto& [column, row] : blocks) {
        const ListedShapes listed =
            shapes_seen(table, view_block * (column + 0.5), view_block * (row + 0.5));
        EXPECT_NE(std::find(listed.shapes.begin(), listed.shapes.end(), 0u), listed.shapes.end())
            << "the wall is listed behind the sphere of block " << column << ", " << row;
        for (double dx : {0.0, 1.0 * view_block - 1e-9})
            for (double dy : {0.0, 1.0 * view_block - 1e-9}) {
                std::uint32_t source = ~0u;
                ASSERT_TRUE(same_first_hit(g, table, c, view_block * column + dx,
                                           view_block * row + dy, &source));
                wall += source == 0;
            }
    }
    EXPECT_GT(wall, 0) << "some corner rays pass the sphere and meet the wall";
}

TEST(ViewTable, FromInsideASphereEveryBlockIsCoveredAndNothingBeyondItIsListed) {
    Scene scene;
    scene.primitives.push_back(sphere({0, 0, 0}, 10.0));
    scene.primitives.push_back(sphere({1, 0, -3}, 0.5));
    scene.primitives.push_back(sphere({0, 0, -40}, 3.0));  // outside the big sphere
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    const CameraFrame camera = view({0, 0, 2}, {0, 0, -1}, 60, 64, 48);
    const ViewTable table = build_view_table(g, camera);
    ASSERT_TRUE(table.built);
    for (const ListedShapes& list : block_lists(table)) {
        EXPECT_TRUE(list.covered);
        for (const std::uint32_t shape : list.shapes)
            EXPECT_NE(shape, 2u) << "the far sphere lies beyond the big one's far side";
    }
    EXPECT_GT(check_view(g, camera, 6), 64 * 48);
}

TEST(ViewTable, OverlappingSpheresListAFewEachBlockAndGiveTheBvhsFirstHits) {
    // Hundreds of big spheres overlapping along the view, as in the nested
    // shells benchmark: once a block is covered by a near sphere, spheres
    // beyond its far side are left out, so the lists stay short. Tiny far
    // spheres beside them cover no block.
    Scene scene;
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 400; ++i)
        scene.primitives.push_back(sphere({0.5 * unit(rng), 0.5 * unit(rng), -5.0 - 0.05 * i},
                                          1.0 + 0.5 * (unit(rng) + 1)));
    for (int i = 0; i < 100; ++i)
        scene.primitives.push_back(sphere({12.0 + 0.3 * (i % 10), 0.3 * (i / 10), -40.0}, 0.01));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    ASSERT_TRUE(g.bvh);
    const CameraFrame camera = view({0, 0, 10}, {0, 0, -1}, 40, 80, 60);
    const ViewTable table = build_view_table(g, camera);
    ASSERT_TRUE(table.built);
    const ListedShapes centre = shapes_seen(table, 40, 30);
    EXPECT_TRUE(centre.covered);
    EXPECT_LT(centre.size(), 400u / 4) << "spheres beyond the covering one are left out";
    double x, y;
    ASSERT_TRUE(
        image_point(camera, glm::normalize(Vec3{13.0, 1.0, -40.0} - camera.position), x, y));
    const ListedShapes tiny = shapes_seen(table, x, y);
    EXPECT_GE(tiny.size(), 1u);
    EXPECT_FALSE(tiny.covered);
    EXPECT_GT(check_view(g, camera, 7), 2000);
}

TEST(ViewTable, AWalkThatRunsLongHandsOverToTheBvh) {
    // A big sphere covers the view, but its hits lie beyond the 300 tiny
    // spheres listed before it: a walk stops after a few hundred of them,
    // and the BVH finds the rest.
    Scene scene;
    scene.primitives.push_back(sphere({0, 0, -100}, 90.0));
    const Vec3 eye{0, 0, 10};
    const Vec3 along = glm::normalize(Vec3{0, 0.3, -1});
    std::mt19937 rng(32);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), inside(0.0, 1.0);
    for (int i = 0; i < 300; ++i)
        scene.primitives.push_back(
            sphere(eye + (20.2 + 0.002 * i) * along + 0.01 * Vec3{unit(rng), unit(rng), 0}, 0.02));
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    ASSERT_TRUE(g.bvh);
    const CameraFrame camera = view(eye, eye + along, 0.5, 8, 8);
    const ViewTable table = build_view_table(g, camera);
    ASSERT_TRUE(table.built);
    std::size_t longest = 0;
    for (const ListedShapes& list : block_lists(table)) longest = std::max(longest, list.size());
    EXPECT_GT(longest, 256u);
    int tiny = 0;
    for (int i = 0; i < 5000; ++i) {
        std::uint32_t source = 0;
        ASSERT_TRUE(same_first_hit(g, table, camera, 8 * inside(rng), 8 * inside(rng), &source));
        ASSERT_FALSE(::testing::Test::HasFailure());
        tiny += source != 0;
    }
    EXPECT_GT(tiny, 0);
}

TEST(ViewTable, NoneWithoutBoundedShapesOrWithoutAFrame) {
    Scene planes;
    planes.primitives.push_back(plane({0, 1, 0}, 0.0));
    auto only_planes = prepare_scene(planes).value();
    EXPECT_FALSE(
        build_view_table(*only_planes->geometry, view({0, 2, 5}, {0, 0, 0}, 45, 32, 32)).built);
    auto prepared = crowd(30, 25);
    EXPECT_FALSE(
        build_view_table(*prepared->geometry, view({1, 2, 3}, {1, 2, 3}, 45, 32, 32)).built)
        << "look_at at the camera: no frame, no table";
    EXPECT_TRUE(
        build_view_table(*prepared->geometry, view({0, 2, 15}, {0, 0, 0}, 45, 32, 32)).built);
}

TEST(ViewTable, ACoveringSphereIsMetWithinItsBound) {
    // A block a sphere covers has its corners within the inner sphere's cone;
    // its rays, no wider from the centre's direction than its farthest
    // corner, must meet the sphere (the exact test's root) no farther than
    // the bound its list is cut at. Rays at exactly the farthest corner's
    // angle and inside it; corners from the axis out to the inner sphere's
    // rim; cameras far off, near the surface, inside, and in the thin shell
    // between the inner and the true sphere; scales 1e-3 to 1e3.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    int rays = 0;
    for (int i = 0; i < 40000; ++i) {
        const double scale = std::pow(10.0, 6.0 * fraction(rng) - 3.0);
        const double radius = scale * (0.1 + fraction(rng));
        const double distance = i % 10 == 0 ? radius * (1.0 - 1e-9 * fraction(rng))
                                : i % 10 == 1
                                    ? radius * fraction(rng)
                                    : radius * (1.0 + std::pow(10.0, 4.0 * fraction(rng) - 3.0));
        const Vec3 center =
            distance * glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)) + Vec3(0, 0, 1e-3));
        const PaddedBound padded = padded_bound(center, radius, Vec3(0.0));
        const double inner = std::max(radius * (1.0 - 1e-7) - 1e-9 * padded.distance, 0.0);
        const double length = glm::length(center);
        if (!(length > inner)) continue;
        // The farthest corner's angle, up to the inner sphere's rim; a ray
        // at that angle, or within it.
        const double rim = std::asin(inner / length);
        const double farthest = rim * (i % 4 == 0 ? 1.0 : fraction(rng));
        const double angle = farthest * (i % 3 == 0 ? 1.0 : std::sqrt(fraction(rng)));
        const double bound =
            covered_hit_bound(padded.distance, inner, padded.radius, std::cos(farthest));
        const Vec3 axis = center / length;
        const Vec3 side = glm::normalize(glm::cross(axis, Vec3(unit(rng), unit(rng), unit(rng))));
        const Vec3 d = glm::normalize(std::cos(angle) * axis + std::sin(angle) * side);
        const double t = intersect_sphere(Vec3(0.0), d, center, radius, 0.0, 1e300);
        if (t == no_hit) continue;
        ++rays;
        ASSERT_LE(t, bound) << "ray " << i << ": distance " << distance << ", radius " << radius
                            << ", angle " << angle << " of " << farthest;
    }
    EXPECT_GT(rays, 30000);
}

TEST(ViewTable, ListsAreNearestFirstWithTrueLowerBounds) {
    auto prepared = crowd(200, 26);
    const Geometry& g = *prepared->geometry;
    const CameraFrame camera = view({0, 2, 15}, {0, 0, 0}, 45, 64, 36);
    const ViewTable table = build_view_table(g, camera);
    ASSERT_TRUE(table.built);
    const std::vector<ListedShapes> lists = block_lists(table);
    std::size_t listed = 0;
    for (const ListedShapes& list : lists)
        for (std::size_t k = 0; k < list.size(); ++k) {
            ++listed;
            if (k > 0) {
                EXPECT_LE(list.nearest[k - 1], list.nearest[k]);
            }
            if (list.shapes[k] & shape_flag) continue;
            const WorldSphere& s = g.spheres[list.shapes[k]];
            EXPECT_LT(list.nearest[k], glm::length(s.center - camera.position) - s.radius);
            // Never above the padded bound it stores (a float rounded to
            // nearest would be, for about half the shapes).
            EXPECT_LE(list.nearest[k], padded_bound(s.center, s.radius, camera.position).nearest);
        }
    // Blocks of 4x4 pixels list a few shapes each, not the crowd.
    EXPECT_LT(listed, 16u * lists.size());
}

}  // namespace
}  // namespace jt::test
