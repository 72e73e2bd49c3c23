// Writing a finished 1920x1080 render as the CLI does, and as it did before
// the image moved out of the job and the BMP was written in pieces: a copy of
// the image, a whole-file buffer, then the safe write. Each iteration writes
// to the same file, so both pay the same fsync and rename.
//
// The CLI writes once, so its megabyte buffers are memory fresh from the
// kernel. glibc would keep a freed 6 MB buffer and hand it back on the next
// iteration (its mmap threshold adapts); a fixed threshold makes every large
// buffer a fresh mapping, as in the CLI.

#include "jtracer/atomic_file.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/image.hpp"

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cstdlib>
#include <filesystem>

namespace {

constexpr int fixed_mmap_threshold = 256 << 10;

jt::Image8 render_sized_image() {
    jt::Image8 image(1920, 1080);
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
        image.rgb[i] = static_cast<std::uint8_t>((i * 2654435761u) >> 13);
    return image;
}

std::filesystem::path output_file() {
    const char* tmp = std::getenv("TMPDIR");
    return std::filesystem::path(tmp ? tmp : "/tmp") / "jtracer_bench_image_write.bmp";
}

void BM_CopyEncodeThenWrite(benchmark::State& state) {
    mallopt(M_MMAP_THRESHOLD, fixed_mmap_threshold);
    const jt::Image8 image = render_sized_image();
    const std::filesystem::path file = output_file();
    for (auto _ : state) {
        const jt::Image8 copy = image;
        const jt::Expected<void> written = jt::write_file_atomically(file, jt::encode_bmp(copy));
        if (!written) state.SkipWithError(written.error().message.c_str());
    }
    std::filesystem::remove(file);
}

void BM_WriteInPieces(benchmark::State& state) {
    mallopt(M_MMAP_THRESHOLD, fixed_mmap_threshold);
    const jt::Image8 image = render_sized_image();
    const std::filesystem::path file = output_file();
    for (auto _ : state) {
        const jt::Expected<void> written = jt::write_bmp(file, image);
        if (!written) state.SkipWithError(written.error().message.c_str());
    }
    std::filesystem::remove(file);
}

BENCHMARK(BM_CopyEncodeThenWrite)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WriteInPieces)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
