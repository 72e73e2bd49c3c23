#pragma once
// Refusing a render that cannot fit in memory before allocating it, so that
// a huge --width/--height gives a clear message rather than a visit from the
// kernel's out-of-memory killer half way through.

#include <cstdint>
#include <string>

namespace jt::cli {

// Bytes a width x height render needs at most: the job's image and running
// sums, the copy handed to the writer and the encoded file.
std::uint64_t render_memory_bytes(int width, int height, int samples);

// The memory this process may still take: the smaller of the system's
// available memory and the address-space limit (ulimit -v); 0 when unknown.
std::uint64_t available_memory_bytes();

// Empty when the render fits, else the message explaining why not.
std::string check_render_memory(int width, int height, int samples);

}  // namespace jt::cli
