// The early answers given to a few spheres at once (SSE2, and AVX where the
// processor has it) are the scalar test's, lane for lane, and a list walk that passes over the
// spheres they decide still finds every ray's first hit to the bit: rays grazing spheres at many
// scales, from outside and inside nested shells, through lists shorter and longer than a batch that
// stop anywhere in one.

#include "render/sphere_batch.hpp"

#include "geometry/intersect.hpp"
#include "render/listed_shapes.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace jt::test {
namespace {

// intersect_sphere's early answers, as it gives them one sphere at a time.
template <bool DecideEntryBeyond>
bool scalar_missed_early(const WorldSphere& s, const Vec3& origin, const Vec3& direction,
                         double t_min, double t_max) {
    const Vec3 f = origin - s.center;
    const double b = glm::dot(f, direction);
    const double ff = glm::dot(f, f);
    const double c = ff - s.radius * s.radius;
    const double a = glm::dot(direction, direction);
    return (c > 0.0 && b >= 0.0 && t_min >= 0.0) || passes_wide_of_sphere(a, b, c, ff) ||
           (DecideEntryBeyond && t_min >= 0.0 && enters_beyond(a, b, c, ff, t_max));
}

// A ray from `origin` that passes `s`'s outline by `miss` radii (negative:
// inside it), its direction scaled by `scale`.
Vec3 grazing(const WorldSphere& s, const Vec3& origin, double miss, double scale,
             std::mt19937_64& rng) {
    const Vec3 to = s.center - origin;
    return scale * (to + (s.radius * (1.0 + miss)) * across(to, rng));
}

constexpr double misses[] = {-0.5, -1e-6, -1e-12, 0.0, 1e-12, 1e-6, 0.5};

TEST(SphereBatch, EveryLaneIsTheScalarEarlyAnswer) {
    std::mt19937_64 rng(71);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
    std::uniform_int_distribution<int> pick_miss(0, std::size(misses) - 1);
    long decided = 0, tested = 0, entries = 0;
    for (int round = 0; round < 20000; ++round) {
        const double scale = log_uniform(1e-5, 1e5);
        const Vec3 near{scale * (unit(rng) - 0.5), scale * (unit(rng) - 0.5),
                        scale * (unit(rng) - 0.5)};
        WorldSphere spheres[sphere_batch];
        for (WorldSphere& s : spheres) {
            s.center = near + scale * Vec3{unit(rng), unit(rng), unit(rng)};
            s.radius = scale * log_uniform(1e-3, 2.0);
        }
        // From outside, from inside the first sphere, and from far away.
        const int where = round % 3;
        const Vec3 origin = where == 0 ? near
                            : where == 1
                                ? spheres[0].center + 0.5 * spheres[0].radius * across(near, rng)
                                : near - 1e3 * scale * Vec3{1.0, 0.3, 0.2};
        const WorldSphere& aim = spheres[round % sphere_batch];
        Vec3 direction = grazing(aim, origin, misses[pick_miss(rng)], log_uniform(1e-3, 1e3), rng);
        if (round % 11 == 10) {
            // On the surface of sphere 1, exactly (c = 0), heading across it
            // (b = 0) or anywhere.
            const double power = std::ldexp(1.0, static_cast<int>(round % 40) - 20);
            spheres[1].center = origin + power * Vec3{4.0, 0.0, 0.0};
            spheres[1].radius = std::abs(origin.x - spheres[1].center.x);
            if (round % 2 == 0) direction.x = 0.0;
        }
        const double t_min = round % 5 == 0 ? -1e-3 : round % 5 == 1 ? 1e-9 : 0.0;
        // The hit distance of one sphere, its neighbours in the doubles, and
        // no bound at all.
        const double hit = intersect_sphere(origin, direction, spheres[round % 2].center,
                                            spheres[round % 2].radius, t_min, no_hit);
        const double t_max = round % 7 == 0 || hit == no_hit ? no_hit
                             : round % 2 == 0                ? std::nextafter(hit, no_hit)
                                                             : hit * log_uniform(0.5, 2.0);
        const WorldSphere* const lanes[sphere_batch] = {&spheres[0], &spheres[1], &spheres[2],
                                                        &spheres[3]};
        const BatchRay ray = batch_ray(origin, direction, t_min);
        const unsigned primary = spheres_missed_early<true>(lanes, ray, t_max);
        const unsigned shadow = spheres_missed_early<false>(lanes, ray, t_max);
#if defined(JT_SPHERE_BATCH_AVX)
        if (sphere_batch_avx()) {
            ASSERT_EQ(spheres_missed_early_avx<true>(lanes, ray, t_max), primary) << round;
            ASSERT_EQ(spheres_missed_early_avx<false>(lanes, ray, t_max), shadow) << round;
        }
#endif
        for (std::size_t k = 0; k < sphere_batch; ++k) {
            const WorldSphere& s = spheres[k];
            ++tested;
            ASSERT_EQ((primary >> k & 1u) != 0,
                      scalar_missed_early<true>(s, origin, direction, t_min, t_max))
                << round << " lane " << k;
            ASSERT_EQ((shadow >> k & 1u) != 0,
                      scalar_missed_early<false>(s, origin, direction, t_min, t_max))
                << round << " lane " << k;
            if (!(primary >> k & 1u)) continue;
            ++decided;
            entries += !(shadow >> k & 1u);
            // Decided: no hit before t_max, nor before any nearer bound.
            for (const double t : {t_max, t_max * 0.5, std::nextafter(t_max, 0.0)})
                ASSERT_EQ(intersect_sphere(origin, direction, s.center, s.radius, t_min, t), no_hit)
                    << round << " lane " << k << " t " << t;
        }
    }
    // Each early answer decides a fair share of the lanes, and not all.
    EXPECT_GT(decided, tested / 10);
    EXPECT_GT(entries, tested / 50);
    EXPECT_LT(decided, tested * 9 / 10);
}

// Every sphere and shape of `g`, nearest `point` first, as a table lists them;
// of shapes equally near, the later one first, so that a twin met at the same
// distance as the one before it wins by the tie rule.
std::vector<std::uint32_t> listed_from(const Geometry& g, const Vec3& point,
                                       std::vector<ListedDistance>& nearest) {
    std::vector<std::uint32_t> shapes;
    std::vector<double> exact;
    for (std::uint32_t i = 0; i < g.spheres.size(); ++i) {
        shapes.push_back(i);
        exact.push_back(padded_bound(g.spheres[i].center, g.spheres[i].radius, point).nearest);
    }
    for (std::uint32_t i = 0; i < g.shapes.size(); ++i) {
        shapes.push_back(i | shape_flag);
        exact.push_back(padded_bound(g.shapes[i].bounding_center,
                                     std::sqrt(g.shapes[i].bounding_radius_sq), point)
                            .nearest);
    }
    std::vector<std::size_t> order(shapes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
        return exact[i] < exact[j] || (exact[i] == exact[j] && i > j);
    });
    std::vector<std::uint32_t> sorted;
    nearest.clear();
    for (const std::size_t i : order) {
        sorted.push_back(shapes[i]);
        nearest.push_back(listed_distance(exact[i]));
    }
    return sorted;
}

// Nested shells around a few centres, each shell a little off centre, at
// scales from a thousandth to a thousand; some transformed shapes among them,
// and some shells twice.
Scene shells(std::mt19937_64& rng, int nests, int per_nest) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Scene scene;
    for (int n = 0; n < nests; ++n) {
        const double scale = std::pow(10.0, 3.0 * unit(rng));
        const Vec3 centre = scale * Vec3{3 * unit(rng), 3 * unit(rng), 3 * unit(rng)};
        for (int k = 0; k < per_nest; ++k) {
            const double radius = scale * (0.3 + 0.15 * k);
            const Vec3 off = 0.05 * scale * Vec3{unit(rng), unit(rng), unit(rng)};
            Primitive p = sphere(centre + off, radius);
            if (k % 5 == 4)
                p.transforms = {test::scale({1.0, 1.0 + 0.2 * unit(rng), 1.0}), translate(centre)};
            scene.primitives.push_back(p);
            if (k % 4 == 1) scene.primitives.push_back(p);
        }
    }
    return scene;
}

// Where a walk's rays start, by `from`: outside everything (even), or inside
// nested shells (odd).
Vec3 walk_origin(const Geometry& g, int from, std::mt19937_64& rng) {
    const WorldSphere& home = g.spheres[static_cast<std::size_t>(from) % g.spheres.size()];
    return from % 2 == 0 ? home.center + home.radius * 40.0 * across({1, 2, 3}, rng)
                         : home.center + home.radius * 0.3 * across({3, 2, 1}, rng);
}

TEST(SphereBatch, ListWalksFindEveryRaysFirstHit) {
    std::mt19937_64 rng(72);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> pick_miss(0, std::size(misses) - 1);
    int hits = 0, rays = 0, crowded_short = 0;
    // Nests and shells a nest: lists of 1, 2, 3 shapes (shorter than a
    // batch), 16 to 20 (the shortest walked in batches, ending in a whole or a
    // partial batch) and up to a few hundred. Where the shells overlap heavily
    // (Geometry::crowded), covered lists from 4 shapes go in batches.
    constexpr std::pair<int, int> crowds[] = {{1, 1},  {1, 2},  {1, 3},  {1, 5},  {2, 3},
                                              {3, 3},  {1, 8},  {1, 11}, {1, 13}, {1, 14},
                                              {1, 15}, {1, 16}, {2, 9},  {4, 12}, {8, 40}};
    for (const auto& [nests, per_nest] : crowds) {
        for (int scene_round = 0; scene_round < 3; ++scene_round) {
            auto prepared = prepare_scene(shells(rng, nests, per_nest)).value();
            const Geometry& g = *prepared->geometry;
            if (g.spheres.empty()) continue;
            for (int from = 0; from < 6; ++from) {
                const Vec3 origin = walk_origin(g, from, rng);
                std::vector<ListedDistance> nearest;
                const std::vector<std::uint32_t> shapes = listed_from(g, origin, nearest);
                // Only a covered list is walked in batches; any list may be called
                // covered, which only lets its walk go on longer.
                const ListedShapes listed{shapes, nearest, from % 3 != 0};
                crowded_short +=
                    g.crowded && listed.covered && shapes.size() >= 4 && shapes.size() < 16;
                for (int r = 0; r < 300; ++r) {
                    const WorldSphere& aim = g.spheres[rng() % g.spheres.size()];
                    const Vec3 d = grazing(aim, origin, misses[pick_miss(rng)],
                                           std::pow(10.0, 3.0 * (unit(rng) - 0.5)), rng);
                    const double t_min = r % 4 == 0 ? 1e-9 : 0.0;
                    Hit expected, actual;
                    const bool hit = closest_hit(g, origin, d, t_min, expected);
                    ASSERT_EQ(closest_hit(g, origin, d, t_min, actual, &listed), hit) << r;
                    ++rays;
                    if (!hit) continue;
                    ++hits;
                    ASSERT_EQ(actual.t, expected.t) << r;
                    ASSERT_EQ(actual.source, expected.source) << r;
                    ASSERT_EQ(actual.normal, expected.normal) << r;
                }
            }
        }
    }
    EXPECT_GT(hits, rays / 3);
    EXPECT_LT(hits, rays);
    EXPECT_GT(crowded_short, 10) << "crowded covered lists of 4 to 15 shapes are walked";
}

TEST(SphereBatch, AWalkHintedWithAnySphereFindsEveryRaysFirstHit) {
    // A hint only orders the tests: the hinted sphere met first, met later
    // than the first hit, missed, a twin of the first hit with the higher
    // index (the tie rule must still pick the lower), a stale hint from the
    // previous ray, none, or out of range. A hinted walk leaves the hint on
    // the sphere it met first.
    std::mt19937_64 rng(73);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> pick_miss(0, std::size(misses) - 1);
    int hits = 0, rays = 0, twins = 0, left_on = 0;
    constexpr std::pair<int, int> crowds[] = {{1, 16}, {1, 20}, {2, 9}, {4, 12}, {8, 40}};
    for (const auto& [nests, per_nest] : crowds) {
        for (int scene_round = 0; scene_round < 3; ++scene_round) {
            auto prepared = prepare_scene(shells(rng, nests, per_nest)).value();
            const Geometry& g = *prepared->geometry;
            ASSERT_GE(g.spheres.size() + g.shapes.size(), 16u);
            for (int from = 0; from < 4; ++from) {
                const Vec3 origin = walk_origin(g, from, rng);
                std::vector<ListedDistance> nearest;
                const std::vector<std::uint32_t> shapes = listed_from(g, origin, nearest);
                ListedShapes listed{shapes, nearest, true};
                HitHint stale;
                for (int r = 0; r < 300; ++r) {
                    const WorldSphere& aim = g.spheres[rng() % g.spheres.size()];
                    const Vec3 d = grazing(aim, origin, misses[pick_miss(rng)],
                                           std::pow(10.0, 3.0 * (unit(rng) - 0.5)), rng);
                    Hit expected;
                    const bool hit = closest_hit(g, origin, d, 0.0, expected);
                    ++rays;
                    hits += hit;
                    // The sphere met first, when a plain sphere is.
                    std::uint32_t first = HitHint::none;
                    for (std::uint32_t i = 0; hit && i < g.spheres.size(); ++i)
                        if (g.spheres[i].source == expected.source) first = i;
                    std::vector<std::uint32_t> hints = {
                        HitHint::none, static_cast<std::uint32_t>(rng() % g.spheres.size()),
                        static_cast<std::uint32_t>(g.spheres.size() + 3), stale.sphere};
                    if (first != HitHint::none) {
                        hints.push_back(first);
                        // A twin: the same sphere listed again, later.
                        for (std::uint32_t i = first + 1; i < g.spheres.size(); ++i)
                            if (g.spheres[i].center == g.spheres[first].center &&
                                g.spheres[i].radius == g.spheres[first].radius) {
                                hints.push_back(i);
                                ++twins;
                            }
                    }
                    for (const std::uint32_t h : hints) {
                        HitHint hint{h};
                        listed.hint = &hint;
                        Hit actual;
                        ASSERT_EQ(closest_hit(g, origin, d, 0.0, actual, &listed), hit)
                            << r << " hint " << h;
                        if (first != HitHint::none) {
                            ASSERT_EQ(hint.sphere, first) << r << " hint " << h;
                            ++left_on;
                        }
                        if (!hit) continue;
                        ASSERT_EQ(actual.t, expected.t) << r << " hint " << h;
                        ASSERT_EQ(actual.source, expected.source) << r << " hint " << h;
                        ASSERT_EQ(actual.normal, expected.normal) << r << " hint " << h;
                    }
                    stale.sphere = first;
                }
            }
        }
    }
    EXPECT_GT(hits, rays / 3);
    EXPECT_LT(hits, rays);
    EXPECT_GT(twins, 100);
    EXPECT_GT(left_on, rays);
}

}  // namespace
}  // namespace jt::test
