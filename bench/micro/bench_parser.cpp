// Parser throughput in bytes of scene text a second, on two layouts of the
// same random spheres: "normal" (one property a line, indented, as people
// write scenes) and "dense" (all on one line, no spaces, as generators write).
//
// Each layout runs twice: "cold", where every parse gets fresh memory from the
// kernel (as the CLI and the viewer's first load do: on a VM the page faults of
// first touch cost as much as the parsing), and "warm", where the heap keeps
// its pages between parses, which measures the parser's own work.
// "DenseColdNoMap" parses without the source map, as jtracer-cli does.
//
// A text of more than a MiB is read by several threads, a part each
// (language/scene_parts.hpp): the parse figures are wall time, and each
// "OneThread" figure the same parse with ParseOptions::threads = 1.
//
// "ValidateDense" is the checks that follow the parse (validate_scene, as
// check_scene runs it), on the scene parsed without the map, in bytes of its
// text a second so that it compares with the parse.

#include "jtracer/parser.hpp"
#include "jtracer/validate.hpp"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <cstdio>
#include <random>
#include <string>

namespace {

constexpr int sphere_count = 20000;

std::string scene_header() {
    return "render_settings { width: 640; height: 480; }\n"
           "cameras { perspective_camera { position: <0, 0, 10>; } }\n"
           "scene {\n";
}

std::string spheres(bool dense) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-10.0, 10.0), c(0.0, 1.0);
    std::string text = scene_header();
    char buffer[512];
    const char* format =
        dense ? "sphere{center:<%.4f,%.4f,%.4f>;radius:%.4f;material{pigment:<%.3f,%.3f,%.3f>;"
                "ambient:<0.2,0.2,0.2>;diffuse:<0.8,0.8,0.8>;}}"
              : "    sphere {\n        center: <%.4f, %.4f, %.4f>;\n        radius: %.4f;\n"
                "        material {\n            pigment: <%.3f, %.3f, %.3f>;\n"
                "            ambient: <0.2, 0.2, 0.2>;\n            diffuse: <0.8, 0.8, 0.8>;\n"
                "        }\n    }\n";
    for (int i = 0; i < sphere_count; ++i) {
        double x = u(rng), y = u(rng), z = u(rng), r = c(rng);
        double cr = c(rng), cg = c(rng), cb = c(rng);
        std::snprintf(buffer, sizeof buffer, format, x, y, z, r, cr, cg, cb);
        text += buffer;
    }
    text += "\n}\n";
    return text;
}

void parse(benchmark::State& state, const std::string& text, jt::ParseOptions options = {}) {
    for (auto _ : state) {
        jt::ParseResult result = jt::parse_scene(text, options);
        if (!result.ok() || result.scene.primitives.size() != sphere_count)
            state.SkipWithError("the benchmark scene did not parse");
        benchmark::DoNotOptimize(result);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(text.size()));
}

// glibc's defaults: freed memory at the top of the heap goes back to the
// kernel, and large blocks are mapped afresh each time.
constexpr int default_trim_threshold = 128 * 1024, default_mmap_threshold = 128 * 1024;

// Setting them also stops glibc from raising them after the first large free,
// which it otherwise does: then a cold figure depended on which benchmarks ran
// before it (88 MB/s for dense cold alone, 161 MB/s after the normal layout).
void parse_with_cold_heap(benchmark::State& state, const std::string& text,
                          jt::ParseOptions options = {}) {
    mallopt(M_TRIM_THRESHOLD, default_trim_threshold);
    mallopt(M_MMAP_THRESHOLD, default_mmap_threshold);
    parse(state, text, options);
}

void parse_with_warm_heap(benchmark::State& state, const std::string& text) {
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    parse(state, text);
    mallopt(M_TRIM_THRESHOLD, default_trim_threshold);
    mallopt(M_MMAP_THRESHOLD, default_mmap_threshold);
}

const std::string& normal_text() {
    static const std::string text = spheres(false);
    return text;
}

const std::string& dense_text() {
    static const std::string text = spheres(true);
    return text;
}

void BM_ParseNormalCold(benchmark::State& state) {
    parse_with_cold_heap(state, normal_text());
}
void BM_ParseDenseCold(benchmark::State& state) {
    parse_with_cold_heap(state, dense_text());
}
void BM_ParseDenseColdNoMap(benchmark::State& state) {
    parse_with_cold_heap(state, dense_text(), {.source_map = false});
}
void BM_ParseNormalColdOneThread(benchmark::State& state) {
    parse_with_cold_heap(state, normal_text(), {.threads = 1});
}
void BM_ParseDenseColdOneThread(benchmark::State& state) {
    parse_with_cold_heap(state, dense_text(), {.threads = 1});
}
void BM_ParseDenseColdNoMapOneThread(benchmark::State& state) {
    parse_with_cold_heap(state, dense_text(), {.source_map = false, .threads = 1});
}
void BM_ParseNormalWarm(benchmark::State& state) {
    parse_with_warm_heap(state, normal_text());
}
void BM_ParseDenseWarm(benchmark::State& state) {
    parse_with_warm_heap(state, dense_text());
}

void BM_ValidateDense(benchmark::State& state) {
    const std::string& text = dense_text();
    const jt::ParseResult parsed = jt::parse_scene(text, {.source_map = false});
    for (auto _ : state) {
        std::vector<jt::Diagnostic> found = jt::validate_scene(parsed.scene, parsed.source);
        // One warning, for the camera's aspect; no error.
        for (const jt::Diagnostic& d : found)
            if (d.severity == jt::Severity::error) state.SkipWithError("the scene has errors");
        benchmark::DoNotOptimize(found);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(text.size()));
}

BENCHMARK(BM_ParseNormalCold)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseNormalColdOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseDenseCold)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseDenseColdOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseDenseColdNoMap)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseDenseColdNoMapOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseNormalWarm)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseDenseWarm)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ValidateDense)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
