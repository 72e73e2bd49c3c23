// Preparing a 100,000-sphere scene again after one sphere's colour changed:
// prepare_scene with the previous scene (its BVH reused, every material
// gathered again) against prepare_scene_edit (the one material patched).

#include "jtracer/render_job.hpp"

#include <benchmark/benchmark.h>

#include <random>

namespace {

jt::Scene spheres(int count) {
    jt::Scene scene;
    scene.settings.width = 1280;
    scene.settings.height = 720;
    jt::Camera camera;
    camera.position = {60, 80, 160};
    scene.cameras.push_back(camera);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
        // Built whole: assigning a sphere to a default primitive's shape makes
        // GCC 12 warn (-Wmaybe-uninitialized) about the variant's mesh string.
        const jt::Sphere sphere{{100 * unit(rng) - 50, 100 * unit(rng) - 50, 100 * unit(rng) - 50},
                                0.2 + 0.3 * unit(rng)};
        jt::Material material;
        material.pigment = {unit(rng), unit(rng), unit(rng)};
        material.finish.edit().diffuse = jt::Colour(0.8);
        scene.primitives.push_back(jt::Primitive{sphere, material, {}});
    }
    scene.lights.push_back({{100, 200, 150}, jt::Colour(0.9)});
    return scene;
}

void prepare_after_edit(benchmark::State& state, bool patch) {
    const jt::Scene before = spheres(static_cast<int>(state.range(0)));
    const auto previous = jt::prepare_scene(before).value();
    jt::Scene after = before;
    after.primitives[after.primitives.size() / 2].material.pigment = {0.9, 0.1, 0.1};
    for (auto _ : state) {
        auto prepared = patch ? jt::prepare_scene_edit(before, after, previous)
                              : jt::prepare_scene(after, previous);
        benchmark::DoNotOptimize(prepared);
    }
}

void BM_PrepareAgain(benchmark::State& state) {
    prepare_after_edit(state, false);
}
void BM_PrepareEdit(benchmark::State& state) {
    prepare_after_edit(state, true);
}

// The open's case: nothing prepared before.
void BM_PrepareFresh(benchmark::State& state) {
    const jt::Scene scene = spheres(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        auto prepared = jt::prepare_scene(scene);
        benchmark::DoNotOptimize(prepared);
    }
}

BENCHMARK(BM_PrepareFresh)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PrepareAgain)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PrepareEdit)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
