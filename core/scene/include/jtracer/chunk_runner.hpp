#pragma once
// A way to run independent pieces of work on several threads, supplied by the
// caller: jtracer_scene has no thread pool of its own (no TBB, so that the
// fuzzers and image tools build without the renderer), and a program that has
// one hands it in (parallel_chunks.hpp, in jtracer_render, runs them on TBB).

#include <cstddef>
#include <functional>

namespace jt {

// Calls work(0), ..., work(count - 1), each once, in any order and on any
// threads, and returns when all have returned (rethrowing an exception one of
// them threw). An empty ChunkRunner means: one after another on this thread.
using ChunkRunner =
    std::function<void(std::size_t count, const std::function<void(std::size_t)>& work)>;

}  // namespace jt
