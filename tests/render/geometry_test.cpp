// The geometry layer on its own: transforms, exact intersections, and the BVH
// queries checked against brute force over every primitive.

#include "geometry/intersect.hpp"
#include "jtracer/affine.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "render/trace.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <limits>
#include <random>
#include <string>

namespace jt::test {
namespace {

void expect_near(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Affine, RightHandRotationsAndWrittenOrder) {
    expect_near(apply_point(affine_of(rotate(TransformKind::zrotate, 90)), {1, 0, 0}), {0, 1, 0});
    expect_near(apply_point(affine_of(rotate(TransformKind::xrotate, 90)), {0, 1, 0}), {0, 0, 1});
    expect_near(apply_point(affine_of(rotate(TransformKind::yrotate, 90)), {0, 0, 1}), {1, 0, 0});
    expect_near(apply_point(affine_of(rotate(TransformKind::zrotate, 30)), {1, 0, 0}),
                {std::sqrt(3.0) / 2, 0.5, 0});
    // The manual's example: translate, zrotate, scale means M = S * Rz * T.
    Affine m = compose_transforms(
        {translate({0, -0.5, 0}), rotate(TransformKind::zrotate, 90), scale({2, 1, 1})});
    // (1, 0.5, 0) -> translate (1, 0, 0) -> rotate (0, 1, 0) -> scale (0, 1, 0)
    expect_near(apply_point(m, {1, 0.5, 0}), {0, 1, 0});
    // (0, 1.5, 0) -> (0, 1, 0) -> (-1, 0, 0) -> (-2, 0, 0)
    expect_near(apply_point(m, {0, 1.5, 0}), {-2, 0, 0});
}

// The reason object_transform gives for leaving a list out, or "renders".
std::string verdict(const std::vector<TransformOp>& ops) {
    const auto placed = object_transform(ops);
    const auto* out = std::get_if<LeftOut>(&placed);
    if (!out) return "renders";
    return (out->reason == LeftOut::Reason::zero_scale ? "zero scale at " : "out of range at ") +
           std::to_string(out->op);
}

TEST(Affine, InverseAndDegenerateMaps) {
    const std::vector<TransformOp> ops = {scale({2, 3, 4}), rotate(TransformKind::xrotate, 33),
                                          translate({1, 2, 3})};
    auto placed = object_transform(ops);
    ASSERT_TRUE(std::holds_alternative<ObjectTransform>(placed));
    const ObjectTransform& m = std::get<ObjectTransform>(placed);
    expect_near(apply_point(m.to_object, apply_point(m.to_world, {0.3, -0.7, 2})), {0.3, -0.7, 2});
    EXPECT_EQ(m.to_world.linear, compose_transforms(ops).linear);
    EXPECT_EQ(m.normal_matrix, glm::transpose(m.to_object.linear));
    EXPECT_TRUE(similarity_scale(
        compose_transforms({rotate(TransformKind::yrotate, 17), scale({3, 3, 3})}).linear));
    EXPECT_FALSE(similarity_scale(compose_transforms({scale({3, 3, 2})}).linear));
}

// A zero scale component leaves the primitive out wherever it stands in the
// list: a rotation after it rounds the composed determinant to about 1e-17, not
// 0, so no test on the composed matrix can decide it.
TEST(Affine, ZeroScaleLeavesOutWhateverSurroundsIt) {
    const TransformOp y150 = rotate(TransformKind::yrotate, 150);
    const TransformOp y60 = rotate(TransformKind::yrotate, 60);
    EXPECT_EQ(verdict({y150, scale({0, 1, 1}), y60}), "zero scale at 1");
    EXPECT_NE(glm::determinant(compose_transforms({y150, scale({0, 1, 1}), y60}).linear), 0.0)
        << "the case the rule exists for";
    EXPECT_EQ(verdict({scale({1, 1, 0})}), "zero scale at 0");
    EXPECT_EQ(verdict({translate({1, 2, 3}), scale({1, 0, 1}), translate({0, 1, 0})}),
              "zero scale at 1");
    EXPECT_EQ(verdict({scale({-0.0, 2, 2}), scale({0, 0, 0})}), "zero scale at 0");
    // A zero scale decides before any overflow.
    EXPECT_EQ(verdict({scale(Vec3(1e300)), scale(Vec3(1e300)), scale({1, 1, 0})}),
              "zero scale at 2");
    EXPECT_EQ(verdict({}), "renders");
    EXPECT_EQ(verdict({scale({1e-3, 1e3, 1}), y60}), "renders");
}

// Magnitudes past the doubles: the op where the map or its inverse first
// stops being finite. Tiny scales stay exact however flat they make the map.
TEST(Affine, MapsLeavingTheDoublesAreLeftOut) {
    EXPECT_EQ(verdict({scale(Vec3(1e300)), scale({1e300, 1, 1})}), "out of range at 1");
    EXPECT_EQ(verdict({scale(Vec3(1e-200)), scale(Vec3(1e-200))}), "out of range at 1");
    EXPECT_EQ(verdict({translate({1e308, 0, 0}), translate({1e308, 0, 0})}), "out of range at 1");
    EXPECT_EQ(verdict({translate({std::nan(""), 0, 0})}), "out of range at 0");
    EXPECT_EQ(verdict({scale({1e-310, 1, 1})}), "out of range at 0") << "1/s overflows";
    // det = 1e-300, and placed: a determinant test would place this list too,
    // but not the product of two such lists, whose determinant rounds to 0.
    const std::vector<TransformOp> flat = {scale({1e-100, 1e-100, 1e-100}),
                                           rotate(TransformKind::zrotate, 30)};
    auto placed = object_transform(flat);
    ASSERT_TRUE(std::holds_alternative<ObjectTransform>(placed));
    const ObjectTransform& m = std::get<ObjectTransform>(placed);
    expect_near(1e-100 * apply_point(m.to_object, apply_point(m.to_world, {0.3, -0.7, 2})),
                1e-100 * Vec3(0.3, -0.7, 2), 1e-112);
}

TEST(Affine, UnitLengthOfTinyAndHugeVectors) {
    EXPECT_EQ(unit_length({0, 2, 0}), Vec3(0, 1, 0));
    ASSERT_TRUE(unit_length({3e-200, 0, 4e-200})) << "the squares underflow";
    expect_near(*unit_length({3e-200, 0, 4e-200}), {0.6, 0, 0.8}, 1e-15);
    EXPECT_EQ(unit_length({0, 0, 5e-324}), Vec3(0, 0, 1)) << "the smallest double";
    ASSERT_TRUE(unit_length({-3e200, 4e200, 0})) << "the squares overflow";
    expect_near(*unit_length({-3e200, 4e200, 0}), {-0.6, 0.8, 0}, 1e-15);
    EXPECT_FALSE(unit_length({0, 0, 0}));
    EXPECT_FALSE(unit_length({1, std::nan(""), 0}));
    EXPECT_FALSE(unit_length({std::numeric_limits<double>::infinity(), 0, 0}));
    // In the ordinary range it is exactly v / |v|.
    const Vec3 v(0.3, -1.7, 2.9);
    EXPECT_EQ(unit_length(v), v / glm::length(v));
}

TEST(Intersect, SphereStaysPreciseFromFarAway) {
    // A unit sphere seen from 1e8 away: b^2 - ac cancels to 0 and puts the hit
    // at 1e8, a whole radius off.
    double t = intersect_sphere({0, 0, 1e8}, {0, 0, -1}, {0, 0, 0}, 1.0, 0.0, no_hit);
    EXPECT_NEAR(t, 1e8 - 1.0, 1e-6);
    // Off-centre, the half chord is sqrt(1 - 0.6^2) = 0.8.
    t = intersect_sphere({0.6, 0, 1e8}, {0, 0, -1}, {0, 0, 0}, 1.0, 0.0, no_hit);
    EXPECT_NEAR(t, 1e8 - 0.8, 1e-6);
    // From inside, the far root.
    EXPECT_EQ(intersect_sphere({0, 0, 0}, {0, 0, -1}, {0, 0, 0}, 2.0, 0.0, no_hit), 2.0);
    EXPECT_EQ(intersect_sphere({0, 3, 5}, {0, 0, -1}, {0, 0, 0}, 2.0, 0.0, no_hit), no_hit);
}

// intersect_sphere's answer without its early ones: the first root it
// computes in (t_min, t_max).
double exact_sphere_test(const Vec3& origin, const Vec3& direction, const Vec3& center,
                         double radius, double t_min, double t_max) {
    const Vec3 f = origin - center;
    const double b = glm::dot(f, direction);
    const double c = glm::dot(f, f) - radius * radius;
    const double a = glm::dot(direction, direction);
    const Vec3 perpendicular = f - (b / a) * direction;
    double t0, t1;
    if (!solve_ray_quadratic(a, b, c, glm::dot(perpendicular, perpendicular), radius * radius, t0,
                             t1))
        return no_hit;
    return first_in_range(t0, t1, t_min, t_max);
}

// The early miss may only answer where the exact test finds no root: rays
// grazing spheres within a relative 1e-17 to 1e-3 of the radius, outside and
// inside, at scales from 1e-6 to 1e7 and from near and far.
TEST(Intersect, AWideMissIsOnlyDecidedWhereTheExactTestMisses) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> exponent(-17.0, -3.0);
    int decided = 0, grazing_hits = 0;
    for (int i = 0; i < 400000; ++i) {
        const double scale = std::pow(10.0, 13.0 * (unit(rng) + 1.0) / 2.0 - 6.0);
        const double radius = scale * (0.01 + std::abs(unit(rng)));
        const Vec3 center = scale * Vec3(unit(rng), unit(rng), unit(rng)) * 3.0;
        // The point where the ray passes the centre, off it by r (1 + e).
        const Vec3 axis = glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
        Vec3 side = glm::cross(axis, Vec3(unit(rng), unit(rng), unit(rng)));
        side = glm::normalize(side);
        const double e = (i % 2 ? 1.0 : -1.0) * std::pow(10.0, exponent(rng));
        const Vec3 passing = center + side * (radius * (1.0 + e));
        const double distance = scale * std::pow(10.0, 4.0 * (unit(rng) + 1.0) / 2.0);
        const Vec3 origin = passing - axis * distance;
        const double length = std::pow(10.0, 2.0 * unit(rng));  // directions need not be unit
        const Vec3 direction = axis * length;
        const Vec3 f = origin - center;
        const double a = glm::dot(direction, direction);
        const double b = glm::dot(f, direction);
        const double ff = glm::dot(f, f);
        const double c = ff - radius * radius;
        const bool root =
            exact_sphere_test(origin, direction, center, radius, -no_hit, no_hit) != no_hit;
        if (passes_wide_of_sphere(a, b, c, ff)) {
            ++decided;
            ASSERT_FALSE(root) << "case " << i << ": e = " << e << ", scale " << scale;
        }
        if (root && e > 0.0) ++grazing_hits;
    }
    // Rays off by 1e-3 of the radius and more are decided early; the test's
    // grazing rays reach the exact test's rounding, where it still finds roots.
    EXPECT_GT(decided, 400000 / 2 / 10);
    EXPECT_GT(grazing_hits, 100);
}

// An entry beyond t_max may only be decided where the exact test finds no root
// before t_max: rays from outside, grazing spheres within a relative 1e-17 to
// 1e-3 of the radius or crossing them anywhere, at scales from 1e-6 to 1e7,
// with t_max just before, at and just after the computed entry (or the
// closest approach, for a miss), off it by a relative 1e-17 to 1e-3.
TEST(Intersect, AnEntryBeyondTMaxIsOnlyDecidedWhereTheExactTestMisses) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> exponent(-17.0, -3.0);
    constexpr int rays = 400000;
    int decided = 0, undecided_before_entry = 0;
    for (int i = 0; i < rays; ++i) {
        const double scale = std::pow(10.0, 13.0 * (unit(rng) + 1.0) / 2.0 - 6.0);
        const double radius = scale * (0.01 + std::abs(unit(rng)));
        const Vec3 center = scale * Vec3(unit(rng), unit(rng), unit(rng)) * 3.0;
        const Vec3 axis = glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)));
        const Vec3 side = glm::normalize(glm::cross(axis, Vec3(unit(rng), unit(rng), unit(rng))));
        // Where the ray passes the centre: off it by r (1 + e), grazing from
        // outside or inside, or anywhere across the sphere.
        const double e = std::pow(10.0, exponent(rng));
        const double offset = i % 3 == 0 ? 1.0 + e : i % 3 == 1 ? 1.0 - e : std::abs(unit(rng));
        const Vec3 passing = center + side * (radius * offset);
        // From outside: at least a thousandth of the radius before the sphere.
        const double distance =
            radius * (1.0 + std::pow(10.0, 7.0 * (unit(rng) + 1.0) / 2.0 - 3.0));
        const Vec3 origin = passing - axis * distance;
        const Vec3 direction = axis * std::pow(10.0, 2.0 * unit(rng));  // need not be unit
        const Vec3 f = origin - center;
        const double a = glm::dot(direction, direction);
        const double b = glm::dot(f, direction);
        const double ff = glm::dot(f, f);
        const double c = ff - radius * radius;
        const double entry = exact_sphere_test(origin, direction, center, radius, 0.0, no_hit);
        const double near = entry != no_hit ? entry : -b / a;
        const double off = std::pow(10.0, exponent(rng));
        for (const double t_max : {near * (1.0 - off), std::nextafter(near, 0.0), near,
                                   std::nextafter(near, no_hit), near * (1.0 + off)}) {
            const double exact = exact_sphere_test(origin, direction, center, radius, 0.0, t_max);
            if (enters_beyond(a, b, c, ff, t_max)) {
                ++decided;
                ASSERT_EQ(exact, no_hit) << "case " << i << ": offset " << offset << ", t_max "
                                         << t_max << ", entry " << entry << ", scale " << scale;
            } else if (entry != no_hit && t_max < entry) {
                ++undecided_before_entry;
            }
        }
    }
    // Most t_max well before an entry are decided; those within the margin of
    // it (one ulp before, or a grazing ray's) are not.
    EXPECT_GT(decided, rays / 2);
    EXPECT_GT(undecided_before_entry, rays / 20);
}

// intersect_cylinder's answer without its early one: the same side and cap
// tests, in the same order.
double exact_cylinder_test(const Vec3& origin, const Vec3& direction, double radius, double height,
                           double t_min, double t_max) {
    double best = no_hit;
    const double r2 = radius * radius;
    const double a = direction.x * direction.x + direction.z * direction.z;
    if (a > 0.0) {
        const double b = origin.x * direction.x + origin.z * direction.z;
        const double c = origin.x * origin.x + origin.z * origin.z - r2;
        const double px = origin.x - (b / a) * direction.x;
        const double pz = origin.z - (b / a) * direction.z;
        double t0, t1;
        if (solve_ray_quadratic(a, b, c, px * px + pz * pz, r2, t0, t1))
            for (double t : {t0, t1}) {
                if (!(t > t_min && t < best && t < t_max)) continue;
                const double y = origin.y + t * direction.y;
                if (y >= 0.0 && y <= height) best = t;
            }
    }
    if (direction.y != 0.0)
        for (const double y : {0.0, height}) {
            const double t = (y - origin.y) / direction.y;
            if (!(t > t_min && t < best && t < t_max)) continue;
            const double x = origin.x + t * direction.x;
            const double z = origin.z + t * direction.z;
            if (x * x + z * z <= r2) best = t;
        }
    return best;
}

// The early miss may only answer where the exact test finds no root, side or
// cap: lines passing the axis within a relative 1e-17 to 1e-3 of the radius,
// outside and inside, through the side or across a cap's rim (nearly
// parallel to the caps, or steep), at scales from 1e-6 to 1e7 and from near
// and far.
TEST(Intersect, ACylinderWideMissIsOnlyDecidedWhereTheExactTestMisses) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> exponent(-17.0, -3.0);
    constexpr int rays = 400000;
    int decided = 0, grazing_hits = 0, cap_hits = 0;
    for (int i = 0; i < rays; ++i) {
        const double scale = std::pow(10.0, 13.0 * (unit(rng) + 1.0) / 2.0 - 6.0);
        const double radius = scale * (0.01 + std::abs(unit(rng)));
        const double height = scale * (0.01 + 2.0 * std::abs(unit(rng)));
        // The line's direction in the xz plane and its closest point to the
        // axis there, off it by r (1 + e).
        const double angle = 3.14159 * unit(rng);
        const Vec3 across(std::cos(angle), 0.0, std::sin(angle));
        const Vec3 side(-across.z, 0.0, across.x);
        const double e = (i % 2 ? 1.0 : -1.0) * std::pow(10.0, exponent(rng));
        // Every third line nearly parallel to the caps, every third steep,
        // the rest anywhere; where it passes the axis, at a cap's height or
        // anywhere along it.
        const double slope = i % 3 == 0   ? 1e-6 * unit(rng)
                             : i % 3 == 1 ? std::pow(10.0, 4.0 * std::abs(unit(rng))) * unit(rng)
                                          : 2.0 * unit(rng);
        const double y = i % 4 == 0 ? 0.0 : i % 4 == 1 ? height : height * (1.5 * unit(rng) + 0.5);
        const Vec3 passing = side * (radius * (1.0 + e)) + Vec3(0.0, y, 0.0);
        const Vec3 axis = glm::normalize(across + Vec3(0.0, slope, 0.0));
        const double distance = scale * std::pow(10.0, 4.0 * (unit(rng) + 1.0) / 2.0);
        const Vec3 origin = passing - axis * distance;
        const Vec3 direction = axis * std::pow(10.0, 2.0 * unit(rng));  // need not be unit
        const double a = direction.x * direction.x + direction.z * direction.z;
        const double b = origin.x * direction.x + origin.z * direction.z;
        const double ff = origin.x * origin.x + origin.z * origin.z;
        const double c = ff - radius * radius;
        const double exact =
            exact_cylinder_test(origin, direction, radius, height, -no_hit, no_hit);
        if (passes_wide_of_cylinder(a, b, c, ff)) {
            ++decided;
            ASSERT_EQ(exact, no_hit) << "case " << i << ": e = " << e << ", scale " << scale;
        }
        // The whole test, early answer included, agrees with the exact one.
        CylinderPart part = CylinderPart::side;
        ASSERT_EQ(intersect_cylinder(origin, direction, radius, height, -no_hit, no_hit, part),
                  exact)
            << "case " << i;
        if (exact != no_hit && e > 0.0) {
            ++grazing_hits;
            if (part != CylinderPart::side) ++cap_hits;
        }
    }
    // Lines off by 1e-3 of the radius and more are decided early; the test's
    // grazing lines reach the exact test's rounding, where it still finds
    // roots, on the side and on the caps.
    EXPECT_GT(decided, rays / 2 / 10);
    EXPECT_GT(grazing_hits, 100);
    EXPECT_GT(cap_hits, 10);
}

TEST(Intersect, CylinderPartsAndRims) {
    CylinderPart part = CylinderPart::side;
    EXPECT_EQ(intersect_cylinder({0, 5, 0}, {0, -1, 0}, 1.0, 2.0, 0.0, no_hit, part), 3.0);
    EXPECT_EQ(part, CylinderPart::top);
    EXPECT_EQ(intersect_cylinder({0, -5, 0}, {0, 1, 0}, 1.0, 2.0, 0.0, no_hit, part), 5.0);
    EXPECT_EQ(part, CylinderPart::bottom);
    EXPECT_EQ(intersect_cylinder({0, 1, 5}, {0, 0, -1}, 1.0, 2.0, 0.0, no_hit, part), 4.0);
    EXPECT_EQ(part, CylinderPart::side);
    // Parallel to the axis outside the radius, and above the top: misses.
    EXPECT_EQ(intersect_cylinder({2, 5, 0}, {0, -1, 0}, 1.0, 2.0, 0.0, no_hit, part), no_hit);
    EXPECT_EQ(intersect_cylinder({0, 2.5, 5}, {0, 0, -1}, 1.0, 2.0, 0.0, no_hit, part), no_hit);
    // From inside the solid, the exit through the side.
    EXPECT_EQ(intersect_cylinder({0, 1, 0}, {1, 0, 0}, 1.0, 2.0, 0.0, no_hit, part), 1.0);
    expect_near(cylinder_normal({0.6, 1.2, 0.8}, CylinderPart::side), {0.6, 0, 0.8});
}

// Embree only culls: the BVH answer must equal a brute-force loop over every
// primitive with the same exact routines, for `rays` random rays through a
// crowd of `count` spheres, ellipsoids and cylinders.
// `extra` primitives join the crowd.
void expect_bvh_agrees_with_brute_force(int count, double extent, int rays, int min_hits,
                                        const std::vector<Primitive>& extra = {}) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    Scene scene = random_crowd(rng, count, extent, 1.5);
    scene.primitives.push_back(plane({0.2, 1, 0.1}, -12.0));
    scene.primitives.insert(scene.primitives.end(), extra.begin(), extra.end());
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    ASSERT_GT(g.shapes.size(), static_cast<std::size_t>(count / 2));

    auto brute = [&](const Vec3& o, const Vec3& d, Hit& best) {
        best.t = no_hit;
        auto consider = [&](double t, std::uint32_t source) {
            if (t < best.t || (t == best.t && t != no_hit && source < best.source)) {
                best.t = t;
                best.source = source;
            }
        };
        for (const WorldSphere& s : g.spheres)
            consider(intersect_sphere(o, d, s.center, s.radius, 0.0, no_hit), s.source);
        for (const TransformedShape& s : g.shapes) {
            Vec3 oo = apply_point(s.to_object, o), dd = apply_vector(s.to_object, d);
            CylinderPart part;
            consider(s.kind == TransformedShape::Kind::sphere
                         ? intersect_sphere(oo, dd, s.center, s.radius, 0.0, no_hit)
                         : intersect_cylinder(oo, dd, s.radius, s.height, 0.0, no_hit, part),
                     s.source);
        }
        for (const WorldPlane& p : g.planes)
            consider(intersect_plane(o, d, p.normal, p.distance, 0.0, no_hit), p.source);
        return best.t != no_hit;
    };

    int hits = 0;
    for (int i = 0; i < rays; ++i) {
        Vec3 o{u(rng) * 2, u(rng) * 2, u(rng) * 2};
        Vec3 d = glm::normalize(Vec3{u(rng), u(rng), u(rng)});
        Hit expected_hit, actual;
        bool expected = brute(o, d, expected_hit);
        ASSERT_EQ(closest_hit(g, o, d, 0.0, actual), expected) << "ray " << i;
        if (!expected) continue;
        ++hits;
        ASSERT_EQ(actual.t, expected_hit.t) << "ray " << i;
        ASSERT_EQ(actual.source, expected_hit.source) << "ray " << i;
        // Occlusion just short of and just past the hit.
        EXPECT_FALSE(occluded(g, o, d, 0.0, expected_hit.t * (1 - 1e-9))) << "ray " << i;
        EXPECT_TRUE(occluded(g, o, d, 0.0, expected_hit.t * (1 + 1e-9))) << "ray " << i;
    }
    EXPECT_GT(hits, min_hits);
}

TEST(RayQueries, BvhAgreesWithBruteForce) {
    expect_bvh_agrees_with_brute_force(600, 10.0, 4000, 1000);
}

// Past 50,000 shapes prepare_scene takes Embree's Morton build (a faster
// build, a looser tree): the answers stay exact.
TEST(RayQueries, MortonBuiltBvhAgreesWithBruteForce) {
    expect_bvh_agrees_with_brute_force(60000, 60.0, 300, 100);
}

// A large scene's spheres are put in Morton order of their centres (Embree's
// Morton builder then reads their boxes in order): each one is kept once, as
// the scene says, and neighbours in the array are neighbours in space.
TEST(RayQueries, ManySpheresAreKeptOnceEachInCurveOrder) {
    constexpr int count = 60000;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-50.0, 50.0);
    Scene scene;
    for (int i = 0; i < count; ++i)
        scene.primitives.push_back(sphere({u(rng), u(rng), u(rng)}, 0.2));
    auto prepared = prepare_scene(scene).value();
    const std::vector<WorldSphere>& spheres = prepared->geometry->spheres;
    ASSERT_EQ(spheres.size(), static_cast<std::size_t>(count));
    std::vector<bool> seen(count, false);
    for (const WorldSphere& s : spheres) {
        ASSERT_LT(s.source, static_cast<std::uint32_t>(count));
        ASSERT_FALSE(seen[s.source]) << s.source;
        seen[s.source] = true;
        const Sphere& written = shape_as<Sphere>(scene.primitives[s.source].shape);
        ASSERT_EQ(s.center, written.center);
        ASSERT_EQ(s.radius, written.radius);
    }
    const auto mean_step = [&](auto centre_of) {
        double sum = 0.0;
        for (int i = 1; i < count; ++i) sum += glm::distance(centre_of(i - 1), centre_of(i));
        return sum / (count - 1);
    };
    const double in_array =
        mean_step([&](int i) { return spheres[static_cast<std::size_t>(i)].center; });
    const double in_scene = mean_step([&](int i) {
        return shape_as<Sphere>(scene.primitives[static_cast<std::size_t>(i)].shape).center;
    });
    EXPECT_LT(in_array, in_scene / 10) << in_array << " against " << in_scene;
}

// Embree's BVH leaves out a box that reaches past 1.8e18: the shapes that
// reach there are tested on every ray instead, and the answers stay exact.
// Each slab below is 2 thick and 2e19 wide, through the crowd's middle.
TEST(RayQueries, ShapesPastEmbreesReachAgreeWithBruteForce) {
    Primitive slab = sphere({0, 0, 0}, 1.0);
    slab.transforms = {scale({1e9, 1e9, 1e9}), scale({1e9, 1e9, 1e9}), scale({10, 1e-18, 10})};
    Primitive wall = cylinder(1.0, 2.0);
    wall.transforms = {translate({0, -1, 0}), scale({1e9, 1e9, 1e9}), scale({1e9, 1e9, 1e9}),
                       scale({10, 1e-18, 10}), rotate(TransformKind::zrotate, 90)};
    expect_bvh_agrees_with_brute_force(600, 10.0, 4000, 1000, {slab, wall});
}

// A sphere stretched by a map whose object space puts it ~1e7 of its radius
// from that space's origin (differential seed 121667 of language 1.1: a
// translate by nearly minus its centre, then scales of ~1e7): a ray leaving
// its surface from the point lifted by surface_offset (docs/language.md §8.5)
// must not meet it again. Taken to that space whole, the ray's origin rounds
// at the size of the centre there, about one lift.
TEST(RayQueries, ARayLeavingAStretchedSphereFarFromItsOriginMissesIt) {
    Primitive stretched = sphere({0.06476805540587785, 0.084473805468467181, -0.058113274558300836},
                                 7.4043913325365748e-09);
    stretched.transforms = {
        translate({-0.06476805846916156, -0.084473802875869974, 0.058113274007193294}),
        scale({407.02525222708795, -665.11645279335278, 436.85098383355569}),
        scale({167.08437766954484, 167.08437766954484, 167.08437766954484}),
        scale({127.22874896432829, 101.06857192702297, 135.99943968591234})};
    Scene scene;
    scene.primitives.push_back(stretched);
    auto prepared = prepare_scene(scene).value();
    const Geometry& g = *prepared->geometry;
    std::mt19937 rng(5);
    std::normal_distribution<double> normal;
    auto random_unit = [&] { return glm::normalize(Vec3(normal(rng), normal(rng), normal(rng))); };
    const Vec3 middle(-0.026, 0.029, -0.005);
    int hits = 0, met_again = 0;
    for (int i = 0; i < 2000; ++i) {
        // From inside, as a refracted ray leaves it (the lift then crosses).
        const Vec3 o = middle + 0.01 * random_unit();
        const Vec3 d = random_unit();
        Hit hit;
        if (!closest_hit(g, o, d, 0.0, hit)) continue;
        ++hits;
        const Vec3 p = o + hit.t * d;
        const Vec3 n = glm::normalize(hit.normal);  // outward
        const Vec3 lifted = p + surface_offset(o, p, hit.t) * n;
        // Away from the surface, outside: the sphere is convex.
        Vec3 away = random_unit();
        if (glm::dot(away, n) < 0.0) away = -away;
        Hit again;
        if (closest_hit(g, lifted, away, 0.0, again)) ++met_again;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(met_again, 0) << "of " << hits;
}

}  // namespace
}  // namespace jt::test
