#include "jtracer/parallel_chunks.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace jt {

ChunkRunner parallel_chunks(int threads) {
    return [threads](std::size_t count, const std::function<void(std::size_t)>& work) {
        tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                              [&](const tbb::blocked_range<std::size_t>& range) {
                                  for (std::size_t i = range.begin(); i != range.end(); ++i)
                                      work(i);
                              });
        });
    };
}

}  // namespace jt
