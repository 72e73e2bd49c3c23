// parallel_chunks: the ChunkRunner on TBB that the front end hands to the
// scene checks (chunk_runner.hpp's contract).

#include "jtracer/parallel_chunks.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace jt {
namespace {

TEST(ParallelChunks, RunsEveryChunkOnceBeforeReturning) {
    for (int threads : {0, 1, 2}) {
        std::vector<std::atomic<int>> runs(1000);
        parallel_chunks(threads)(runs.size(), [&](std::size_t i) { ++runs[i]; });
        for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i], 1) << i;
    }
}

TEST(ParallelChunks, PassesOnAnExceptionOfAChunk) {
    EXPECT_THROW(parallel_chunks(2)(64,
                                    [](std::size_t i) {
                                        if (i == 40) throw std::runtime_error("chunk 40");
                                    }),
                 std::runtime_error);
}

}  // namespace
}  // namespace jt
