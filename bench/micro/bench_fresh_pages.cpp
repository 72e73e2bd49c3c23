// Filling memory fresh from the kernel, in 4 KiB pages and in 2 MiB pages
// (MADV_HUGEPAGE): what io/huge_pages.hpp's min_huge_page_array_bytes weighs.
// Each iteration maps a new buffer, fills it once, as the CLI fills an image
// or the parser its arrays, and unmaps it. The max over the repetitions shows
// the fills that waited.
//
// Memory a process has just freed is filled again quickly. A VM with free
// page reporting hands free 2 MiB blocks back to its host after about two
// seconds, and a page taken from such a block is backed by the host again at
// its first touch: the "rest" cases wait three seconds before each fill, as a
// render started a while after the last one does.
//
//   build/release/bench/bench_fresh_pages --benchmark_repetitions=10
//   (then the lines ending in _median and _max)

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace {

#if defined(__linux__)
void BM_FillFresh(benchmark::State& state) {
    const auto bytes = static_cast<std::size_t>(state.range(0)) << 20;
    const bool huge = state.range(1) != 0;
    const bool rest = state.range(2) != 0;
    for (auto _ : state) {
        if (rest) {
            state.PauseTiming();
            std::this_thread::sleep_for(std::chrono::seconds(3));
            state.ResumeTiming();
        }
        void* p =
            ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) {
            state.SkipWithError("mmap failed");
            return;
        }
        ::madvise(p, bytes, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
        std::memset(p, 1, bytes);
        benchmark::DoNotOptimize(p);
        ::munmap(p, bytes);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(bytes));
}

double slowest(const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end());
}

// MB filled, 1 for 2 MiB pages, 1 for a rest before each fill.
BENCHMARK(BM_FillFresh)
    ->ArgsProduct({{6, 64}, {0, 1}, {0}})
    ->Args({6, 0, 1})
    ->Args({6, 1, 1})
    ->ArgNames({"MB", "huge", "rest"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1)
    ->ComputeStatistics("max", slowest);
#endif

}  // namespace

BENCHMARK_MAIN();
