// The exact double-precision intersection routines, one ray at a time, over a
// fixed set of rays of which about half hit, so the branches stay honest.

#include "geometry/intersect.hpp"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <random>
#include <vector>

namespace {

struct Ray {
    jt::Vec3 origin, direction;
};

// Rays from around (0, 0.5, 6) toward a 4 x 4 window about the origin.
const std::vector<Ray>& rays() {
    static const std::vector<Ray> all = [] {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-2.0, 2.0);
        std::vector<Ray> r(1024);
        for (Ray& ray : r) {
            ray.origin = {0.1 * u(rng), 0.5 + 0.1 * u(rng), 6.0};
            ray.direction = glm::normalize(jt::Vec3(u(rng), u(rng), 0.0) - ray.origin);
        }
        return r;
    }();
    return all;
}

void BM_IntersectSphere(benchmark::State& state) {
    const jt::Vec3 center{0.0, 0.5, 0.0};
    for (auto _ : state)
        for (const Ray& r : rays())
            benchmark::DoNotOptimize(
                jt::intersect_sphere(r.origin, r.direction, center, 1.5, 0.0, jt::no_hit));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays().size()));
}

void BM_IntersectPlane(benchmark::State& state) {
    const jt::Vec3 normal = glm::normalize(jt::Vec3(0.0, 1.0, 0.2));
    for (auto _ : state)
        for (const Ray& r : rays())
            benchmark::DoNotOptimize(
                jt::intersect_plane(r.origin, r.direction, normal, -0.5, 0.0, jt::no_hit));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays().size()));
}

void BM_IntersectCylinder(benchmark::State& state) {
    jt::CylinderPart part = jt::CylinderPart::side;
    for (auto _ : state)
        for (const Ray& r : rays()) {
            // Lay the cylinder across the view: swap y and z of the ray.
            jt::Vec3 o{r.origin.x, r.origin.z, r.origin.y},
                d{r.direction.x, r.direction.z, r.direction.y};
            benchmark::DoNotOptimize(jt::intersect_cylinder(o, d, 1.0, 2.0, 0.0, jt::no_hit, part));
        }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays().size()));
}

BENCHMARK(BM_IntersectSphere);
BENCHMARK(BM_IntersectPlane);
BENCHMARK(BM_IntersectCylinder);

}  // namespace

BENCHMARK_MAIN();
