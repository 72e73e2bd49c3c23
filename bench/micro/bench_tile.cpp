// One full 32 x 32 tile of the showcase (800 x 450, recurse_depth 4), on one
// thread, from the middle of the image where the mirror sphere is: the work of
// one task of the renderer, camera rays to reflections and shadows.

#include "jtracer/render_job.hpp"
#include "jtracer/scene_file.hpp"

#include <benchmark/benchmark.h>

namespace {

void BM_ShowcaseTile(benchmark::State& state) {
    const jt::Expected<jt::LoadedScene> loaded =
        jt::load_scene_file(JT_SOURCE_DIR "/scenes/showcase.jts");
    if (!loaded || !loaded->parsed.ok()) {
        state.SkipWithError("cannot load scenes/showcase.jts");
        return;
    }
    auto prepared = jt::prepare_scene(loaded->parsed.scene).value();
    jt::RenderOptions options;
    options.width = 800;
    options.height = 450;
    options.camera = 0;
    options.threads = 1;
    options.previews = false;
    options.region = jt::PixelRect{384, 224, 416, 256};
    for (auto _ : state) benchmark::DoNotOptimize(jt::render_image(prepared, options));
    state.SetItemsProcessed(state.iterations() * 32 * 32);
    state.SetLabel("items = pixels");
}

BENCHMARK(BM_ShowcaseTile)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
