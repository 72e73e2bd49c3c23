#pragma once
// Refusing a render that cannot fit in memory before allocating it, so that
// a huge --width/--height gives a clear message rather than a visit from the
// kernel's out-of-memory killer half way through.

#include "jtracer/error.hpp"
#include "jtracer/frontend/argument_names.hpp"
#include "jtracer/render_job.hpp"

#include <cstdint>
#include <string>

namespace jt::frontend {

// Bytes a render needs at most: the job's pixels and running sums (the region
// only, when there is one), then the image handed to the writer and the
// encoded file (the region alone with `region_output`, else the whole frame).
std::uint64_t render_memory_bytes(const RenderOptions& options, bool region_output);

// The memory this process may still take: the smaller of the system's
// available memory and the address-space limit (ulimit -v); 0 when unknown.
std::uint64_t available_memory_bytes();

// Whether the render fits; the error explains why not, naming the settings
// as `names` does (--width/--height, --samples).
Expected<void> check_render_memory(const RenderOptions& options, bool region_output,
                                   const ArgumentNames& names = {});

}  // namespace jt::frontend
