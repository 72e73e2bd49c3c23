#pragma once
// A ChunkRunner (chunk_runner.hpp) on TBB's threads, for the checks of the
// scene library, which has no thread pool of its own.

#include "jtracer/chunk_runner.hpp"

namespace jt {

// Runs the chunks on `threads` threads (0: every core), the calling thread
// among them.
ChunkRunner parallel_chunks(int threads = 0);

}  // namespace jt
